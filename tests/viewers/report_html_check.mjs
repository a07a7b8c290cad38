#!/usr/bin/env node
// Opens a cadnurbs HTML report (report/html/report_html.hpp) from its file in headless Chromium and
// checks that it works offline and draws what it should:
//
//   report_html_check.mjs PAGE.html [--out DIR] [--bars N] [--curves N] [--views N]
//                         [--min-chart F] [--min-view F] [--timeout SECONDS] [--chromium PATH]
//
//  - no console error, no page error, no X_ITE parser warning, and no request but the page itself
//    (everything is inlined; any fetch fails the check);
//  - the page's charts report ready; every 3D view (scrolled into view, since the page makes views
//    lazily) reaches data-state "ready";
//  - a screenshot of every view's <x3d-canvas> has at least F (--min-view, default 0.02) of its pixels
//    away from its background (the most frequent colour of the screenshot's one-pixel border) by more
//    than 40 in some channel; a chart's canvas at least F (--min-chart, default 0.01) such pixels that are
//    also coloured (channels 40 apart): the data are drawn in colour, axes and text in grey. Measured on
//    make_report_page's page (tests/report_html): bars 14.7 %, curve 2.2 %, NURBS view 13.8 %, mesh view
//    14.1 %; on altered copies of such a page: a bar chart without bars 0 %, a curve chart whose lines
//    cannot be drawn 0.4 % (its legend), a view of a scene X_ITE could not read 0 % (and its parser
//    warning fails the check too);
//  - with --bars/--curves/--views, exactly that many bar charts, curve charts and view areas.
// Prints one JSON line per area ({"area", "pixels", "foreground", "fraction"}), writes the screenshots to
// DIR (default: beside the page, in report_html_check/). Exit status 0 when every check passes, 1 with
// one line per failure on stderr, 2 on bad arguments.
// Chromium: CHROMIUM env var or --chromium, default /usr/bin/chromium (SwiftShader WebGL, as render_xite.mjs).

import fs from 'node:fs';
import path from 'node:path';
import { pathToFileURL } from 'node:url';
import { PNG } from 'pngjs';

function usage(msg) {
  if (msg) process.stderr.write(`report_html_check: ${msg}\n`);
  process.stderr.write('usage: report_html_check.mjs PAGE.html [--out DIR] [--bars N] [--curves N] [--views N] [--min-chart F] [--min-view F] [--timeout SECONDS] [--chromium PATH]\n');
  process.exit(2);
}

const opt = { out: null, bars: null, curves: null, views: null, minChart: 0.01, minView: 0.02, timeout: 200,
  chromium: process.env.CHROMIUM || '/usr/bin/chromium' };
const positional = [];
{
  const a = process.argv.slice(2);
  for (let i = 0; i < a.length; ++i) {
    const arg = a[i];
    const value = () => { if (a[i + 1] === undefined) usage(`${arg} needs a value`); return a[++i]; };
    const num = () => { const v = Number(value()); if (!Number.isFinite(v) || v < 0) usage(`${arg} needs a number`); return v; };
    if (arg === '--out') opt.out = path.resolve(value());
    else if (arg === '--bars') opt.bars = num();
    else if (arg === '--curves') opt.curves = num();
    else if (arg === '--views') opt.views = num();
    else if (arg === '--min-chart') opt.minChart = num();
    else if (arg === '--min-view') opt.minView = num();
    else if (arg === '--timeout') opt.timeout = num();
    else if (arg === '--chromium') opt.chromium = value();
    else if (arg.startsWith('--')) usage(`unknown option ${arg}`);
    else positional.push(arg);
  }
}
if (positional.length !== 1) usage('need PAGE.html');
const pageFile = path.resolve(positional[0]);
if (!fs.existsSync(pageFile)) usage(`no such file: ${positional[0]}`);
const outDir = opt.out ?? path.join(path.dirname(pageFile), 'report_html_check');
fs.mkdirSync(outDir, { recursive: true });

let chromium;
try {
  ({ chromium } = await import('playwright-core'));
} catch {
  process.stderr.write(`report_html_check: playwright-core not installed: run npm ci in ${path.dirname(new URL(import.meta.url).pathname)}\n`);
  process.exit(2);
}

