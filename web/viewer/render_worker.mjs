// The viewer's renderer, off the page's thread: three.js draws on the canvas the page hands over
// (OffscreenCanvas), so that neither WebGL's start nor a slow draw (a software GPU) holds the page.
// While the view or the mesh changes it draws without antialiasing, at the page's pixel ratio; once
// nothing has changed for settleMs and the viewer is not refining, it draws once more supersampled (twice
// the pixel ratio where that is below 1.5; the browser scales the picture down), which smooths the edges
// as multisampling would without costing every frame (under SwiftShader multisampling slowed WebGL's start
// and every frame: the renderer's longest gap 621 ms against 263, bench/README.md). Messages in:
//   {type: 'start', canvas: OffscreenCanvas, width, height, pixelRatio}
//   {type: 'size', width, height}                                     CSS pixels (after start)
//   {type: 'view', position, quaternion, fov, aspect, near, far}      the page's camera
//   {type: 'mesh', id, positions, normals, colours, indices}          float32 arrays, Uint32Array indices
//   {type: 'refining', value}                                         whether the viewer is refining (gaps
//                                                                     count, no settled frame)
//   {type: 'silhouettes', positions, indices}  -> {type: 'silhouettes', ...counts} (viewer.mjs says what)
// Messages out (at: milliseconds since the epoch, so that the page can place them on its own clock):
//   {type: 'ready', at}                                               WebGL started
//   {type: 'drawn', at, meshId, drawMs}                               a frame with mesh meshId drawn
//   {type: 'gap', longestFrameGap}                                    this thread's longest gap while refining
import * as THREE from 'three';

const settleMs = 200;
let renderer = null, object = null, dirty = false, refining = false, meshId = -1;
let pixelRatio = 1, supersampled = false, settling = null;
const scene = new THREE.Scene();
scene.background = new THREE.Color(1, 1, 1);
const camera = new THREE.PerspectiveCamera(35, 1, 1, 10);
scene.add(camera);
scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 1.6));
const light = new THREE.DirectionalLight(0xffffff, 1.6);
light.position.set(1, 1, 2);
camera.add(light);
const material = new THREE.MeshStandardMaterial({ vertexColors: true, side: THREE.DoubleSide, roughness: 0.6, metalness: 0.1 });
const epoch = () => performance.timeOrigin + performance.now();

function geometryOf({ positions, normals, colours, indices }) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  if (normals) geometry.setAttribute('normal', new THREE.BufferAttribute(normals, 3));
  if (colours) geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  geometry.setIndex(new THREE.BufferAttribute(indices, 1));
  return geometry;
}

// The pixels of the drawn mesh and of another mesh of the part (both drawn flat in the current view, no
// antialiasing) and how many of each lie more than one pixel (in x or y) from the other's.
function silhouettes({ positions, indices }) {
  const size = renderer.getSize(new THREE.Vector2());
  const width = Math.floor(size.x * pixelRatio), height = Math.floor(size.y * pixelRatio);  // the page's pixels
  const target = new THREE.WebGLRenderTarget(width, height);
  const flat = new THREE.MeshBasicMaterial({ color: 0x000000, side: THREE.DoubleSide });
  const mask = (mesh) => {
    const alone = new THREE.Scene();
    alone.background = new THREE.Color(1, 1, 1);
    alone.add(mesh);
    renderer.setRenderTarget(target);
    renderer.render(alone, camera);
    renderer.setRenderTarget(null);
    const rgba = new Uint8Array(4 * width * height);
    renderer.readRenderTargetPixels(target, 0, 0, width, height, rgba);
    const covered = new Uint8Array(width * height);
    for (let i = 0; i < covered.length; ++i) covered[i] = rgba[4 * i] < 128 ? 1 : 0;
    return covered;
  };
  const other = geometryOf({ positions, indices });
  const mine = mask(new THREE.Mesh(object.geometry, flat)), theirs = mask(new THREE.Mesh(other, flat));
  other.dispose();
  flat.dispose();
  target.dispose();
  const beyondOnePixel = (a, b) => {
    let count = 0;
    for (let y = 0; y < height; ++y)
      for (let x = 0; x < width; ++x) {
        if (!a[y * width + x] || b[y * width + x]) continue;
        let near = false;
        for (let dy = -1; dy <= 1 && !near; ++dy)
          for (let dx = -1; dx <= 1 && !near; ++dx) {
            const u = x + dx, v = y + dy;
            near = u >= 0 && v >= 0 && u < width && v < height && b[v * width + u] === 1;
          }
        if (!near) ++count;
      }
    return count;
  };
  const count = (a) => a.reduce((sum, c) => sum + c, 0);
  dirty = true;
  return { type: 'silhouettes', width, height, viewerPixels: count(mine), otherPixels: count(theirs),
           viewerBeyond: beyondOnePixel(mine, theirs), otherBeyond: beyondOnePixel(theirs, mine) };
}

// Once nothing has changed for settleMs, and the viewer is not refining, the view drawn supersampled.
function settleLater() {
  clearTimeout(settling);
  settling = setTimeout(() => {
    if (refining || !renderer || !object || supersampled || pixelRatio >= 1.5) return;
    supersampled = true;
    renderer.setPixelRatio(2 * pixelRatio);
    dirty = true;
  }, settleMs);
}

// Something to draw again: at the page's pixel ratio now.
function changed() {
  dirty = object !== null;
  if (supersampled && renderer) {
    supersampled = false;
    renderer.setPixelRatio(pixelRatio);
  }
  settleLater();
}

const handlers = {
  start({ canvas, width, height, pixelRatio: ratio }) {
    pixelRatio = ratio;
    renderer = new THREE.WebGLRenderer({ canvas, antialias: false });
    renderer.setPixelRatio(pixelRatio);
    renderer.setSize(width, height, false);
    renderer.compile(scene, camera);
    self.postMessage({ type: 'ready', at: epoch() });
  },
  size({ width, height }) {
    if (renderer) renderer.setSize(width, height, false);
    changed();
  },
  view({ position, quaternion, fov, aspect, near, far }) {
    camera.position.fromArray(position);
    camera.quaternion.fromArray(quaternion);
    Object.assign(camera, { fov, aspect, near, far });
    camera.updateProjectionMatrix();
    changed();
  },
  mesh(m) {
    if (object) {
      scene.remove(object);
      object.geometry.dispose();
    }
    object = new THREE.Mesh(geometryOf(m), material);
    scene.add(object);
    meshId = m.id;
    changed();
  },
  refining({ value }) {
    refining = value;
    settleLater();
  },
  silhouettes(request) {
    self.postMessage(silhouettes(request));
  },
};
self.onmessage = ({ data }) => handlers[data.type](data);

let last = performance.now(), longestFrameGap = 0;
const frame = (now) => {
  if (refining && now - last > longestFrameGap) {
    longestFrameGap = now - last;
    self.postMessage({ type: 'gap', longestFrameGap });
  }
  last = now;
  if (dirty && renderer) {
    dirty = false;
    const drawing = performance.now();
    renderer.render(scene, camera);
    self.postMessage({ type: 'drawn', at: epoch(), meshId, drawMs: performance.now() - drawing });
  }
  self.requestAnimationFrame(frame);
};
self.requestAnimationFrame(frame);
