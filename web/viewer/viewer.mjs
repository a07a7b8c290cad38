// The cadnurbs part viewer: three.js draws the meshes the worker (mesh_worker.mjs) makes with the
// WebAssembly module, coarse at once, then finer until every point is within one pixel of the exact part
// in the current view (the deviation is the world size of a pixel at the part's nearest point); orbit,
// fit to view, the faces' colours, and on screen the triangle count and the deviation the mesh is
// certified within. The page's thread keeps the camera, the controls and the status line; WebGL runs in a
// second worker (render_worker.mjs) on an OffscreenCanvas, so that its start and its draws never hold the
// page. Until WebGL's first frame the page shows its picture of the part (a site's page), or else the first
// mesh sketched on a 2D canvas (sketch.mjs).
// window.cadnurbsViewerState says what the viewer did, for tests and for the curious; its times are
// milliseconds since the page's navigation started.
import { Box3, MathUtils, OrbitControls, PerspectiveCamera, Vector3 } from './three_for_page.mjs';

import { startMeshWorker } from './mesh_worker_start.mjs';
import { whenPictureIsPainted } from './picture_painted.mjs';
import { drawSketch } from './sketch.mjs';

const finestFraction = 1e-5;     // of the diagonal: no finer, however close the camera comes
const refineRatio = 1.5;         // a new mesh only when the wanted deviation is this much finer

function base64Bytes(text) {
  const binary = atob(text.trim());
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; ++i) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

// 12345 as "12,345"; toLocaleString's first call loads the locale's data, which holds the page for tens of
// milliseconds.
function grouped(count) {
  return String(count).replace(/\B(?=(\d{3})+(?!\d))/g, ',');
}

function formatLength(value) {
  return value >= 1 ? value.toPrecision(3) : value.toExponential(2);
}