// Pixels that differ from the most frequent colour of the border by more than `tolerance` in some
// channel; with `coloured`, only those whose channels also differ among themselves by more than that
// (the charts draw their data in colour, their axes, grid and text in grey).
function foreground(buffer, coloured, tolerance = 40) {
  const png = PNG.sync.read(buffer);
  const { width, height, data } = png;
  const counts = new Map();
  const key = (i) => (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
  for (let x = 0; x < width; ++x)
    for (const y of [0, height - 1]) { const k = key(4 * (y * width + x)); counts.set(k, (counts.get(k) ?? 0) + 1); }
  for (let y = 0; y < height; ++y)
    for (const x of [0, width - 1]) { const k = key(4 * (y * width + x)); counts.set(k, (counts.get(k) ?? 0) + 1); }
  const background = [...counts].sort((a, b) => b[1] - a[1])[0][0];
  const bg = [(background >> 16) & 255, (background >> 8) & 255, background & 255];
  let n = 0;
  for (let i = 0; i < data.length; i += 4) {
    const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
    const differs = Math.abs(r - bg[0]) > tolerance || Math.abs(g - bg[1]) > tolerance || Math.abs(b - bg[2]) > tolerance;
    if (differs && (!coloured || Math.max(r, g, b) - Math.min(r, g, b) > tolerance)) ++n;
  }
  return { pixels: width * height, foreground: n, background: bg };
}

const oneLine = (s) => String(s).replace(/\s+/g, ' ').trim().slice(0, 400);
const failures = [];
const pageURL = pathToFileURL(pageFile).href;
let browser = null;
const deadline = setTimeout(() => {
  process.stderr.write(`report_html_check: ${positional[0]}: timed out after ${opt.timeout} s${failures.length ? ': ' + failures.join(' | ') : ''}\n`);
  (browser ? browser.close() : Promise.resolve()).finally(() => process.exit(1));
}, opt.timeout * 1000);

try {
  // SwiftShader: WebGL without a GPU; no background traffic of Chromium's own to mistake for the page's.
  browser = await chromium.launch({ executablePath: opt.chromium, headless: true,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--disable-background-networking',
      '--disable-component-update', '--no-first-run'] });
  const page = await browser.newPage({ viewport: { width: 1200, height: 900 }, deviceScaleFactor: 1 });
  page.on('console', (msg) => {
    const text = oneLine(msg.text());
    if (msg.type() === 'error') failures.push(`console error: ${text}`);
    else if (msg.type() === 'warning' && /Parser error|Unknown (node|proto|field)/i.test(text)) failures.push(`X_ITE: ${text}`);
  });
  page.on('pageerror', (err) => failures.push(oneLine(`page error: ${err.message}`)));
  page.on('crash', () => failures.push('page crashed'));
  page.on('request', (request) => {
    const url = request.url();
    if (url !== pageURL && !url.startsWith('data:')) failures.push(`the page fetched ${url.slice(0, 200)}`);
  });

  await page.goto(pageURL, { waitUntil: 'load' });
  await page.waitForFunction(() => document.documentElement.dataset.charts === 'ready', null, { timeout: opt.timeout * 1000 });

  const counted = await page.evaluate(() => ({
    bars: document.querySelectorAll('canvas.bars').length,
    curves: document.querySelectorAll('canvas.curve').length,
    views: document.querySelectorAll('.view-box').length,
  }));
  for (const what of ['bars', 'curves', 'views'])
    if (opt[what] !== null && counted[what] !== opt[what]) failures.push(`${counted[what]} ${what} areas, expected ${opt[what]}`);

  const measure = async (locator, name, minimum, coloured) => {
    const file = path.join(outDir, `${name}.png`);
    const buffer = await locator.screenshot({ path: file, animations: 'disabled' });
    const m = foreground(buffer, coloured);
    const fraction = m.foreground / m.pixels;
    process.stdout.write(JSON.stringify({ area: name, pixels: m.pixels, foreground: m.foreground, fraction: Number(fraction.toFixed(4)), background: m.background }) + '\n');
    if (fraction < minimum) failures.push(`${name}: ${(100 * fraction).toFixed(2)} % of its pixels drawn, expected at least ${(100 * minimum).toFixed(2)} %`);
  };

  const charts = page.locator('canvas.bars, canvas.curve');
  for (let i = 0; i < await charts.count(); ++i) {
    const canvas = charts.nth(i);
    const name = `${await canvas.getAttribute('class')}-${await canvas.getAttribute('data-part')}`;
    await measure(canvas, name, opt.minChart, true);
  }

  const boxes = page.locator('.view-box');
  for (let i = 0; i < await boxes.count(); ++i) {
    const box = boxes.nth(i);
    const name = `view-${await box.getAttribute('data-view')}-${await box.getAttribute('data-part')}`;
    await box.scrollIntoViewIfNeeded();
    const handle = await box.elementHandle();
    await page.waitForFunction((b) => ['ready', 'failed'].includes(b.dataset.state), handle, { timeout: opt.timeout * 1000 });
    const state = await box.getAttribute('data-state');
    if (state !== 'ready') { failures.push(`${name}: ${state}: ${oneLine(await box.textContent())}`); continue; }
    // A few frames after the first one, as render_xite.mjs waits.
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => requestAnimationFrame(r)))));
    await measure(box.locator('x3d-canvas'), name, opt.minView, false);
  }
} catch (e) {
  failures.push(oneLine(e?.message ?? e));
}

clearTimeout(deadline);
try { if (browser) await browser.close(); } catch { /* already gone */ }
if (failures.length) {
  for (const f of failures) process.stderr.write(`report_html_check: ${positional[0]}: ${f}\n`);
  process.exit(1);
}
process.stdout.write(`report_html_check: ${positional[0]}: ok\n`);
