// The browser module's meshes against native ones (issue 40): for each file, the WebAssembly build of
// web/api/scene_arrays (loaded in Node.js) and the native one (native_scene_arrays) mesh it within FRACTION
// of its diagonal; they must give the same vertex, triangle and face counts, the same indices and face
// ranges, positions within 1e-9 of the diagonal and normals within 1e-6.
//
//   node compare_with_native.mjs MODULE_DIR NATIVE_TOOL FRACTION OUT_DIR FILE...
//
// A FILE that is a folder stands for every .cnb file under it (a batch's outputs).
//
// Prints one line per file (counts, largest position difference over the diagonal, both meshing times)
// and exits 1 when any file differs or fails on one side only. A file both sides refuse with the same
// message passes (the message is printed).
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, readdirSync, readFileSync, statSync } from 'node:fs';
import { createRequire } from 'node:module';
import { basename, join, resolve } from 'node:path';

import { readNativeArrays } from './native_arrays.mjs';

const [moduleDirGiven, nativeTool, fractionText, outDir, ...given] = process.argv.slice(2);
const cnbUnder = (folder) => readdirSync(folder, { withFileTypes: true }).sort((a, b) => (a.name < b.name ? -1 : 1))
  .flatMap((entry) => (entry.isDirectory() ? cnbUnder(join(folder, entry.name))
                       : entry.name.endsWith('.cnb') ? [join(folder, entry.name)] : []));
const files = given.flatMap((path) => (existsSync(path) && statSync(path).isDirectory() ? cnbUnder(path) : [path]));
const moduleDir = resolve(moduleDirGiven ?? '');  // imported below: a relative path would name a package
if (!files.length) {
  console.error('usage: node compare_with_native.mjs MODULE_DIR NATIVE_TOOL FRACTION OUT_DIR FILE...');
  process.exit(2);
}
const fraction = Number(fractionText);
if (!existsSync(join(moduleDir, 'cadnurbs_wasm.wasm'))) {
  console.error(`${moduleDir}: the WebAssembly module is not built (it needs emcc and Debian's zlib source: scripts/setup.sh)`);
  process.exit(1);
}
mkdirSync(outDir, { recursive: true });

// Emscripten 3.1.6's ES module reaches for CommonJS names when it runs under Node.js.
globalThis.__dirname = moduleDir;
globalThis.require = createRequire(import.meta.url);
const { loadCadnurbs } = await import(join(moduleDir, 'cadnurbs.mjs'));
const cadnurbs = await loadCadnurbs({ wasmBinary: readFileSync(join(moduleDir, 'cadnurbs_wasm.wasm')) });

function firstDifference(a, b) {
  if (a.length !== b.length) return `lengths ${a.length} and ${b.length}`;
  for (let i = 0; i < a.length; ++i) if (a[i] !== b[i]) return `at ${i}: ${a[i]} and ${b[i]}`;
  return '';
}

function largestDifference(a, b) {
  let d = 0;
  for (let i = 0; i < a.length; ++i) d = Math.max(d, Math.abs(a[i] - b[i]));
  return d;
}

let failures = 0;
for (const file of files) {
  const name = basename(file);  // the dumps of same-named files in two folders take turns: each is read at once
  const dump = join(outDir, `${name}.native`);
  let native, nativeError = '', nativeMs = 0;
  try {
    const start = performance.now();
    execFileSync(nativeTool, [file, String(fraction), dump], { stdio: ['ignore', 'ignore', 'pipe'] });
    nativeMs = performance.now() - start;
    native = readNativeArrays(dump);
  } catch (e) {
    nativeError = (e.stderr ? e.stderr.toString() : e.message).trim();
  }
  let wasm, wasmError = '', wasmMs = 0;
  try {
    const start = performance.now();
    const part = cadnurbs.read(readFileSync(file), file);
    try {
      wasm = part.mesh(fraction * part.diagonal);
    } finally {
      part.free();
    }
    wasmMs = performance.now() - start;
  } catch (e) {
    wasmError = e.message;
  }
  if (nativeError || wasmError) {
    const same = nativeError === wasmError;
    if (!same) ++failures;
    console.log(`${name}\t${same ? 'both refuse' : 'DIFFERENT'}\tnative: ${nativeError || 'read'}\twasm: ${wasmError || 'read'}`);
    continue;
  }
  const problems = [];
  for (const field of ['indices', 'faceFirstTriangle']) {
    const d = firstDifference(native[field], wasm[field]);
    if (d) problems.push(`${field} differ (${d})`);
  }
  let positions = Infinity, normals = Infinity;
  if (native.positions.length === wasm.positions.length) {
    positions = largestDifference(native.positions, wasm.positions) / native.diagonal;
    normals = largestDifference(native.normals, wasm.normals);
  } else {
    problems.push(`vertex counts ${native.positions.length / 3} and ${wasm.positions.length / 3}`);
  }
  if (!(positions <= 1e-9)) problems.push(`positions differ by ${positions} of the diagonal`);
  if (!(normals <= 1e-6)) problems.push(`normals differ by ${normals}`);
  if (problems.length) ++failures;
  console.log(`${name}\t${problems.length ? 'DIFFERENT' : 'same'}\tvertices ${wasm.positions.length / 3}\t` +
              `triangles ${wasm.indices.length / 3}\tfaces ${wasm.faceColours.length / 3}\t` +
              `positions ${positions.toExponential(2)} of the diagonal\tnative ${nativeMs.toFixed(0)} ms\t` +
              `wasm ${wasmMs.toFixed(0)} ms${problems.length ? '\t' + problems.join('; ') : ''}`);
}
console.log(`${files.length - failures} of ${files.length} files mesh alike`);
process.exit(failures ? 1 : 0);
