// Two sites' part pages (`batch --site`, two builds of the viewer) side by side in headless Chromium: the
// same pages, A then B, then B then A in the next round, each in a fresh browser context (nothing cached),
// the two sites served over HTTP by this process. Prints a line per load and, per site, the medians and
// the largest of: the first contentful paint (the browser's), the first frame with the part (a picture's
// paint as the browser reports it, or the viewer's own record), WebGL's first frame, the sub-pixel mesh
// drawn, and the longest gap between the page's and the renderer's frames while refining (ms since the
// page's navigation started). A viewer from before a figure existed reports null for it.
//
//   node bench/viewer_pages_ab.mjs SITE_A SITE_B ROUNDS PAGE...      (PAGE: a path under both sites)
//   node bench/viewer_pages_ab.mjs --picture-alone SITE ROUNDS PAGE...
//
// --picture-alone holds the site's pages against the same pages without their scripts (B): the picture
// alone, what the browser does without the viewer. For those, the first frame is the picture's paint and
// the longest gap is between the page's frames in the 1.5 s after it.
//
// Chromium: CHROMIUM, default /usr/bin/chromium; playwright-core from tests/viewers.
import { createServer } from 'node:http';
import { existsSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { extname, join, normalize, resolve, sep } from 'node:path';

const here = import.meta.dirname ?? new URL('.', import.meta.url).pathname;
const { chromium } = createRequire(join(here, '../tests/viewers/package.json'))('playwright-core');
const pictureAlone = process.argv[2] === '--picture-alone';
const [siteA, siteB, rounds, ...pages] = pictureAlone ? [process.argv[3], process.argv[3], ...process.argv.slice(4)] : process.argv.slice(2);
if (!siteB || !(Number(rounds) > 0) || !pages.length) {
  console.error('usage: node bench/viewer_pages_ab.mjs SITE_A SITE_B ROUNDS PAGE...\n' +
                '       node bench/viewer_pages_ab.mjs --picture-alone SITE ROUNDS PAGE...');
  process.exit(2);
}
const types = { '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.png': 'image/png' };

// `withoutScripts`: pages served with their script elements taken out.
async function serve(folder, withoutScripts = false) {
  const root = resolve(folder);
  const server = createServer((request, response) => {
    const path = normalize(join(root, decodeURIComponent(new URL(request.url, 'http://x').pathname)));
    if (!(path + sep).startsWith(root + sep) || !existsSync(path)) return response.writeHead(404).end();
    let body = readFileSync(path);
    if (withoutScripts && extname(path) === '.html') body = body.toString().replace(/<script\b[^>]*>[\s\S]*?<\/script>/g, '');
    response.writeHead(200, { 'Content-Type': types[extname(path)] || 'application/octet-stream' }).end(body);
  });
  await new Promise((ready) => server.listen(0, '127.0.0.1', ready));
  return { server, origin: `http://127.0.0.1:${server.address().port}` };
}

const sites = { A: await serve(siteA), B: await serve(siteB, pictureAlone) };
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || '/usr/bin/chromium', headless: true,
  args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking',
         '--disable-component-update', '--disable-sync', '--no-first-run'],
});

// The picture alone: its paint (Element Timing) and the longest gap between the page's frames after it.
async function pictureFigures(tab) {
  const painted = await tab.evaluate(() => new Promise((resolve) => new PerformanceObserver((list) => resolve(list.getEntries()[0].renderTime))
    .observe({ type: 'element', buffered: true })));
  await tab.waitForTimeout(1500);
  const frames = await tab.evaluate(() => window.frameTimes);
  let gap = 0;
  for (let i = 1; i < frames.length; ++i) if (frames[i - 1] >= painted && frames[i] <= painted + 1500) gap = Math.max(gap, frames[i] - frames[i - 1]);
  return { contentfulPaint: painted, firstFrame: painted, webglFrame: null, subPixel: null, pageGap: gap, rendererGap: null, meshes: 0, error: '' };
}

async function load(origin, page, alone) {
  const context = await browser.newContext({ viewport: { width: 1600, height: 1200 }, deviceScaleFactor: 1 });
  const tab = await context.newPage();
  const errors = [];
  tab.on('pageerror', (e) => errors.push(e.message));
  await tab.addInitScript(() => {
    // The viewer's record; before 2026-12 it was window.cadnurbsViewer, now the name of the viewer's script.
    window.viewerRecord = () => window.cadnurbsViewerState ?? (window.cadnurbsViewer?.started !== undefined ? window.cadnurbsViewer : null);
    window.frameTimes = [];
    const frame = (time) => { window.frameTimes.push(time); requestAnimationFrame(frame); };
    requestAnimationFrame(frame);
  });
  await tab.goto(`${origin}/${page.split('/').map(encodeURIComponent).join('/')}`);
  if (alone) {
    const figures = await pictureFigures(tab);
    await context.close();
    return figures;
  }
  await tab.waitForFunction(() => window.viewerRecord()?.error || window.viewerRecord()?.subPixelMs > 0, null, { timeout: 60000 });
  const figures = await tab.evaluate(() => {
    const s = window.viewerRecord();
    // Viewers before this script's time counted from their own start, not the navigation's.
    const base = s.viewerStartedMs === undefined ? s.started : 0;
    const at = (value) => (value === null || value === undefined ? null : value + base);
    const paint = performance.getEntriesByType('paint').find((entry) => entry.name === 'first-contentful-paint');
    return { contentfulPaint: paint ? paint.startTime : null, firstFrame: at(s.firstFrameMs), webglFrame: at(s.firstWebGLFrameMs),
             subPixel: at(s.subPixelMs), pageGap: s.longestFrameGap, rendererGap: s.longestRenderGap ?? null, meshes: s.meshes.length,
             error: s.error };
  });
  await context.close();
  if (errors.length) figures.error += errors.join('; ');
  return figures;
}

const keys = ['contentfulPaint', 'firstFrame', 'webglFrame', 'subPixel', 'pageGap', 'rendererGap'];
const loads = { A: [], B: [] };
await load(sites.A.origin, pages[0]);  // the browser's own start, counted for neither
for (let round = 0; round < Number(rounds); ++round)
  for (const page of pages)
    for (const label of round % 2 ? ['B', 'A'] : ['A', 'B']) {
      const figures = await load(sites[label].origin, page, pictureAlone && label === 'B');
      loads[label].push(figures);
      console.log(`${label}\t${page}\t${keys.map((k) => `${k} ${figures[k] === null ? '-' : Math.round(figures[k])}`).join('\t')}` +
                  `\tmeshes ${figures.meshes}${figures.error ? '\terror ' + figures.error : ''}`);
    }
const median = (values) => values[Math.floor(values.length / 2)];
for (const label of ['A', 'B']) {
  const summary = keys.map((k) => {
    const values = loads[label].map((f) => f[k]).filter((v) => v !== null).sort((a, b) => a - b);
    return values.length ? `${k} ${Math.round(median(values))} (max ${Math.round(values[values.length - 1])})` : `${k} -`;
  });
  console.log(`${label} medians over ${loads[label].length} loads: ${summary.join(', ')}`);
}
await browser.close();
for (const { server } of Object.values(sites)) server.close();
const failed = [...loads.A, ...loads.B].filter((f) => f.error).length;
process.exit(failed ? 1 : 0);
