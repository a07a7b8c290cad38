#!/usr/bin/env node
// Renders a VRML97 / X3D file with X_ITE (npm x_ite) in headless Chromium and saves a PNG
// of the canvas only.
//
//   render_xite.mjs IN OUT.png [--width 400] [--height 300] [--timeout SECONDS]
//                   [--protos DIR] [--chromium PATH] [--ignore-errors]
//                   [--background R,G,B] [--time] [--times T1,T2,...] [--next-frame] [--allow-missing NAME,...]
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
// --times T1,T2,... (seconds, increasing) renders the scene at those scene times on a clock that
// stands still unless moved (virtual_clock.mjs: time T is an instant at which every corpus cycle has
// run T seconds), one picture each, OUT.png's name with ".t<i>" before the extension (OUT.t0.png ...);
// the same times give the same pictures, run after run. Between the pictures X_ITE draws no frame the
// script did not ask for (virtual_clock.mjs hold()).
// --next-frame (with --times) also saves, after each picture, the picture one frame later at the same
// time, OUT.t<i>.next.png: in a scene whose ROUTEs form a loop that changes the picture in every frame
// (robot_opengl's ProximitySensor moving its own parent Transform) the two are the loop's two states.
// --allow-missing NAME,... lets a load go on when files of those names (e.g. textures and white_dune's
// scripted PROTOs that a corpus file names but does not ship) are missing: their 404s, X_ITE's "Couldn't
// load URL" for them and its image load warnings are not errors; any other missing file still is.
//
// Exit status 0 with OUT.png written; 1 with a one-line error on stderr when the scene
// fails to load or the page reports an error (X_ITE console errors, X_ITE parser errors,
// which it logs as warnings, and uncaught page errors are collected and printed); 2 on
// bad arguments. Other console warnings are printed to stderr but do not fail the run.
// --ignore-errors still prints the errors but takes the screenshot and exits 0 when the
// page got that far (for looking at files that are known to have problems). Chromium: CHROMIUM env var or --chromium,
// default /usr/bin/chromium.

import fs from 'node:fs';
import path from 'node:path';

import {XiteSession, defaultProtosDir, oneLine, requireXite} from './xite_page.mjs';
import {setClockAndDraw, virtualClockInitScript} from './virtual_clock.mjs';

function usage(msg) {
  if (msg) process.stderr.write(`render_xite: ${msg}\n`);
  process.stderr.write(
      'usage: render_xite.mjs IN OUT.png [--width 400] [--height 300] [--timeout SECONDS] [--protos DIR] [--chromium PATH] [--ignore-errors] [--background R,G,B] [--time] [--times T1,T2,...] [--next-frame] [--allow-missing NAME,...]\n');
  process.exit(2);
}

// ---------------------------------------------------------------- arguments
const opt = {
  width: 400,
  height: 300,
  timeout: 90,
  protos: defaultProtosDir,
  chromium: process.env.CHROMIUM || '/usr/bin/chromium',
  ignoreErrors: false,
  background: null,  // [r, g, b] in 0..1, or null for white
  time: false,
  times: null,  // scene times (s) on the virtual clock, or null for the real clock
  allowMissing: [],
  nextFrame: false,  // with --times: also the picture one frame later at the same time
};
const positional = [];
// "R,G,B" with components in 0..1, or in 0..255 when any exceeds 1.
function parseColour(text) {
  const c = text.split(',').map(Number);
  if (c.length !== 3 || c.some((v) => !Number.isFinite(v) || v < 0 || v > 255))
    usage(`--background needs R,G,B: ${text}`);
  return c.some((v) => v > 1) ? c.map((v) => v / 255) : c;
}
{
  const a = process.argv.slice(2);
  for (let i = 0; i < a.length; ++i) {
    const arg = a[i];
    const value = () => {
      if (a[i + 1] === undefined) usage(`${arg} needs a value`);
      return a[++i];
    };
    const int = () => {
      const v = Number(value());
      if (!Number.isInteger(v) || v <= 0) usage(`${arg} needs a positive integer`);
      return v;
    };
    if (arg === '--width')
      opt.width = int();
    else if (arg === '--height')
      opt.height = int();
    else if (arg === '--timeout')
      opt.timeout = int();
    else if (arg === '--protos')
      opt.protos = path.resolve(value());
    else if (arg === '--chromium')
      opt.chromium = value();
    else if (arg === '--ignore-errors')
      opt.ignoreErrors = true;
    else if (arg === '--time')
      opt.time = true;
    else if (arg === '--next-frame')
      opt.nextFrame = true;
    else if (arg === '--background')
      opt.background = parseColour(value());
    else if (arg === '--times') {
      opt.times = value().split(',').map(Number);
      if (opt.times.some((t, k) => !Number.isFinite(t) || t <= 0 || (k > 0 && t <= opt.times[k - 1])))
        usage(`--times needs increasing positive seconds: ${a[i]}`);
    } else if (arg === '--allow-missing')
      opt.allowMissing = value().split(',').filter(Boolean);
    else if (arg === '-h' || arg === '--help')
      usage();
    else if (arg.startsWith('--'))
      usage(`unknown option ${arg}`);
    else
      positional.push(arg);
  }
}
if (positional.length !== 2) usage('need IN and OUT.png');
if (opt.nextFrame && !opt.times) usage('--next-frame needs --times');
const inFile = path.resolve(positional[0]);
const outFile = path.resolve(positional[1]);
if (!fs.existsSync(inFile) || !fs.statSync(inFile).isFile()) usage(`no such file: ${positional[0]}`);
fs.rmSync(outFile, {force: true});  // never leave an old picture behind a failure

const {xiteDist, chromium} = await requireXite('render_xite');

