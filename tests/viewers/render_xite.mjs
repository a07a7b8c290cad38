#!/usr/bin/env node
// Renders a VRML97 / X3D file with X_ITE (npm x_ite) in headless Chromium and saves a PNG
// of the canvas only.
//
//   render_xite.mjs IN OUT.png [--width 400] [--height 300] [--timeout SECONDS]
//                   [--protos DIR] [--chromium PATH] [--ignore-errors]
//                   [--background R,G,B] [--time]
//
// IN's folder is served read-only on an ephemeral port of 127.0.0.1, together with
// X_ITE's dist folder, so relative URLs inside IN (Inline, EXTERNPROTO, textures) resolve
// against IN's folder. A file that is not in IN's folder but is in the --protos folder
// (default: formats/vrml/protos of this source tree) is served from there: so the
// EXTERNPROTO URL "cadnurbs-nurbs-protos.wrl#NurbsSurface" that cadnurbs writes finds
// the project's implementation PROTOs without copying them next to IN.
//
// The page is white; when the file binds no Background, X_ITE's default (black) one is
// made white, or the colour of --background R,G,B (components 0..1 or 0..255), so that
// white or grey parts stand out against it (the page is then that colour too).
// --time prints one line "render_xite: time load S first-frame S" on stdout: seconds from
// the loadURL call to the world loaded (every EXTERNPROTO, Inline and PROTO Script
// initialize() done), and to the first frame rendered after it.
// X_ITE's splash screen, notifications and context menu are off; the navigation headlight
// is left as the file sets it; the file's own first Viewpoint is used as it is (X_ITE's
// StraightenHorizon option, on by default, is turned off: it would roll a Viewpoint whose
// up direction is not +Y). After X_ITE reports the world loaded (Browser.loadURL
// resolved: every EXTERNPROTO and Inline done) the script waits a few rendered frames,
// then screenshots the <x3d-canvas> element.
//
// Exit status 0 with OUT.png written; 1 with a one-line error on stderr when the scene
// fails to load or the page reports an error (X_ITE console errors, X_ITE parser errors,
// which it logs as warnings, and uncaught page errors are collected and printed); 2 on
// bad arguments. Other console warnings are printed to stderr but do not fail the run.
// --ignore-errors still prints the errors but takes the screenshot and exits 0 when the
// page got that far (for looking at files that are known to have problems). Chromium: CHROMIUM env var or --chromium, default
// /usr/bin/chromium.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import http from 'node:http';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';

const here = path.dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);

function usage(msg) {
  if (msg) process.stderr.write(`render_xite: ${msg}\n`);
  process.stderr.write('usage: render_xite.mjs IN OUT.png [--width 400] [--height 300] [--timeout SECONDS] [--protos DIR] [--chromium PATH] [--ignore-errors] [--background R,G,B] [--time]\n');
  process.exit(2);
}

// ---------------------------------------------------------------- arguments
const opt = {
  width: 400,
  height: 300,
  timeout: 90,
  protos: path.resolve(here, '../../formats/vrml/protos'),
  chromium: process.env.CHROMIUM || '/usr/bin/chromium',
  ignoreErrors: false,
  background: null, // [r, g, b] in 0..1, or null for white
  time: false,
};
const positional = [];
// "R,G,B" with components in 0..1, or in 0..255 when any exceeds 1.
function parseColour(text) {
  const c = text.split(',').map(Number);
  if (c.length !== 3 || c.some((v) => !Number.isFinite(v) || v < 0 || v > 255)) usage(`--background needs R,G,B: ${text}`);
  return c.some((v) => v > 1) ? c.map((v) => v / 255) : c;
}
{
  const a = process.argv.slice(2);
  for (let i = 0; i < a.length; ++i) {
    const arg = a[i];
    const value = () => { if (a[i + 1] === undefined) usage(`${arg} needs a value`); return a[++i]; };
    const int = () => { const v = Number(value()); if (!Number.isInteger(v) || v <= 0) usage(`${arg} needs a positive integer`); return v; };
    if (arg === '--width') opt.width = int();
    else if (arg === '--height') opt.height = int();
    else if (arg === '--timeout') opt.timeout = int();
    else if (arg === '--protos') opt.protos = path.resolve(value());
    else if (arg === '--chromium') opt.chromium = value();
    else if (arg === '--ignore-errors') opt.ignoreErrors = true;
    else if (arg === '--time') opt.time = true;
    else if (arg === '--background') opt.background = parseColour(value());
    else if (arg === '-h' || arg === '--help') usage();
    else if (arg.startsWith('--')) usage(`unknown option ${arg}`);
    else positional.push(arg);
  }
}
if (positional.length !== 2) usage('need IN and OUT.png');
const inFile = path.resolve(positional[0]);
const outFile = path.resolve(positional[1]);
if (!fs.existsSync(inFile) || !fs.statSync(inFile).isFile()) usage(`no such file: ${positional[0]}`);
fs.rmSync(outFile, { force: true }); // never leave an old picture behind a failure

