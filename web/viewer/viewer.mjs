// The cadnurbs part viewer: three.js draws the meshes the worker (mesh_worker.mjs) makes with the
// WebAssembly module, coarse at once, then finer until every point is within one pixel of the exact part
// in the current view (the deviation is the world size of a pixel at the part's nearest point); orbit,
// fit to view, the faces' colours, and on screen the triangle count and the deviation the mesh is
// certified within. window.cadnurbsViewer says what the viewer did, for tests and for the curious.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';

const coarseFraction = 1e-2;     // of the diagonal: the first mesh, at once
const finestFraction = 1e-5;     // of the diagonal: no finer, however close the camera comes
const refineRatio = 1.5;         // a new mesh only when the wanted deviation is this much finer

function base64Bytes(text) {
  const binary = atob(text.trim());
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

function formatLength(value) {
  return value >= 1 ? value.toPrecision(3) : value.toExponential(2);
}

// Starts the viewer in `container`. The part and the module are either bytes (partBytes, wasmBytes: a page
// that carries them) or URLs the worker fetches (partUrl, wasmUrl: a site's pages, which share one module
// the browser compiles while it downloads). `workerUrl`: the worker's script; `hud`: an element for the
// status line.
export async function startViewer({ container, hud, partBytes, wasmBytes, partUrl, wasmUrl, workerUrl, name }) {
  const state = {
    name, started: performance.now(), error: '', frames: 0, longestFrameGap: 0, meshes: [],
    openedMs: null, firstFrameMs: null, longestDrawMs: 0, subPixelMs: null, deviation: null, triangles: 0, refining: false,
  };
  window.cadnurbsViewer = state;
  // The worker first, and WebGL only once its script runs: starting a worker needs this thread, which
  // WebGL's start holds for a while; then the worker compiles the module and reads the part meanwhile.
  const worker = new Worker(workerUrl);
  const running = new Promise((resolve) => { worker.onmessage = ({ data }) => data.type === 'started' && resolve(); });
  if (partUrl) {
    worker.postMessage({ type: 'open', partUrl, wasmUrl, name, firstMesh: coarseFraction });
  } else {
    const wasm = wasmBytes.buffer.slice(wasmBytes.byteOffset, wasmBytes.byteOffset + wasmBytes.byteLength);
    const bytes = partBytes.buffer.slice(partBytes.byteOffset, partBytes.byteOffset + partBytes.byteLength);
    worker.postMessage({ type: 'open', wasm, bytes, name, firstMesh: coarseFraction }, [wasm, bytes]);
  }
  await running;
  state.workerMs = performance.now() - state.started;
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(1, 1, 1);
  const camera = new THREE.PerspectiveCamera(35, 1, 1, 10);
  scene.add(camera);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x666666, 1.6));
  const light = new THREE.DirectionalLight(0xffffff, 1.6);
  light.position.set(1, 1, 2);
  camera.add(light);
  const controls = new OrbitControls(camera, container);
  const material = new THREE.MeshStandardMaterial({ vertexColors: true, side: THREE.DoubleSide, roughness: 0.6, metalness: 0.1 });
  // The first, coarse mesh is sketched on a 2D canvas as soon as it comes (flat shades, far triangles
  // first); WebGL, whose start holds this thread for a while, starts only then, and takes over.
  const sketch = document.createElement('canvas');
  sketch.style.cssText = 'position: absolute; left: 0; top: 0; width: 100%; height: 100%;';
  container.appendChild(sketch);
  let renderer = null;
  let object = null, diagonal = 0, sphere = null, pending = false, id = 0;
  // Drawn when something changed (a mesh, the camera, the size); the frame loop runs regardless, so that
  // its gaps show whether the page is free. Nothing to draw before the first mesh.
  let dirty = false;

  const resize = () => {
    const width = container.clientWidth || window.innerWidth, height = container.clientHeight || window.innerHeight;
    if (renderer) renderer.setSize(width, height);
    sketch.width = Math.round(width * window.devicePixelRatio);
    sketch.height = Math.round(height * window.devicePixelRatio);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    dirty = object !== null;
  };
  window.addEventListener('resize', resize);
  resize();

  const show = (text) => { if (hud) hud.textContent = text; };
  const fail = (message) => { state.error = message; show(`${name}: ${message}`); };

  // The deviation one pixel of the view allows at the part's nearest point.
  const pixelDeviation = () => {
    const distance = camera.position.distanceTo(sphere.center) - sphere.radius;
    const nearest = Math.max(distance, camera.near);
    const pixels = sketch.height;  // the drawing buffer's height, the sketch's and WebGL's alike
    const pixel = (2 * nearest * Math.tan(THREE.MathUtils.degToRad(camera.fov) / 2)) / pixels;
    return Math.max(pixel, finestFraction * diagonal);
  };

  const fit = () => {
    const distance = sphere.radius / Math.sin(THREE.MathUtils.degToRad(camera.fov) / 2);
    const direction = new THREE.Vector3(1, -1.4, 0.9).normalize();
    camera.position.copy(sphere.center).addScaledVector(direction, distance);
    camera.up.set(0, 0, 1);
    camera.near = distance / 100;
    camera.far = distance * 10;
    camera.updateProjectionMatrix();
    controls.target.copy(sphere.center);
    controls.update();
  };

  const ask = (deviation) => {
    pending = true;
    state.refining = true;
    worker.postMessage({ type: 'mesh', id: ++id, deviation });
  };
  const refine = () => {
    if (pending || !sphere) return;
    const wanted = pixelDeviation();
    if (wanted * refineRatio < state.deviation) {
      ask(wanted);
    } else if (state.refining) {
      state.refining = false;
      if (state.subPixelMs === null) state.subPixelMs = performance.now() - state.started;
    }
    status();
  };
  // The meshing's figures are of the part the file holds; a .cnb also states how far that lies from the
  // exact part it was written from, and the two add up.
  const status = () => show(`${name} · ${state.triangles.toLocaleString()} triangles · meshed within ${formatLength(state.deviation)}` +
                            ` of the file (certified ${formatLength(state.certified)})` +
                            (state.fileDeviationBound > 0 ? ` · the file within ${formatLength(state.fileDeviationBound)} of the exact part` : '') +
                            ` · ${state.refining ? 'refining…' : 'meshed below one pixel'}`);

  const place = (m) => {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(m.positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(m.normals, 3));
    geometry.setAttribute('color', new THREE.BufferAttribute(m.colours, 3));
    geometry.setIndex(new THREE.BufferAttribute(m.indices, 1));
    geometry.computeBoundingSphere();
    if (object) {
      scene.remove(object);
      object.geometry.dispose();
    }
    object = new THREE.Mesh(geometry, material);
    scene.add(object);
    dirty = true;
    if (!sphere) {
      sphere = geometry.boundingSphere.clone();
      fit();
    }
  };

  // The coarse mesh on the 2D canvas: each triangle in its first vertex's colour, lit as the thumbnail
  // pictures are (a light over the viewer's shoulder, both sides lit), drawn far to near.
  const drawSketch = (m) => {
    const context = sketch.getContext('2d', { willReadFrequently: true });  // drawn by the CPU: no GPU start before the first frame
    const width = sketch.width, height = sketch.height;
    context.fillStyle = '#fff';
    context.fillRect(0, 0, width, height);
    camera.updateMatrixWorld();
    const vertices = m.positions.length / 3, screen = new Float32Array(3 * vertices), v = new THREE.Vector3();
    for (let i = 0; i < vertices; ++i) {
      v.fromArray(m.positions, 3 * i).project(camera);
      screen.set([(v.x + 1) / 2 * width, (1 - v.y) / 2 * height, v.z], 3 * i);
    }
    const triangles = m.indices.length / 3, depth = new Float32Array(triangles);
    for (let t = 0; t < triangles; ++t)
      depth[t] = screen[3 * m.indices[3 * t] + 2] + screen[3 * m.indices[3 * t + 1] + 2] + screen[3 * m.indices[3 * t + 2] + 2];
    const order = Array.from({ length: triangles }, (_, t) => t).sort((a, b) => depth[b] - depth[a]);
    const toLight = new THREE.Vector3(1, 1, 2).normalize().transformDirection(camera.matrixWorld);
    const a = new THREE.Vector3(), b = new THREE.Vector3(), c = new THREE.Vector3();
    context.lineWidth = 1;
    for (const t of order) {
      const [i, j, k] = [m.indices[3 * t], m.indices[3 * t + 1], m.indices[3 * t + 2]];
      a.fromArray(m.positions, 3 * i);
      b.fromArray(m.positions, 3 * j).sub(a);
      c.fromArray(m.positions, 3 * k).sub(a);
      const normal = b.cross(c);
      const length = normal.length();
      const shade = 0.35 + 0.65 * (length > 0 ? Math.abs(normal.dot(toLight)) / length : 0);
      const rgb = [0, 1, 2].map((q) => Math.round(255 * Math.min(1, m.colours[3 * i + q] * shade)));
      context.fillStyle = context.strokeStyle = `rgb(${rgb[0]},${rgb[1]},${rgb[2]})`;
      context.beginPath();
      context.moveTo(screen[3 * i], screen[3 * i + 1]);
      context.lineTo(screen[3 * j], screen[3 * j + 1]);
      context.lineTo(screen[3 * k], screen[3 * k + 1]);
      context.closePath();
      context.fill();
      context.stroke();  // no hairlines between neighbours
    }
  };

  const startWebGL = () => {
    renderer = new THREE.WebGLRenderer({ antialias: true });
    state.webglMs = performance.now() - state.started;
    renderer.setPixelRatio(window.devicePixelRatio);
    renderer.domElement.style.cssText = 'position: absolute; left: 0; top: 0;';
    container.appendChild(renderer.domElement);
    resize();
    renderer.compile(scene, camera);
    dirty = true;
  };

  worker.onmessage = ({ data }) => {
    if (data.type === 'error') return fail(data.message);
    if (data.type === 'opened') {
      diagonal = data.diagonal;
      state.diagonal = diagonal;
      state.fileDeviationBound = data.fileDeviationBound;
      state.openedMs = performance.now() - state.started;
      state.moduleMs = data.moduleMs;
      state.readMs = data.readMs;
      if (!(diagonal > 0)) return fail('the part is empty');
      pending = true;  // the worker meshes at coarseFraction at once
      state.refining = true;
      return;
    }
    pending = false;
    place(data);
    state.deviation = data.deviation;
    state.certified = data.certifiedDeviation;
    state.triangles = data.indices.length / 3;
    state.meshes.push({ deviation: data.deviation, triangles: state.triangles, milliseconds: data.milliseconds,
                        at: performance.now() - state.started });
    if (!renderer) drawSketch(data);
    requestAnimationFrame(() => {
      if (state.firstFrameMs === null) state.firstFrameMs = performance.now() - state.started;
      if (!renderer) startWebGL();
      refine();
    });
  };
  worker.onerror = (event) => fail(event.message || 'the worker failed');
  controls.addEventListener('end', refine);

  controls.addEventListener('change', () => { dirty = true; });

  // For tests: the silhouette of the mesh drawn now against that of another mesh of the part (positions in
  // the part's coordinates, float32, and indices), both drawn in the current view without antialiasing.
  // Returns the pixels each covers and how many of each lie more than one pixel (in x or y) from the other.
  state.compareSilhouettes = (positions, indices) => {
    const width = renderer.domElement.width, height = renderer.domElement.height;
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
    const other = new THREE.BufferGeometry();
    other.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    other.setIndex(new THREE.BufferAttribute(indices, 1));
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
    return { width, height, viewerPixels: count(mine), otherPixels: count(theirs),
             viewerBeyond: beyondOnePixel(mine, theirs), otherBeyond: beyondOnePixel(theirs, mine) };
  };
  let last = performance.now();
  // Frame gaps count while refining after the first frame with the part (that one compiles the shaders).
  const frame = (now) => {
    if (state.refining && state.firstFrameMs !== null) state.longestFrameGap = Math.max(state.longestFrameGap, now - last);
    last = now;
    ++state.frames;
    controls.update();
    if (dirty && renderer) {
      dirty = false;
      const drawing = performance.now();
      renderer.render(scene, camera);
      // What one draw costs the page's thread (the GPU's work, or a software renderer's), beside the gaps.
      state.longestDrawMs = Math.max(state.longestDrawMs, performance.now() - drawing);
      if (sketch.isConnected) {
        sketch.remove();
        state.firstWebGLFrameMs = performance.now() - state.started;
      }
    }
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);

  show(`${name}: reading…`);
  return state;
}

// A self-contained page (page.html): the part, the module and the worker's script are in its own elements.
export function startEmbeddedViewer() {
  const text = (id) => document.getElementById(id).textContent;
  const workerUrl = URL.createObjectURL(new Blob([text('cadnurbs-worker')], { type: 'text/javascript' }));
  return startViewer({
    container: document.getElementById('cadnurbs-view'), hud: document.getElementById('cadnurbs-hud'),
    partBytes: base64Bytes(text('cadnurbs-part')), wasmBytes: base64Bytes(text('cadnurbs-wasm')), workerUrl,
    name: document.getElementById('cadnurbs-part').dataset.name,
  });
}

// A page of a site (`batch --site`, site_page.html): the part's .cnb, the module and the worker's script are
// files beside it, named by the cadnurbs-site element's data attributes (relative to the page).
export function startSiteViewer() {
  const site = document.getElementById('cadnurbs-site').dataset;
  const url = (relative) => new URL(relative, document.baseURI).href;
  return startViewer({
    container: document.getElementById('cadnurbs-view'), hud: document.getElementById('cadnurbs-hud'),
    partUrl: url(site.part), wasmUrl: url(site.wasm), workerUrl: url(site.worker), name: site.name,
  });
}