// Starts the viewer in `container`. `meshWorker`: the mesh worker startMeshWorker started on the part, which
// a page may start before this script loads; otherwise `part` says what to start it on (startMeshWorker's
// options). `rendererUrl`: the renderer's script; `hud`: an element for the status line; `picture`: an
// element shown until the first mesh is drawn (a site page's picture of the part), or null. Refuses a
// browser that cannot draw WebGL in a worker.
export function startViewer({ container, hud, picture = null, meshWorker = null, part = {}, rendererUrl, name }) {
  const state = {
    name, viewerStartedMs: performance.now(), error: '', longestFrameGap: 0, longestRenderGap: 0, meshes: [],
    openedMs: null, webglMs: null, pictureMs: null, sketchMs: null, firstFrameMs: null, firstWebGLFrameMs: null, longestDrawMs: 0, subPixelMs: null,
    deviation: null, certified: null, triangles: 0, refining: false,
  };
  window.cadnurbsViewerState = state;
  const show = (text) => { if (hud) hud.textContent = text; };
  const fail = (message) => { state.error = message; show(`${name}: ${message}`); };
  if (typeof OffscreenCanvas === 'undefined' || !HTMLCanvasElement.prototype.transferControlToOffscreen) {
    fail('this browser cannot draw WebGL in a worker (OffscreenCanvas)');
    return state;
  }
  const { worker, said } = meshWorker ?? startMeshWorker({ ...part, name });
  const layer = () => {
    const canvas = document.createElement('canvas');
    canvas.style.cssText = 'position: absolute; left: 0; top: 0; width: 100%; height: 100%;';
    container.appendChild(canvas);
    return canvas;
  };
  const size = () => ({ width: container.clientWidth || window.innerWidth, height: container.clientHeight || window.innerHeight });
  // WebGL's start (its script parsed, its shaders compiled by a software GPU where there is no other)
  // would delay the first frame on a machine of few cores: the renderer starts once the picture or the
  // sketch is shown.
  const glCanvas = layer();
  let renderer = null;
  const toRenderer = [];  // what the renderer is told before it starts
  const tell = (message, transfer = []) => (renderer ? renderer.postMessage(message, transfer) : toRenderer.push([message, transfer]));
  const startRenderer = () => {
    if (renderer) return;
    renderer = new Worker(rendererUrl);
    renderer.onmessage = ({ data }) => fromRenderer[data.type](data);
    renderer.onerror = (event) => fail(event.message || 'the renderer failed');
    const canvas = glCanvas.transferControlToOffscreen();
    renderer.postMessage({ type: 'start', canvas, ...size(), pixelRatio: window.devicePixelRatio }, [canvas]);
    for (const [message, transfer] of toRenderer.splice(0)) renderer.postMessage(message, transfer);
  };
  const sketch = picture ? null : layer();  // above WebGL's canvas until WebGL draws
  if (picture) {
    whenPictureIsPainted(picture, (paintedMs) => {
      if (paintedMs !== null) {
        state.pictureMs = paintedMs;
        if (state.firstFrameMs === null || paintedMs < state.firstFrameMs) state.firstFrameMs = paintedMs;
        updateCounting();
      }
      startRenderer();
    });
  }

  const camera = new PerspectiveCamera(35, 1, 1, 10);
  const controls = new OrbitControls(camera, container);
  let diagonal = 0, center = null, radius = 0, pixels = 1, pending = false, id = 0, meshId = -1, subPixelMeshId = null;
  let viewChanged = false, silhouettesReply = null;
  // The camera to the renderer, when it moved (orbit, fit, size) since it was last sent.
  const sendViewIfChanged = () => {
    if (!viewChanged) return;
    viewChanged = false;
    tell({ type: 'view', position: camera.position.toArray(), quaternion: camera.quaternion.toArray(),
           fov: camera.fov, aspect: camera.aspect, near: camera.near, far: camera.far });
  };
  // Frame gaps count from the first frame until the sub-pixel mesh is drawn, and whenever refining after.
  const counting = () => state.firstFrameMs !== null && (state.refining || state.subPixelMs === null);
  let countingGaps = false;
  const updateCounting = () => {
    if (counting() !== countingGaps) tell({ type: 'refining', value: (countingGaps = counting()) });
  };

  const resize = () => {
    const { width, height } = size();
    pixels = Math.floor(height * window.devicePixelRatio);  // WebGL's drawing buffer's height, as three.js sizes it
    if (sketch) [sketch.width, sketch.height] = [Math.round(width * window.devicePixelRatio), pixels];
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    tell({ type: 'size', width, height });
    viewChanged = true;
  };
  window.addEventListener('resize', resize);
  resize();

  // The deviation one pixel of the view allows at the part's nearest point.
  const pixelDeviation = () => {
    const nearest = Math.max(camera.position.distanceTo(center) - radius, camera.near);
    const pixel = (2 * nearest * Math.tan(MathUtils.degToRad(camera.fov) / 2)) / pixels;
    return Math.max(pixel, finestFraction * diagonal);
  };

  // The bounding sphere as three.js makes it (the box's centre, the farthest point), of the first mesh.
  const bound = (positions) => {
    center = new Box3().setFromArray(positions).getCenter(new Vector3());
    const p = new Vector3();
    for (let i = 0; i < positions.length; i += 3) radius = Math.max(radius, center.distanceToSquared(p.fromArray(positions, i)));
    radius = Math.sqrt(radius);
  };

  const fit = () => {
    const distance = radius / Math.sin(MathUtils.degToRad(camera.fov) / 2);
    const direction = new Vector3(1, -1.4, 0.9).normalize();
    camera.position.copy(center).addScaledVector(direction, distance);
    camera.up.set(0, 0, 1);
    camera.near = distance / 100;
    camera.far = distance * 10;
    camera.updateProjectionMatrix();
    controls.target.copy(center);
    controls.update();
    camera.updateMatrixWorld();
    viewChanged = true;
  };

  const ask = (deviation) => {
    pending = true;
    state.refining = true;
    worker.postMessage({ type: 'mesh', id: ++id, deviation });
  };
  // A mesh is as fine as its certified bound says, when every triangle has one (a .cnb's own meshes are
  // the file's: bound 0, nothing to refine).
  const achieved = () => (state.uncertified ? state.deviation : Math.min(state.deviation, state.certified));
  const refine = () => {
    if (pending || !center) return;
    const wanted = pixelDeviation();
    if (wanted * refineRatio < achieved()) {
      ask(wanted);
    } else if (state.refining) {
      state.refining = false;
      subPixelMeshId = meshId;
    }
    updateCounting();
    status();
  };
  // The meshing's figures are of the part the file holds; a .cnb also states how far that lies from the
  // exact part it was written from, and the two add up.
  const status = () => show(`${name} · ${grouped(state.triangles)} triangles · meshed within ${formatLength(state.deviation)}` +
                            ` of the file (certified ${formatLength(state.certified)})` +
                            (state.fileDeviationBound > 0 ? ` · the file within ${formatLength(state.fileDeviationBound)} of the exact part` : '') +
                            ` · ${state.refining ? 'refining…' : 'meshed below one pixel'}`);

  worker.onmessage = ({ data }) => {
    if (data.type === 'error') return fail(data.message);
    if (data.type === 'opened') {
      diagonal = state.diagonal = data.diagonal;
      state.fileDeviationBound = data.fileDeviationBound;
      state.openedMs = performance.now();
      state.moduleMs = data.moduleMs;
      state.readMs = data.readMs;
      if (!(diagonal > 0)) return fail('the part is empty');
      pending = true;  // the worker meshes coarsely at once (mesh_worker_start.mjs)
      state.refining = true;
      return;
    }
    pending = false;
    meshId = data.id;
    Object.assign(state, { deviation: data.deviation, certified: data.certifiedDeviation, uncertified: data.uncertifiedTriangles,
                           triangles: data.indices.length / 3 });
    state.meshes.push({ deviation: data.deviation, triangles: state.triangles, milliseconds: data.milliseconds, at: performance.now() });
    if (!center) {
      bound(data.positions);
      fit();
    }
    if (sketch && state.firstWebGLFrameMs === null) {
      const sketching = performance.now();
      drawSketch(sketch, camera, data);
      state.sketchMs = performance.now() - sketching;
      // Shown in the frame this rAF begins; the one after begins once that frame is out.
      requestAnimationFrame(() => requestAnimationFrame(() => {
        if (state.firstFrameMs === null) state.firstFrameMs = performance.now();
        updateCounting();
        startRenderer();
      }));
    }
    const { positions, normals, colours, indices } = data;
    sendViewIfChanged();
    tell({ type: 'mesh', id: meshId, positions, normals, colours, indices }, [positions.buffer, normals.buffer, colours.buffer, indices.buffer]);
    refine();
  };
  worker.onerror = (event) => fail(event.message || 'the mesh worker failed');
  for (const event of said.splice(0)) worker.onmessage(event);

  const onDrawn = ({ at, meshId: drawn, drawMs }) => {
    const now = at - performance.timeOrigin;
    state.longestDrawMs = Math.max(state.longestDrawMs, drawMs);
    if (state.firstWebGLFrameMs === null) {
      state.firstWebGLFrameMs = now;
      if (state.firstFrameMs === null) state.firstFrameMs = now;
      for (const shown of [sketch, picture]) if (shown) shown.style.visibility = 'hidden';
    }
    if (subPixelMeshId !== null && drawn >= subPixelMeshId) {
      if (state.subPixelMs === null) state.subPixelMs = now;
      subPixelMeshId = null;
    }
    updateCounting();
  };
  const fromRenderer = {
    ready: ({ at }) => { state.webglMs = at - performance.timeOrigin; },
    drawn: onDrawn,
    gap: ({ longestFrameGap }) => { state.longestRenderGap = longestFrameGap; },
    silhouettes: (reply) => silhouettesReply(reply),
  };
  controls.addEventListener('end', refine);
  controls.addEventListener('change', () => { viewChanged = true; });

  // For tests: the silhouette of the mesh drawn now against that of another mesh of the part (positions in
  // the part's coordinates, float32, and indices), both drawn in the current view without antialiasing.
  // Resolves to the pixels each covers and how many of each lie more than one pixel (in x or y) from the
  // other's.
  state.compareSilhouettes = (positions, indices) => new Promise((resolve) => {
    silhouettesReply = resolve;
    tell({ type: 'silhouettes', positions, indices }, [positions.buffer, indices.buffer]);
  });

  let last = performance.now();
  const frame = (now) => {
    if (counting()) state.longestFrameGap = Math.max(state.longestFrameGap, now - last);
    last = now;
    controls.update();
    if (center) sendViewIfChanged();
    requestAnimationFrame(frame);
  };
  requestAnimationFrame(frame);

  show(`${name}: reading…`);
  return state;
}

// A self-contained page (page.html): the part, the module and the workers' scripts are in its own elements.
export function startEmbeddedViewer() {
  const text = (id) => document.getElementById(id).textContent;
  const script = (id) => URL.createObjectURL(new Blob([text(id)], { type: 'text/javascript' }));
  return startViewer({
    container: document.getElementById('cadnurbs-view'), hud: document.getElementById('cadnurbs-hud'),
    part: { partBytes: base64Bytes(text('cadnurbs-part')), wasmBytes: base64Bytes(text('cadnurbs-wasm')), workerUrl: script('cadnurbs-worker') },
    rendererUrl: script('cadnurbs-renderer'), name: document.getElementById('cadnurbs-part').dataset.name,
  });
}

// A page of a site (`batch --site`, site_page.html), called by its script site_start.js once the page's
// picture is painted, with the mesh worker it started, the part (URLs of its .cnb and the shared files) and
// the picture.
export function startSiteViewer({ meshWorker, part, picture }) {
  return startViewer({
    container: document.getElementById('cadnurbs-view'), hud: document.getElementById('cadnurbs-hud'), picture,
    meshWorker, rendererUrl: part.rendererUrl, name: part.name,
  });
}
