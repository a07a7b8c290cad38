// Starts the mesh worker (mesh_worker.mjs) on a part: from bytes (partBytes, wasmBytes: a page that carries
// them) or from URLs the worker fetches (partUrl, wasmUrl: a site's pages). The worker meshes the part at
// coarseFraction of its diagonal as soon as it has read it. Returns {worker, said}: what the worker says
// before the viewer listens is kept in `said`, in order (a worker's messages with no listener are lost),
// so that a page can start the worker before the viewer's script has loaded (site_start.mjs).
export const coarseFraction = 1e-2;

export function startMeshWorker({ workerUrl, partBytes, wasmBytes, partUrl, wasmUrl, name }) {
  const worker = new Worker(workerUrl);
  const said = [];
  worker.onmessage = (event) => said.push(event);
  if (partUrl) {
    worker.postMessage({ type: 'open', partUrl, wasmUrl, name, firstMesh: coarseFraction });
  } else {
    const wasm = wasmBytes.buffer.slice(wasmBytes.byteOffset, wasmBytes.byteOffset + wasmBytes.byteLength);
    const bytes = partBytes.buffer.slice(partBytes.byteOffset, partBytes.byteOffset + partBytes.byteLength);
    worker.postMessage({ type: 'open', wasm, bytes, name, firstMesh: coarseFraction }, [wasm, bytes]);
  }
  return { worker, said };
}
