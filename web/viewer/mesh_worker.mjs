// The viewer's worker: holds the part in the WebAssembly module and meshes it on request, so that the page
// never waits for the tessellator. Messages in:
//   (on starting)                                                      -> {type: 'started'}
//   {type: 'open', wasm: ArrayBuffer, bytes: ArrayBuffer, name}      -> {type: 'opened', diagonal} or {type: 'error'}
//   {type: 'open', wasmUrl, partUrl, name}                            -> the same, the two fetched here
//   {type: 'mesh', id, deviation}                                      -> {type: 'mesh', id, ...arrays} or {type: 'error', id}
// Positions go out as float32 (what WebGL draws), in the part's own coordinates.
import { loadCadnurbs } from 'cadnurbs';

let part = null;

async function fetched(url) {
  const response = await fetch(url);
  if (!response.ok) throw new Error(`${url}: ${response.status} ${response.statusText}`);
  return response.arrayBuffer();
}

async function open({ wasm, bytes, wasmUrl, partUrl, name }) {
  const start = performance.now();
  // From a URL the module compiles while it downloads (Emscripten's instantiateStreaming), the part
  // downloading beside it.
  const partBytes = partUrl ? fetched(partUrl) : Promise.resolve(bytes);
  const cadnurbs = await loadCadnurbs(wasmUrl ? { locateFile: () => wasmUrl } : { wasmBinary: wasm, locateFile: (file) => file });
  const loaded = performance.now();
  part = cadnurbs.read(new Uint8Array(await partBytes), name);
  return { type: 'opened', diagonal: part.diagonal, moduleMs: loaded - start, readMs: performance.now() - loaded };
}

function mesh({ id, deviation }) {
  const start = performance.now();
  const m = part.mesh(deviation);
  const positions = Float32Array.from(m.positions);
  return {
    type: 'mesh', id, deviation, positions, normals: m.normals, indices: m.indices,
    faceFirstTriangle: m.faceFirstTriangle, faceColours: m.faceColours,
    certifiedDeviation: m.certifiedDeviation, uncertifiedTriangles: m.uncertifiedTriangles,
    milliseconds: performance.now() - start,
  };
}

self.postMessage({ type: 'started' });  // the viewer waits for this before it starts WebGL
self.onmessage = async (event) => {
  const request = event.data;
  try {
    const reply = request.type === 'open' ? await open(request) : mesh(request);
    const transfer = reply.type === 'mesh'
      ? [reply.positions.buffer, reply.normals.buffer, reply.indices.buffer, reply.faceFirstTriangle.buffer,
         reply.faceColours.buffer]
      : [];
    self.postMessage(reply, transfer);
  } catch (e) {
    self.postMessage({ type: 'error', id: request.id, message: e.message || String(e) });
  }
};
