#!/usr/bin/env node
// Renders a glTF binary (.glb) with three.js's GLTFLoader, or an STL with its STLLoader, in headless
// Chromium (playwright-core, SwiftShader WebGL) and saves the silhouettes as a PNG.
//
//   render_glb.mjs IN OUT.png [--frame X0,Y0,Z0,X1,Y1,Z1] [--size 200] [--timeout SECONDS] [--chromium PATH]
//
// IN.glb is loaded the way a web page would: GLTFLoader with DRACOLoader (three's decoder files,
// examples/jsm/libs/draco/) and MeshoptDecoder (examples/jsm/libs/meshopt_decoder.module.js), so
// KHR_draco_mesh_compression, EXT_meshopt_compression and KHR_mesh_quantization files decode as in a
// browser. IN.stl is taken as cadnurbs writes meshes: millimetres, +Z up; it is brought into glTF's
// frame here (x 0.001, then (x, y, z) -> (x, z, -y)), independently of our glTF writer, so it can be
// the reference a .glb is compared with.
// The picture is three orthographic views side by side, each SIZE x SIZE pixels: from above (looking
// down -Y, -Z up in the picture), from the front (looking down -Z, +Y up), from the side (looking down
// -X, +Y up). Every triangle is drawn black on white, both sides, no antialiasing: only the silhouette
// counts. Each view frames the box FRAME (glTF coordinates, metres) with a 10 % margin; without --frame
// it frames IN's own bounding box. Prints one line of JSON: {"box": [x0, y0, z0, x1, y1, z1], "meshes",
// "triangles"} (IN's world bounding box as three sees it), which a second run can pass as --frame so
// both pictures share one camera: a file in the wrong unit or mirrored then shows as different.
// Exit status 0 with OUT.png written; 1 with a one-line error on stderr when loading fails, the model
// is empty, or the page logs an error; 2 on bad arguments. Chromium: CHROMIUM or /usr/bin/chromium.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import http from 'node:http';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const usageLine = 'usage: render_glb.mjs IN OUT.png [--frame X0,Y0,Z0,X1,Y1,Z1] [--size 200] [--timeout SECONDS] [--chromium PATH]';
function usage(msg) {
  if (msg) process.stderr.write(`render_glb: ${msg}\n`);
  process.stderr.write(usageLine + '\n');
  process.exit(2);
}

const opt = { frame: null, size: 200, timeout: 90, chromium: process.env.CHROMIUM || '/usr/bin/chromium' };
const files = [];
{
  const a = process.argv.slice(2);
  for (let i = 0; i < a.length; ++i) {
    const arg = a[i];
    const value = () => { if (a[i + 1] === undefined) usage(`${arg} needs a value`); return a[++i]; };
    const positive = () => { const v = Number(value()); if (!Number.isInteger(v) || v <= 0) usage(`${arg} needs a positive integer`); return v; };
    if (arg === '--frame') {
      opt.frame = value().split(',').map(Number);
      if (opt.frame.length !== 6 || opt.frame.some((v) => !Number.isFinite(v))) usage('--frame needs six numbers');
    } else if (arg === '--size') opt.size = positive();
    else if (arg === '--timeout') opt.timeout = positive();
    else if (arg === '--chromium') opt.chromium = value();
    else if (arg === '-h' || arg === '--help') usage();
    else if (arg.startsWith('--')) usage(`unknown option ${arg}`);
    else files.push(arg);
  }
}
if (files.length !== 2) usage('need IN and OUT.png');
const [inFile, outFile] = files.map((f) => path.resolve(f));
const kind = path.extname(inFile).toLowerCase().slice(1);
if (kind !== 'glb' && kind !== 'stl') usage(`IN must be .glb or .stl: ${files[0]}`);
if (!fs.existsSync(inFile)) usage(`no such file: ${files[0]}`);
const threeDir = path.join(here, 'node_modules', 'three');
if (!fs.existsSync(path.join(threeDir, 'build', 'three.module.js'))) {
  process.stderr.write(`render_glb: three not installed: run npm ci in ${here}\n`);
  process.exit(2);
}
let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch {
  process.stderr.write(`render_glb: playwright-core not installed: run npm ci in ${here}\n`);
  process.exit(2);
}