let xiteDist;
try {
  xiteDist = path.dirname(require.resolve('x_ite/x_ite.min.js'));
} catch {
  process.stderr.write(`render_xite: x_ite not installed: run npm ci in ${here}\n`);
  process.exit(2);
}
let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch {
  process.stderr.write(`render_xite: playwright-core not installed: run npm ci in ${here}\n`);
  process.exit(2);
}

// ---------------------------------------------------------------- static server
const sceneDir = path.dirname(inFile);
const mime = {
  '.html': 'text/html; charset=utf-8',
  '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8',
  '.css': 'text/css; charset=utf-8',
  '.json': 'application/json',
  '.wrl': 'model/vrml',
  '.x3dv': 'model/x3d+vrml',
  '.wrz': 'model/vrml',         // gzip'd; X_ITE inflates by content
  '.x3dvz': 'model/x3d+vrml',
  '.x3dz': 'model/x3d+xml',
  '.x3d': 'model/x3d+xml',
  '.x3dj': 'model/x3d+json',
  '.gz': 'application/gzip',
  '.png': 'image/png',
  '.jpg': 'image/jpeg',
  '.jpeg': 'image/jpeg',
  '.gif': 'image/gif',
  '.svg': 'image/svg+xml',
  '.woff2': 'font/woff2',
  '.ttf': 'font/ttf',
  '.otf': 'font/otf',
  '.wasm': 'application/wasm',
};

const pageColour = opt.background
  ? `rgb(${opt.background.map((v) => Math.round(v * 255)).join(',')})`
  : '#ffffff';
const page_html = `<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>render_xite</title>
<style>
html, body { margin: 0; padding: 0; background: ${pageColour}; overflow: hidden; }
x3d-canvas { display: block; width: ${opt.width}px; height: ${opt.height}px; background: ${pageColour}; }
</style>
<script src="/x_ite/x_ite.min.js"></script>
</head><body>
<x3d-canvas id="canvas" splashScreen="false" notifications="false" contextMenu="false" timings="false"></x3d-canvas>
</body></html>
`;

// Resolves a URL path below root; null when it escapes root or is not a file.
function fileBelow(root, urlPath) {
  let rel;
  try { rel = decodeURIComponent(urlPath); } catch { return null; }
  const full = path.resolve(root, '.' + path.posix.normalize('/' + rel));
  if (full !== root && !full.startsWith(root + path.sep)) return null;
  try { return fs.statSync(full).isFile() ? full : null; } catch { return null; }
}

