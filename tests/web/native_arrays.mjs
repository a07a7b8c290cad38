// A mesh native_scene_arrays wrote (its "CNSA" dump), for the browser tests that hold the module's or the
// viewer's meshes against native ones.
import { readFileSync } from 'node:fs';

export function readNativeArrays(path) {
  const b = readFileSync(path);
  if (b.toString('latin1', 0, 4) !== 'CNSA') throw new Error(`${path}: not a native_scene_arrays dump`);
  const vertices = b.readUInt32LE(4), triangles = b.readUInt32LE(8), faces = b.readUInt32LE(12);
  let at = 16;
  const doubles = (n) => { const a = new Float64Array(n); for (let i = 0; i < n; ++i, at += 8) a[i] = b.readDoubleLE(at); return a; };
  const uints = (n) => { const a = new Uint32Array(n); for (let i = 0; i < n; ++i, at += 4) a[i] = b.readUInt32LE(at); return a; };
  const floats = (n) => { const a = new Float32Array(n); for (let i = 0; i < n; ++i, at += 4) a[i] = b.readFloatLE(at); return a; };
  const [diagonal, deviation, certifiedDeviation] = doubles(3);
  return { diagonal, deviation, certifiedDeviation, positions: doubles(3 * vertices), indices: uints(3 * triangles),
           faceFirstTriangle: uints(faces + 1), normals: floats(3 * vertices) };
}
