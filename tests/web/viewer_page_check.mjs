// A page of the cadnurbs viewer in headless Chromium, from a file:// URL (issue 40): it must draw the part
// and refine it to below one pixel with no console error, no page error and no request off the page
// (only file:, data: and blob: URLs).
//
//   node viewer_page_check.mjs [--width 1600] [--height 1200] [--timeout 60] [--screenshots DIR] PAGE...
//   node viewer_page_check.mjs --site DIR [--sample N] [options as above] [PAGE...]
//   node viewer_page_check.mjs --native TOOL --cnb DIR [options as above] PAGE...
//
// With --site, DIR (what `batch --site` wrote) is served over HTTP on 127.0.0.1 and PAGEs are paths under
// it; --sample N adds N part pages spread evenly over the site's index. Requests may go to that server only,
// and none may fail; every link and picture of index.html must name a file of the site.
//
// With --native, each page NAME.html's part DIR/NAME.cnb is also meshed by native code (TOOL,
// native_scene_arrays) at the deviation the viewer ended at, and at an eighth of it (near the exact part);
// in the viewer's final view both silhouettes, drawn without antialiasing, must lie within one pixel (in x
// and y) of the viewer's own, pixel for pixel both ways.
//
// Prints a line per page: triangles, the final deviation, when the first frame showed the part (a site
// page's picture, as the browser reports its paint, or the sketch of the first mesh) and when WebGL drew
// its first frame and the sub-pixel mesh (milliseconds since the page's navigation started), the longest
// gap between the page's frames and between the renderer's (its worker's) while refining; exit 1 when a
// page fails. Chromium: CHROMIUM, default /usr/bin/chromium; playwright-core from tests/viewers.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createServer } from 'node:http';
import { createRequire } from 'node:module';
import { basename, extname, join, normalize, resolve, sep } from 'node:path';
import { tmpdir } from 'node:os';
import { pathToFileURL } from 'node:url';

import { readNativeArrays } from './native_arrays.mjs';

const require = createRequire(join(import.meta.dirname ?? new URL('.', import.meta.url).pathname, '../viewers/package.json'));
const { chromium } = require('playwright-core');

const options = { width: 1600, height: 1200, timeout: 60, screenshots: '', site: '', sample: 0, native: '', cnb: '' };
const pages = [];
for (let a = process.argv.slice(2), i = 0; i < a.length; ++i) {
  if (a[i].startsWith('--')) options[a[i].slice(2)] = a[++i];
  else pages.push(a[i]);
}
let origin = '', server = null, failures = 0;
const siteProblems = [];
if (options.site) {
  const root = resolve(options.site);
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.png': 'image/png',
                  '.txt': 'text/plain', '.cnb': 'application/octet-stream' };
  server = createServer((request, response) => {
    const path = normalize(join(root, decodeURIComponent(new URL(request.url, 'http://x').pathname)));
    if (!(path + sep).startsWith(root + sep) || !existsSync(path)) {
      siteProblems.push(`not found: ${request.url}`);
      response.writeHead(404).end();
      return;
    }
    response.writeHead(200, { 'Content-Type': types[extname(path)] || 'application/octet-stream' }).end(readFileSync(path));
  });
  await new Promise((ready) => server.listen(0, '127.0.0.1', ready));
  origin = `http://127.0.0.1:${server.address().port}`;
  // The index's links and pictures, each a file of the site; the part pages among them for --sample.
  const index = readFileSync(join(root, 'index.html'), 'utf8');
  const named = [...index.matchAll(/(?:href|src)="([^"]+)"/g)].map((m) => m[1].replaceAll('&amp;', '&'))
    .filter((url) => !url.startsWith('data:')).map(decodeURIComponent);
  for (const file of named)
    if (!existsSync(join(root, file))) siteProblems.push(`index.html names ${file}, which is not in the site`);
  const partPages = [...new Set(named.filter((f) => f.endsWith('.html')))];
  const sample = Math.min(Number(options.sample), partPages.length);
  for (let k = 0; k < sample; ++k) pages.push(partPages[Math.floor((k + 0.5) * partPages.length / sample)]);
  console.log(`site: ${partPages.length} part pages in index.html, ${named.length} links and pictures checked`);
}
if (!pages.length) {
  console.error('usage: node viewer_page_check.mjs [--width W] [--height H] [--timeout S] [--screenshots DIR] PAGE...\n' +
                '       node viewer_page_check.mjs --site DIR [--sample N] [...] [PAGE...]');
  process.exit(2);
}
if (options.screenshots) mkdirSync(options.screenshots, { recursive: true });

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--no-first-run'],
});
const slowest = { firstFrameMs: 0, firstWebGLFrameMs: 0, subPixelMs: 0, longestFrameGap: 0, longestRenderGap: 0 };
const scratch = options.native ? mkdtempSync(join(tmpdir(), 'cadnurbs-silhouettes-')) : '';