// The page: three from node_modules through an import map; window.render(url, kind, frame, size).
const pageHtml = `<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>render_glb</title>
<style>html, body { margin: 0; background: #fff; overflow: hidden; } canvas { display: block; }</style>
<script type="importmap">{ "imports": { "three": "/three/build/three.module.js", "three/addons/": "/three/examples/jsm/" } }</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
import { STLLoader } from 'three/addons/loaders/STLLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

async function load(url, kind) {
  if (kind === 'stl') {
    const geometry = await new STLLoader().loadAsync(url);
    const mesh = new THREE.Mesh(geometry);
    // cadnurbs STL: millimetres, +Z up. glTF: metres, +Y up.
    mesh.applyMatrix4(new THREE.Matrix4().makeRotationX(-Math.PI / 2).multiply(new THREE.Matrix4().makeScale(0.001, 0.001, 0.001)));
    const scene = new THREE.Scene();
    scene.add(mesh);
    return scene;
  }
  const draco = new DRACOLoader().setDecoderPath('/three/examples/jsm/libs/draco/');
  const loader = new GLTFLoader().setDRACOLoader(draco).setMeshoptDecoder(MeshoptDecoder);
  const gltf = await loader.loadAsync(url);
  draco.dispose();
  const scene = new THREE.Scene();
  scene.add(gltf.scene);
  return scene;
}

window.render = async (url, kind, frame, size) => {
  const scene = await load(url, kind);
  scene.updateMatrixWorld(true);
  let meshes = 0, triangles = 0;
  scene.traverse((o) => {
    if (!o.isMesh) return;
    ++meshes;
    const g = o.geometry;
    triangles += (g.index ? g.index.count : g.attributes.position.count) / 3;
  });
  const box = new THREE.Box3().setFromObject(scene);
  if (box.isEmpty()) throw new Error('the model has no geometry');
  const f = frame ? new THREE.Box3(new THREE.Vector3(frame[0], frame[1], frame[2]), new THREE.Vector3(frame[3], frame[4], frame[5])) : box;
  const centre = f.getCenter(new THREE.Vector3()), sizes = f.getSize(new THREE.Vector3());
  scene.background = new THREE.Color(0xffffff);
  scene.overrideMaterial = new THREE.MeshBasicMaterial({ color: 0x000000, side: THREE.DoubleSide });
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(1);
  renderer.setSize(3 * size, size);
  renderer.setScissorTest(true);
  document.body.appendChild(renderer.domElement);
  // [looking along, up in the picture, the two box extents seen]
  const views = [
    [new THREE.Vector3(0, -1, 0), new THREE.Vector3(0, 0, -1), sizes.x, sizes.z],
    [new THREE.Vector3(0, 0, -1), new THREE.Vector3(0, 1, 0), sizes.x, sizes.y],
    [new THREE.Vector3(-1, 0, 0), new THREE.Vector3(0, 1, 0), sizes.z, sizes.y],
  ];
  const depth = sizes.length() + 1e-9;
  views.forEach(([direction, up, width, height], i) => {
    const half = 0.55 * Math.max(width, height, 1e-9);
    const camera = new THREE.OrthographicCamera(-half, half, half, -half, 0, 4 * depth);
    camera.up.copy(up);
    camera.position.copy(centre).addScaledVector(direction, -2 * depth);
    camera.lookAt(centre);
    camera.updateMatrixWorld(true);
    renderer.setViewport(i * size, 0, size, size);
    renderer.setScissor(i * size, 0, size, size);
    renderer.render(scene, camera);
  });
  return { box: [...box.min.toArray(), ...box.max.toArray()], meshes, triangles };
};
window.pageReady = true;
</script></head><body></body></html>
`;