// ---------------------------------------------------------------- server and page
const pageColour = opt.background ? `rgb(${opt.background.map((v) => Math.round(v * 255)).join(',')})` : '#ffffff';
const session = new XiteSession({
  xiteDist,
  sceneDir: path.dirname(inFile),
  protos: opt.protos,
  chromium: opt.chromium,
  width: opt.width,
  height: opt.height,
  colour: pageColour,
  initScript: opt.times ? virtualClockInitScript : null,
});
await session.serve();

// ---------------------------------------------------------------- browser
const errors = session.errors;
const warnings = session.warnings;
let exitCode = 0;

const deadline = setTimeout(() => {
  process.stderr.write(`render_xite: ${positional[0]}: timed out after ${opt.timeout} s${
      errors.length ? ': ' + errors.join(' | ') : ''}\n`);
  session.close().finally(() => process.exit(1));
}, opt.timeout * 1000);

try {
  await session.launch(chromium);
  const page = session.page;
  const sceneURL = session.sceneURL(inFile);
  const loaded = await page.evaluate(async ({url, sky, virtualClock}) => {
    const canvas = document.getElementById('canvas');
    const X3D = window.X3D;
    if (!X3D) return {ok: false, error: 'X_ITE did not load'};
    const browser = X3D.getBrowser(canvas);
    // Show the file's Viewpoint exactly: X_ITE's default "straighten horizon" would roll
    // a Viewpoint whose up direction is not +Y.
    browser.setBrowserOption('StraightenHorizon', false);
    if (virtualClock) window.cadnurbsClock.attach(browser);
    const start = performance.now();
    try {
      await browser.loadURL(new X3D.MFString(url));
      if (virtualClock) window.cadnurbsClock.hold();
    } catch (e) {
      return {ok: false, error: `X_ITE failed to load the scene: ${e?.message ?? e}`};
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
    } catch { /* keep X_ITE's default */
    }
    // On the virtual clock no frame is drawn until the clock moves (setClockAndDraw below).
    if (virtualClock) return {ok: true, rootNodes: browser.currentScene?.rootNodes.length ?? 0, loadSeconds};
    // Let scripts, EXTERNPROTO instances and geometry settle: a few rendered frames.
    await browser.nextFrame();
    const firstFrameSeconds = (performance.now() - start) / 1000;
    for (let i = 0; i < 3; ++i) await browser.nextFrame();
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const scene = browser.currentScene;
    return {
      ok: true,
      rootNodes: scene ? scene.rootNodes.length : 0,
      defaultBackgroundSet,
      loadSeconds,
      firstFrameSeconds
    };
  }, {url: sceneURL, sky: opt.background ?? [1, 1, 1], virtualClock: opt.times !== null});
  if (loaded.ok && opt.time)
    process.stdout.write(
        `render_xite: time load ${loaded.loadSeconds.toFixed(3)} first-frame ${loaded.firstFrameSeconds.toFixed(3)}\n`);

  if (!loaded.ok) errors.unshift(loaded.error);
  dropAllowedMissing();
  if (errors.length === 0 || (opt.ignoreErrors && loaded.ok)) {
    if (loaded.rootNodes === 0)
      errors.push('scene has no root nodes');
    else if (opt.times) {
      for (const [k, t] of opt.times.entries()) {
        await setClockAndDraw(page, t);
        await screenshot(page, timedName(outFile, k));
        if (opt.nextFrame) {
          await setClockAndDraw(page, t, 1);
          await screenshot(page, timedName(outFile, k, '.next'));
        }
      }
    } else
      await screenshot(page, outFile);
  }
} catch (e) {
  errors.push(oneLine(e?.message ?? e));
}

dropAllowedMissing();
clearTimeout(deadline);
await session.close();
for (const w of warnings.slice(0, 20)) process.stderr.write(`render_xite: warning: ${w}\n`);
if (errors.length) {
  const missing = session.missingFiles();
  if (missing.length) errors.push(`not found on the test server: ${missing.join(', ')}`);
  process.stderr.write(`render_xite: ${positional[0]}: ${errors.join(' | ')}\n`);
  exitCode = opt.ignoreErrors && fs.existsSync(outFile) ? 0 : 1;
}
process.exit(exitCode);

async function screenshot(page, file) {
  fs.mkdirSync(path.dirname(file), {recursive: true});
  const tmp = `${file}.tmp`;
  await page.locator('#canvas').screenshot({path: tmp, type: 'png', animations: 'disabled'});
  fs.renameSync(tmp, file);
}

// OUT.png -> OUT.t<k><suffix>.png
function timedName(file, k, suffix = '') {
  const ext = path.extname(file);
  return `${file.slice(0, file.length - ext.length)}.t${k}${suffix}${ext}`;
}

// With --allow-missing: when every file the server could not find is one of the allowed names, the
// messages about them (the browser's 404s, X_ITE's failed EXTERNPROTO URLs and image loads, which
// name them or not) are not errors.
function dropAllowedMissing() {
  if (opt.allowMissing.length === 0) return;
  const allowed = (name) => opt.allowMissing.includes(path.posix.basename(name));
  if (!session.missingFiles().every(allowed)) return;
  const namesAllowed = (text) => opt.allowMissing.some((name) => text.includes(name));
  // (the http:// URLs such files are also listed under cannot resolve in the sandbox)
  const generic =
      /^Failed to load resource: (the server responded with a status of 404|net::ERR_NAME_NOT_RESOLVED)|^Error: Not Found at /;
  const keep = errors.filter((e) => !generic.test(e) && !namesAllowed(e));
  errors.splice(0, errors.length, ...keep);
  const keepWarnings = warnings.filter((w) => !(/^Error loading image/.test(w) && namesAllowed(w)));
  warnings.splice(0, warnings.length, ...keepWarnings);
}