// The page's part meshed natively at the viewer's final deviation and at an eighth of it, each silhouette
// held against the viewer's; a line of figures per mesh, problems added to `problems`.
async function compareSilhouettes(tab, name, state, problems) {
  const lines = [];
  const cnb = join(options.cnb, name.replace(/\.html$/, '.cnb'));
  for (const [label, divisor] of [['at its deviation', 1], ['at an eighth of it', 8]]) {
    const dump = join(scratch, `${name}.${divisor}.native`);
    execFileSync(options.native, [cnb, String(state.deviation / divisor / state.diagonal), dump], { stdio: ['ignore', 'ignore', 'pipe'] });
    const native = readNativeArrays(dump);
    const positions = Buffer.from(Float32Array.from(native.positions).buffer).toString('base64');
    const indices = Buffer.from(native.indices.buffer).toString('base64');
    const r = await tab.evaluate(({ positions, indices }) => {
      const bytes = (text) => Uint8Array.from(atob(text), (c) => c.charCodeAt(0)).buffer;
      return window.cadnurbsViewerState.compareSilhouettes(new Float32Array(bytes(positions)), new Uint32Array(bytes(indices)));
    }, { positions, indices });
    const line = `${name}\tsilhouette ${label} (${native.indices.length / 3} triangles): viewer ${r.viewerPixels} px, ` +
                 `native ${r.otherPixels} px, beyond one pixel ${r.viewerBeyond} and ${r.otherBeyond}`;
    if (!(r.viewerPixels > 0) || r.viewerBeyond || r.otherBeyond) problems.push(`silhouettes ${label} differ: ${line}`);
    lines.push(line);
  }
  return lines;
}
const silhouettes = [];
for (const page of pages) {
  const name = basename(page);
  const context = await browser.newContext({ viewport: { width: Number(options.width), height: Number(options.height) },
                                             deviceScaleFactor: 1 });
  const tab = await context.newPage();
  const problems = [];
  tab.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  tab.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  const allowed = origin ? (url) => url.startsWith(origin + '/') || /^(data|blob):/.test(url) : (url) => /^(file|data|blob):/.test(url);
  context.on('request', (r) => { if (!allowed(r.url())) problems.push(`request: ${r.url()}`); });
  context.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  let state = null;
  try {
    const before = siteProblems.length;
    await tab.goto(origin ? `${origin}/${page.split('/').map(encodeURIComponent).join('/')}` : pathToFileURL(resolve(page)).href);
    await tab.waitForFunction(() => window.cadnurbsViewerState && (window.cadnurbsViewerState.error || window.cadnurbsViewerState.subPixelMs !== null),
                              null, { timeout: Number(options.timeout) * 1000 });
    state = await tab.evaluate(() => JSON.parse(JSON.stringify(window.cadnurbsViewerState)));
    if (state.error) problems.push(`viewer: ${state.error}`);
    if (!(state.triangles > 0)) problems.push('no triangles drawn');
    problems.push(...siteProblems.slice(before));
    for (const key of Object.keys(slowest)) slowest[key] = Math.max(slowest[key], state[key]);
    if (options.native && !state.error) silhouettes.push(...await compareSilhouettes(tab, name, state, problems));
    if (options.screenshots) await tab.screenshot({ path: join(options.screenshots, `${name}.png`) });
  } catch (e) {
    problems.push(e.message.split('\n')[0]);
  }
  await context.close();
  if (problems.length) ++failures;
  const ms = (value) => (value === null || value === undefined ? '-' : `${Math.round(value)} ms`);
  const figures = state ? `triangles ${state.triangles}\tdeviation ${state.deviation}\tread ${ms(state.openedMs)} (module ${ms(state.moduleMs)}, ` +
                          `part ${ms(state.readMs)})\tpicture ${ms(state.pictureMs)}\tsketch ${ms(state.sketchMs)}\t` +
                          `first frame ${ms(state.firstFrameMs)}\tWebGL started ${ms(state.webglMs)}, first frame ${ms(state.firstWebGLFrameMs)}\t` +
                          `sub-pixel ${ms(state.subPixelMs)}\tlongest frame gap ${ms(state.longestFrameGap)}\t` +
                          `renderer's ${ms(state.longestRenderGap)}\tlongest draw ${ms(state.longestDrawMs)}\t` +
                          `meshes ${state.meshes.length}` : '';
  console.log(`${name}\t${problems.length ? 'FAIL' : 'ok'}\t${figures}${problems.length ? '\t' + problems.join('; ') : ''}`);
}
await browser.close();
if (server) server.close();
for (const line of silhouettes) console.log(line);
if (scratch) rmSync(scratch, { recursive: true, force: true });
for (const problem of siteProblems.filter((p) => !p.startsWith('not found'))) console.log(`site\tFAIL\t${problem}`);
const siteFailed = siteProblems.some((p) => !p.startsWith('not found'));
console.log(`${pages.length - failures} of ${pages.length} pages drawn below one pixel; slowest: first frame ` +
            `${Math.round(slowest.firstFrameMs)} ms, WebGL's first ${Math.round(slowest.firstWebGLFrameMs)} ms, sub-pixel ` +
            `${Math.round(slowest.subPixelMs)} ms, longest frame gap ${Math.round(slowest.longestFrameGap)} ms (the renderer's ` +
            `${Math.round(slowest.longestRenderGap)} ms)`);
process.exit(failures || siteFailed ? 1 : 0);