// The file of three's package a /three/... URL names; null outside the package or when there is none.
function threeFile(urlPath) {
  let full;
  try { full = path.join(threeDir, decodeURIComponent(urlPath.slice('/three/'.length))); } catch { return null; }
  return full.startsWith(threeDir + path.sep) && fs.statSync(full, { throwIfNoEntry: false })?.isFile() ? full : null;
}
const mime = { '.js': 'text/javascript', '.mjs': 'text/javascript', '.wasm': 'application/wasm', '.glb': 'model/gltf-binary', '.stl': 'model/stl' };
const missing = [];
const server = http.createServer((req, res) => {
  const url = new URL(req.url, 'http://127.0.0.1');
  let file = null;
  if (url.pathname === '/') {
    res.writeHead(200, { 'Content-Type': 'text/html; charset=utf-8' });
    res.end(pageHtml);
    return;
  }
  if (url.pathname === '/favicon.ico') { res.writeHead(204); res.end(); return; }
  if (url.pathname.startsWith('/three/')) file = threeFile(url.pathname);
  else if (url.pathname === `/model/${encodeURIComponent(path.basename(inFile))}`) file = inFile;
  if (!file) {
    missing.push(url.pathname);
    res.writeHead(404);
    res.end('not found');
    return;
  }
  res.writeHead(200, { 'Content-Type': mime[path.extname(file)] ?? 'application/octet-stream', 'Cache-Control': 'no-store' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((resolve, reject) => { server.once('error', reject); server.listen(0, '127.0.0.1', resolve); });
const origin = `http://127.0.0.1:${server.address().port}`;

const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'render_glb-'));
const errors = [];
let context = null;
async function cleanup() {
  try { if (context) await context.close(); } catch { /* already gone */ }
  context = null;
  server.close();
  fs.rmSync(userDataDir, { recursive: true, force: true });
}
const deadline = setTimeout(() => {
  process.stderr.write(`render_glb: ${files[0]}: timed out after ${opt.timeout} s\n`);
  cleanup().finally(() => process.exit(1));
}, opt.timeout * 1000);
const oneLine = (s) => String(s).replace(/\s+/g, ' ').trim().slice(0, 400);

let result = null;
try {
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: opt.chromium,
    headless: true,
    args: ['--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
    viewport: { width: 3 * opt.size, height: opt.size },
    deviceScaleFactor: 1,
  });
  const page = context.pages()[0] ?? await context.newPage();
  page.on('console', (msg) => { if (msg.type() === 'error') errors.push(oneLine(msg.text())); });
  page.on('pageerror', (err) => errors.push(oneLine(`page error: ${err.message}`)));
  page.on('crash', () => errors.push('page crashed'));
  await page.goto(`${origin}/`, { waitUntil: 'load' });
  await page.waitForFunction(() => window.pageReady === true);
  result = await page.evaluate(async ({ url, kind, frame, size }) => {
    try { return await window.render(url, kind, frame, size); } catch (e) { return { error: String(e?.message ?? e) }; }
  }, { url: `/model/${encodeURIComponent(path.basename(inFile))}`, kind, frame: opt.frame, size: opt.size });
  if (result.error) errors.unshift(`cannot load: ${result.error}`);
  else if (errors.length === 0) {
    fs.mkdirSync(path.dirname(outFile), { recursive: true });
    await page.locator('canvas').screenshot({ path: `${outFile}.tmp.png`, type: 'png' });
    fs.renameSync(`${outFile}.tmp.png`, outFile);
  }
} catch (e) {
  errors.push(oneLine(e?.message ?? e));
}
clearTimeout(deadline);
await cleanup();
if (errors.length) {
  if (missing.length) errors.push(`not found on the test server: ${missing.join(', ')}`);
  process.stderr.write(`render_glb: ${files[0]}: ${errors.join(' | ')}\n`);
  process.exit(1);
}
process.stdout.write(JSON.stringify(result) + '\n');
