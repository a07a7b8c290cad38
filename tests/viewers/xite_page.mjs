// X_ITE in headless Chromium, the part shared by render_xite.mjs and check_path_xite.mjs: a static
// server on an ephemeral port of 127.0.0.1 and one page holding an <x3d-canvas>.
//
// The server answers
//   /             the page: X_ITE's script and one <x3d-canvas id="canvas"> of width x height
//                 pixels on a `colour` background (splash screen, notifications, context menu off)
//   /x_ite/...    X_ITE's dist folder (npm x_ite of this folder)
//   /scene/...    session.sceneDir, or the `protos` folder for a file not found there: so the
//                 EXTERNPROTO URL "cadnurbs-nurbs-protos.wrl#Name" that cadnurbs writes finds the
//                 project's implementation PROTOs without a copy next to the scene. sceneDir may
//                 be changed between loads.
// Every request is recorded in session.served ("200 /path" or "404 /path"); missingFiles() lists
// the 404s, so a caller can name the file a failed load looked for.
//
// Console messages are sorted into session.errors and session.warnings: console errors, except
// the failed tries of EXTERNPROTO `urn:` URLs that X_ITE logs before it goes on to the next URL (a
// URL that really fails still gives its own "Couldn't load URL 'http...'" error); X_ITE's parser
// errors and unknown node / proto / field messages, which it logs as warnings; uncaught page
// errors and a crashed page. Other warnings go to session.warnings.
//
// Use: requireXite(program) (exits 2 naming the missing npm package), then
//   const session = new XiteSession({ sceneDir, protos, chromium, width, height, colour });
//   await session.serve(); await session.launch(playwrightChromium); ... session.page ...
//   await session.close();   // safe at any stage, more than once
// Chromium runs with SwiftShader WebGL (no GPU needed) and a throw-away profile directory.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import http from 'node:http';
import { fileURLToPath } from 'node:url';
import { createRequire } from 'node:module';

const here = path.dirname(fileURLToPath(import.meta.url));
const require = createRequire(import.meta.url);

// The project's implementation PROTOs, the default `protos` folder.
export const defaultProtosDir = path.resolve(here, '../../formats/vrml/protos');

// X_ITE's dist folder and playwright's chromium launcher; exits 2 with "PROGRAM: ... not
// installed: run npm ci in <this folder>" when either is missing.
export async function requireXite(program) {
  let xiteDist;
  try {
    xiteDist = path.dirname(require.resolve('x_ite/x_ite.min.js'));
  } catch {
    process.stderr.write(`${program}: x_ite not installed: run npm ci in ${here}\n`);
    process.exit(2);
  }
  try {
    const { chromium } = await import('playwright-core');
    return { xiteDist, chromium };
  } catch {
    process.stderr.write(`${program}: playwright-core not installed: run npm ci in ${here}\n`);
    process.exit(2);
  }
}

// Collapses whitespace and keeps 400 characters, for one-line error reports.
export const oneLine = (s) => String(s).replace(/\s+/g, ' ').trim().slice(0, 400);

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

function pageHtml(width, height, colour) {
  return `<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>xite_page</title>
<style>
html, body { margin: 0; padding: 0; background: ${colour}; overflow: hidden; }
x3d-canvas { display: block; width: ${width}px; height: ${height}px; background: ${colour}; }
</style>
<script src="/x_ite/x_ite.min.js"></script>
</head><body>
<x3d-canvas id="canvas" splashScreen="false" notifications="false" contextMenu="false" timings="false"></x3d-canvas>
</body></html>
`;
}

// Resolves a URL path below root; null when it escapes root or is not a file.
function fileBelow(root, urlPath) {
  let rel;
  try { rel = decodeURIComponent(urlPath); } catch { return null; }
  const full = path.resolve(root, '.' + path.posix.normalize('/' + rel));
  if (full !== root && !full.startsWith(root + path.sep)) return null;
  try { return fs.statSync(full).isFile() ? full : null; } catch { return null; }
}

