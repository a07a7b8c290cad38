// cadnurbs in the browser (and in Node.js): read a part's bytes (.cnb, VRML97, X3D) and mesh it within a
// deviation, with the same certified tessellator as the cadnurbs command. A thin wrapper over the C
// interface of cadnurbs_module.cpp; the arrays it returns are copies, owned by JavaScript.
//
//   import { loadCadnurbs } from './cadnurbs.mjs';
//   const cadnurbs = await loadCadnurbs();
//   const part = cadnurbs.read(bytes, 'part.cnb');   // Uint8Array; throws Error with the reader's message
//   const mesh = part.mesh(part.diagonal * 1e-3);    // {positions, normals, indices, faceFirstTriangle,
//   part.free();                                     //  faceColours, certifiedDeviation, ...}
import createCadnurbsWasm from './cadnurbs_wasm.mjs';

const errorSize = 1024;

class Part {
  constructor(wasm, scene) {
    this.wasm = wasm;
    this.scene = scene;
    this.diagonal = wasm._cn_scene_diagonal(scene);
    // What the file states of its own deviation from the part it was written from (0: none stated).
    this.fileDeviationBound = wasm._cn_scene_file_deviation_bound(scene);
  }

  // The certified mesh within `deviation` (the part's units): every point of it within `deviation` of the
  // exact part where certifiedDeviation says so (uncertifiedTriangles counts those above it).
  mesh(deviation) {
    const w = this.wasm;
    const error = w._malloc(errorSize);
    try {
      const m = w._cn_mesh(this.scene, deviation, error, errorSize);
      if (!m) throw new Error(w.UTF8ToString(error));
      try {
        const vertices = w._cn_mesh_vertex_count(m), triangles = w._cn_mesh_triangle_count(m);
        const faces = w._cn_mesh_face_count(m);
        const copy = (View, pointer, count) => new View(w.HEAPU8.buffer, pointer, count).slice();
        return {
          positions: copy(Float64Array, w._cn_mesh_positions(m), 3 * vertices),
          normals: copy(Float32Array, w._cn_mesh_normals(m), 3 * vertices),
          indices: copy(Uint32Array, w._cn_mesh_indices(m), 3 * triangles),
          faceFirstTriangle: copy(Uint32Array, w._cn_mesh_face_first_triangle(m), faces + 1),
          faceColours: copy(Float32Array, w._cn_mesh_face_colours(m), 3 * faces),
          certifiedDeviation: w._cn_mesh_certified_deviation(m),
          uncertifiedTriangles: w._cn_mesh_uncertified_triangles(m),
          sewn: w._cn_mesh_sewn(m) !== 0,
        };
      } finally {
        w._cn_mesh_free(m);
      }
    } finally {
      w._free(error);
    }
  }

  free() {
    if (this.scene) this.wasm._cn_scene_free(this.scene);
    this.scene = 0;
  }
}

class Cadnurbs {
  constructor(wasm) {
    this.wasm = wasm;
  }

  // The part in `bytes` (a Uint8Array); `name` names it in error messages.
  read(bytes, name = 'part') {
    const w = this.wasm;
    const data = w._malloc(Math.max(bytes.length, 1));
    const nameBytes = new TextEncoder().encode(name + '\0');
    const namePointer = w._malloc(nameBytes.length);
    const error = w._malloc(errorSize);
    try {
      w.HEAPU8.set(bytes, data);
      w.HEAPU8.set(nameBytes, namePointer);
      const scene = w._cn_read(data, bytes.length, namePointer, error, errorSize);
      if (!scene) throw new Error(w.UTF8ToString(error));
      return new Part(w, scene);
    } finally {
      w._free(data);
      w._free(namePointer);
      w._free(error);
    }
  }
}

// Loads the WebAssembly module; `options` go to Emscripten's module factory (locateFile, wasmBinary, ...).
export async function loadCadnurbs(options = {}) {
  return new Cadnurbs(await createCadnurbsWasm(options));
}
