// A page of the cadnurbs viewer in headless Chromium, from a file:// URL (issue 40): it must draw the part
// and refine it to below one pixel with no console error, no page error and no request off the page
// (only file:, data: and blob: URLs).
//
//   node viewer_page_check.mjs [--width 1600] [--height 1200] [--timeout 60] [--screenshots DIR] PAGE...
//
// Prints a line per page: triangles, the final deviation, when the first frame and the sub-pixel mesh
// came (milliseconds after the viewer started), and the longest gap between frames while refining; exit 1
// when a page fails. Chromium: CHROMIUM, default /usr/bin/chromium; playwright-core from tests/viewers.
import { mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { basename, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const require = createRequire(join(import.meta.dirname ?? new URL('.', import.meta.url).pathname, '../viewers/package.json'));
const { chromium } = require('playwright-core');

const options = { width: 1600, height: 1200, timeout: 60, screenshots: '' };
const pages = [];
for (let a = process.argv.slice(2), i = 0; i < a.length; ++i) {
  if (a[i].startsWith('--')) options[a[i].slice(2)] = a[++i];
  else pages.push(a[i]);
}
if (!pages.length) {
  console.error('usage: node viewer_page_check.mjs [--width W] [--height H] [--timeout S] [--screenshots DIR] PAGE...');
  process.exit(2);
}
if (options.screenshots) mkdirSync(options.screenshots, { recursive: true });

const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--no-first-run'],
});
let failures = 0;
for (const page of pages) {
  const name = basename(page);
  const context = await browser.newContext({ viewport: { width: Number(options.width), height: Number(options.height) },
                                             deviceScaleFactor: 1 });
  const tab = await context.newPage();
  const problems = [];
  tab.on('console', (m) => { if (m.type() === 'error') problems.push(`console error: ${m.text()}`); });
  tab.on('pageerror', (e) => problems.push(`page error: ${e.message}`));
  context.on('request', (r) => { if (!/^(file|data|blob):/.test(r.url())) problems.push(`request: ${r.url()}`); });
  let state = null;
  try {
    await tab.goto(pathToFileURL(resolve(page)).href);
    await tab.waitForFunction(() => window.cadnurbsViewer && (window.cadnurbsViewer.error || window.cadnurbsViewer.subPixelMs !== null),
                              null, { timeout: Number(options.timeout) * 1000 });
    state = await tab.evaluate(() => JSON.parse(JSON.stringify(window.cadnurbsViewer)));
    if (state.error) problems.push(`viewer: ${state.error}`);
    if (!(state.triangles > 0)) problems.push('no triangles drawn');
    if (options.screenshots) await tab.screenshot({ path: join(options.screenshots, `${name}.png`) });
  } catch (e) {
    problems.push(e.message.split('\n')[0]);
  }
  await context.close();
  if (problems.length) ++failures;
  const figures = state ? `triangles ${state.triangles}\tdeviation ${state.deviation}\tworker ${Math.round(state.workerMs)} ms\tread ${Math.round(state.openedMs)} ms (module ${Math.round(state.moduleMs)}, ` +
                          `part ${Math.round(state.readMs)})\t` +
                          `WebGL at ${Math.round(state.webglMs)} ms\tfirst frame ${Math.round(state.firstFrameMs)} ms\t` +
                          `sub-pixel ${Math.round(state.subPixelMs)} ms\tlongest frame gap ${Math.round(state.longestFrameGap)} ms\t` +
                          `meshes ${state.meshes.length}` : '';
  console.log(`${name}\t${problems.length ? 'FAIL' : 'ok'}\t${figures}${problems.length ? '\t' + problems.join('; ') : ''}`);
}
await browser.close();
console.log(`${pages.length - failures} of ${pages.length} pages drawn below one pixel`);
process.exit(failures ? 1 : 0);