export class XiteSession {
  // xiteDist: from requireXite; colour: a CSS colour for the page and the canvas.
  // initScript: optional { script, arg } run in the page before X_ITE loads (playwright's addInitScript).
  constructor({ xiteDist, sceneDir, protos = defaultProtosDir, chromium, width = 400, height = 300, colour = '#ffffff', initScript = null }) {
    Object.assign(this, { xiteDist, sceneDir, protos, chromiumPath: chromium, width, height, initScript });
    this.html = pageHtml(width, height, colour);
    this.served = [];
    this.errors = [];
    this.warnings = [];
    this.server = null;
    this.origin = null;
    this.context = null;
    this.page = null;
    this.userDataDir = null;
  }

  async serve() {
    this.server = http.createServer((req, res) => this.answer(req, res));
    await new Promise((resolve, reject) => {
      this.server.once('error', reject);
      this.server.listen(0, '127.0.0.1', resolve);
    });
    this.origin = `http://127.0.0.1:${this.server.address().port}`;
  }

  answer(req, res) {
    const url = new URL(req.url, 'http://127.0.0.1');
    let file = null;
    if (url.pathname === '/' || url.pathname === '/index.html') {
      res.writeHead(200, { 'Content-Type': mime['.html'], 'Cache-Control': 'no-store' });
      res.end(this.html);
      return;
    }
    if (url.pathname === '/favicon.ico') { res.writeHead(204); res.end(); return; }
    if (url.pathname.startsWith('/x_ite/')) file = fileBelow(this.xiteDist, url.pathname.slice('/x_ite'.length));
    else if (url.pathname.startsWith('/scene/')) {
      const p = url.pathname.slice('/scene'.length);
      file = fileBelow(this.sceneDir, p) ?? (fs.existsSync(this.protos) ? fileBelow(this.protos, p) : null);
    }
    if (!file) {
      this.served.push(`404 ${url.pathname}`);
      res.writeHead(404, { 'Content-Type': 'text/plain' });
      res.end('not found');
      return;
    }
    this.served.push(`200 ${url.pathname}`);
    res.writeHead(200, { 'Content-Type': mime[path.extname(file).toLowerCase()] ?? 'application/octet-stream', 'Cache-Control': 'no-store' });
    fs.createReadStream(file).pipe(res);
  }

  // The URL under which the page loads `file`, a file of sceneDir.
  sceneURL(file) {
    return `${this.origin}/scene/${encodeURIComponent(path.basename(file))}`;
  }

  missingFiles() {
    return this.served.filter((s) => s.startsWith('404 ')).map((s) => s.slice(4));
  }

  // Starts Chromium (playwright's `chromium` launcher) and opens the page; after serve().
  async launch(chromium) {
    this.userDataDir = fs.mkdtempSync(path.join(os.tmpdir(), 'render_xite-'));
    this.context = await chromium.launchPersistentContext(this.userDataDir, {
      executablePath: this.chromiumPath,
      headless: true,
      args: [
        '--headless', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
        '--disable-background-networking', '--disable-component-update', '--disable-sync',
        '--no-first-run', '--disable-quic',
      ],
      viewport: { width: this.width, height: this.height },
      deviceScaleFactor: 1,
    });
    const page = this.context.pages()[0] ?? await this.context.newPage();
    page.on('console', (msg) => {
      const text = oneLine(msg.text());
      // EXTERNPROTO URL lists start with URNs (urn:web3d:..., urn:inet:blaxxun.com:...),
      // which a browser cannot fetch: X_ITE logs each failed try (and the bare fetch
      // TypeError) and goes on with the next URL.
      const benign = /\burn:/.test(text) || text.startsWith('TypeError: Failed to fetch');
      if (msg.type() === 'error' && !benign) this.errors.push(text);
      else if (msg.type() === 'warning' && /Parser error|Unknown (node|proto|field)/i.test(text)) this.errors.push(text);
      else if (msg.type() === 'warning') this.warnings.push(text);
    });
    page.on('pageerror', (err) => this.errors.push(oneLine(`page error: ${err.message}`)));
    page.on('crash', () => this.errors.push('page crashed'));
    if (this.initScript) await this.context.addInitScript(this.initScript.script, this.initScript.arg);
    await page.goto(`${this.origin}/`, { waitUntil: 'load' });
    this.page = page;
  }

  async close() {
    try { if (this.context) await this.context.close(); } catch { /* already gone */ }
    this.context = null;
    this.page = null;
    if (this.server) this.server.close();
    this.server = null;
    if (this.userDataDir) fs.rmSync(this.userDataDir, { recursive: true, force: true });
    this.userDataDir = null;
  }
}
