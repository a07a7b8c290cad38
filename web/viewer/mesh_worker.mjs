// The viewer's worker: holds the part in the WebAssembly module and meshes it on request, so that the page
// never waits for the tessellator. Messages in:
//   {type: 'open', wasm: ArrayBuffer, bytes: ArrayBuffer, name}      -> {type: 'opened', diagonal, fileDeviationBound} or {type: 'error'}
//   {type: 'open', wasmUrl, partUrl, name}                            -> the same, the two fetched here
//   (either open with firstMesh: F)                                    -> then {type: 'mesh', id: 0, ...} at F x diagonal
//   {type: 'mesh', id, deviation}                                      -> {type: 'mesh', id, ...arrays} or {type: 'error', id}
// Positions go out as float32 (what WebGL draws), in the part's own coordinates, with a colour per vertex.
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
  return { type: 'opened', diagonal: part.diagonal, fileDeviationBound: part.fileDeviationBound, moduleMs: loaded - start, readMs: performance.now() - loaded };
}

function mesh({ id, deviation }) {
  const start = performance.now();
  const m = part.mesh(deviation);
  const positions = Float32Array.from(m.positions);
  // Each vertex in its face's colour, here rather than on the page's thread (a vertex is in one face).
  const colours = new Float32Array(positions.length);
  const faces = m.faceColours.length / 3;
  for (let f = 0; f < faces; ++f) {
    const colour = m.faceColours.subarray(3 * f, 3 * f + 3);
    for (let c = 3 * m.faceFirstTriangle[f]; c < 3 * m.faceFirstTriangle[f + 1]; ++c) colours.set(colour, 3 * m.indices[c]);
  }
  return {
    type: 'mesh', id, deviation, positions, normals: m.normals, colours, indices: m.indices,
    faceFirstTriangle: m.faceFirstTriangle, faceColours: m.faceColours,
    certifiedDeviation: m.certifiedDeviation, uncertifiedTriangles: m.uncertifiedTriangles,
    milliseconds: performance.now() - start,
  };
}

function post(reply) {
  const transfer = reply.type === 'mesh'
    ? [reply.positions.buffer, reply.normals.buffer, reply.colours.buffer, reply.indices.buffer, reply.faceFirstTriangle.buffer,
       reply.faceColours.buffer]
    : [];
  self.postMessage(reply, transfer);
}

self.onmessage = async (event) => {
  const request = event.data;
  try {
    if (request.type !== 'open') return post(mesh(request));
    const opened = await open(request);
    post(opened);
    // The first mesh at once, at `firstMesh` of the diagonal, without waiting for the page to ask.
    if (request.firstMesh > 0) post(mesh({ id: 0, deviation: request.firstMesh * opened.diagonal }));
  } catch (e) {
    self.postMessage({ type: 'error', id: request.id, message: e.message || String(e) });
  }
};