const served = [];
const server = http.createServer((req, res) => {
  const url = new URL(req.url, 'http://127.0.0.1');
  let file = null;
  if (url.pathname === '/' || url.pathname === '/index.html') {
    res.writeHead(200, { 'Content-Type': mime['.html'], 'Cache-Control': 'no-store' });
    res.end(page_html);
    return;
  }
  if (url.pathname === '/favicon.ico') { res.writeHead(204); res.end(); return; }
  if (url.pathname.startsWith('/x_ite/')) file = fileBelow(xiteDist, url.pathname.slice('/x_ite'.length));
  else if (url.pathname.startsWith('/scene/')) {
    const p = url.pathname.slice('/scene'.length);
    file = fileBelow(sceneDir, p) ?? (fs.existsSync(opt.protos) ? fileBelow(opt.protos, p) : null);
  }
  if (!file) {
    served.push(`404 ${url.pathname}`);
    res.writeHead(404, { 'Content-Type': 'text/plain' });
    res.end('not found');
    return;
  }
  served.push(`200 ${url.pathname}`);
  res.writeHead(200, { 'Content-Type': mime[path.extname(file).toLowerCase()] ?? 'application/octet-stream', 'Cache-Control': 'no-store' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((resolve, reject) => { server.once('error', reject); server.listen(0, '127.0.0.1', resolve); });
const origin = `http://127.0.0.1:${server.address().port}`;

// ---------------------------------------------------------------- browser
const userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'render_xite-'));
const errors = [];
const warnings = [];
let context = null;
let exitCode = 0;

const deadline = setTimeout(() => {
  process.stderr.write(`render_xite: ${positional[0]}: timed out after ${opt.timeout} s${errors.length ? ': ' + errors.join(' | ') : ''}\n`);
  cleanup().finally(() => process.exit(1));
}, opt.timeout * 1000);

async function cleanup() {
  try { if (context) await context.close(); } catch { /* already gone */ }
  context = null;
  server.close();
  fs.rmSync(userDataDir, { recursive: true, force: true });
}

const oneLine = (s) => String(s).replace(/\s+/g, ' ').trim().slice(0, 400);

try {
  context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: opt.chromium,
    headless: true,
    args: [
      '--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--no-first-run', '--disable-quic',
    ],
    viewport: { width: opt.width, height: opt.height },
    deviceScaleFactor: 1,
  });
  const page = context.pages()[0] ?? await context.newPage();
  page.on('console', (msg) => {
    const text = oneLine(msg.text());
    // EXTERNPROTO URL lists start with URNs (urn:web3d:..., urn:inet:blaxxun.com:...),
    // which a browser cannot fetch: X_ITE logs each failed try (and the bare fetch
    // TypeError) and goes on with the next URL. A URL that really fails is still
    // reported by its own "Couldn't load URL 'http...'" error.
    const benign = /\burn:/.test(text) || text.startsWith('TypeError: Failed to fetch');
    if (msg.type() === 'error' && !benign) errors.push(text);
    else if (msg.type() === 'warning' && /Parser error|Unknown (node|proto|field)/i.test(text)) errors.push(text);
    else if (msg.type() === 'warning') warnings.push(text);
  });
  page.on('pageerror', (err) => errors.push(oneLine(`page error: ${err.message}`)));
  page.on('crash', () => errors.push('page crashed'));

  await page.goto(`${origin}/`, { waitUntil: 'load' });
  const sceneURL = `${origin}/scene/${encodeURIComponent(path.basename(inFile))}`;
  const loaded = await page.evaluate(async ({ url, sky }) => {
    const canvas = document.getElementById('canvas');
    const X3D = window.X3D;
    if (!X3D) return { ok: false, error: 'X_ITE did not load' };
    const browser = X3D.getBrowser(canvas);
    // Show the file's Viewpoint exactly: X_ITE's default "straighten horizon" would roll
    // a Viewpoint whose up direction is not +Y.
    browser.setBrowserOption('StraightenHorizon', false);
    const start = performance.now();
    try {
      await browser.loadURL(new X3D.MFString(url));
    } catch (e) {
      return { ok: false, error: `X_ITE failed to load the scene: ${e?.message ?? e}` };
    }
    const loadSeconds = (performance.now() - start) / 1000;
    // Fixed white (or --background) sky when the file binds no Background: X_ITE's default Background is
    // black (the X3D default skyColor). Uses X_ITE internals; harmless if they change,
    // compare_images.mjs finds the background colour by itself.
    let defaultBackgroundSet = false;
    try {
      const layer = browser.getActiveLayer?.();
      const background = layer?.getBackground?.();
      if (background && background === layer.defaultBackground) {
        background._skyColor = new X3D.MFColor(new X3D.SFColor(sky[0], sky[1], sky[2]));
        defaultBackgroundSet = true;
      }
    } catch { /* keep X_ITE's default */ }
    // Let scripts, EXTERNPROTO instances and geometry settle: a few rendered frames.
    await browser.nextFrame();
    const firstFrameSeconds = (performance.now() - start) / 1000;
    for (let i = 0; i < 3; ++i) await browser.nextFrame();
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const scene = browser.currentScene;
    return { ok: true, rootNodes: scene ? scene.rootNodes.length : 0, defaultBackgroundSet, loadSeconds, firstFrameSeconds };
  }, { url: sceneURL, sky: opt.background ?? [1, 1, 1] });
  if (loaded.ok && opt.time)
    process.stdout.write(`render_xite: time load ${loaded.loadSeconds.toFixed(3)} first-frame ${loaded.firstFrameSeconds.toFixed(3)}\n`);

  if (!loaded.ok) errors.unshift(loaded.error);
  if (errors.length === 0 || (opt.ignoreErrors && loaded.ok)) {
    if (loaded.rootNodes === 0) errors.push('scene has no root nodes');
    else {
      fs.mkdirSync(path.dirname(outFile), { recursive: true });
      const tmp = `${outFile}.tmp`;
      await page.locator('#canvas').screenshot({ path: tmp, type: 'png', animations: 'disabled' });
      fs.renameSync(tmp, outFile);
    }
  }
} catch (e) {
  errors.push(oneLine(e?.message ?? e));
}

clearTimeout(deadline);
await cleanup();
for (const w of warnings.slice(0, 20)) process.stderr.write(`render_xite: warning: ${w}\n`);
if (errors.length) {
  const missing = served.filter((s) => s.startsWith('404 ')).map((s) => s.slice(4));
  if (missing.length) errors.push(`not found on the test server: ${missing.join(', ')}`);
  process.stderr.write(`render_xite: ${positional[0]}: ${errors.join(' | ')}\n`);
  exitCode = opt.ignoreErrors && fs.existsSync(outFile) ? 0 : 1;
}
process.exit(exitCode);
