#!/usr/bin/env node
// The fit-path check in a real viewer: a Transform driven by the NurbsPositionInterpolator that
// `cadnurbs fit-path` wrote is where the one driven by the original PositionInterpolator is, within
// D, at sampled fractions, as X_ITE (npm x_ite, headless Chromium) computes both.
//
//   check_path_xite.mjs ORIGINAL FITTED --deviation D [--interpolator PATH] [--transform Ball]
//                       [--samples 20] [--timeout SECONDS] [--protos DIR] [--chromium PATH]
//
// Both files are loaded in turn in one X_ITE page (xite_page.mjs: each file's folder is served, and
// formats/vrml/protos for the PROTO library a VRML97 EXTERNPROTO names). In each, the node DEF'd
// --interpolator (default PATH) must route its value_changed to the translation of the Transform
// DEF'd --transform (default Ball); the check drives the interpolator itself through X_ITE's
// scripting interface (Browser.currentScene.getNamedNode), so nothing else may drive it (a
// running TimeSensor would: the check then fails, see below). ORIGINAL's interpolator must have a
// `key` field and FITTED's must be a NurbsPositionInterpolator (native X3D node or PROTO instance).
//
// Fractions: 0, 1, and for i = 1 .. samples-2 the midpoint of ORIGINAL's key interval holding
// i / (samples - 1): between keys, where a linear path and a curve part most. For each fraction:
// the Transform's translation is set to a sentinel and read back one frame later (it must still
// be the sentinel: nothing else moves the Transform), then set_fraction is sent; the translation is
// read after every frame until it changes (the event cascade has run: set_fraction, the
// interpolator's or its Script's value_changed, the ROUTE), then once more a frame later, where it
// must not have changed again.
//
// Prints one line per fraction (both translations and their distance), then
//   "check_path_xite: PASS: max distance M at fraction F <= D"  (exit status 0), or
//   "check_path_xite: FAIL: max distance M at fraction F exceeds D"  (exit status 1).
// Exit status 1 with a one-line error on stderr when a file fails to load, the page logs an error
// (as render_xite.mjs counts them), a node is missing or of the wrong kind, or the Transform never
// moves; 2 on bad arguments. Chromium: CHROMIUM env var or --chromium, default /usr/bin/chromium.

import fs from 'node:fs';
import path from 'node:path';

import { XiteSession, defaultProtosDir, oneLine, requireXite } from './xite_page.mjs';

const usageLine = 'usage: check_path_xite.mjs ORIGINAL FITTED --deviation D [--interpolator PATH] [--transform Ball] '
  + '[--samples 20] [--timeout SECONDS] [--protos DIR] [--chromium PATH]';
function usage(msg) {
  if (msg) process.stderr.write(`check_path_xite: ${msg}\n`);
  process.stderr.write(usageLine + '\n');
  process.exit(2);
}

const opt = {
  deviation: null,
  interpolator: 'PATH',
  transform: 'Ball',
  samples: 20,
  timeout: 120,
  protos: defaultProtosDir,
  chromium: process.env.CHROMIUM || '/usr/bin/chromium',
};
const files = [];
{
  const a = process.argv.slice(2);
  for (let i = 0; i < a.length; ++i) {
    const arg = a[i];
    const value = () => { if (a[i + 1] === undefined) usage(`${arg} needs a value`); return a[++i]; };
    const int = (least) => { const v = Number(value()); if (!Number.isInteger(v) || v < least) usage(`${arg} needs an integer >= ${least}`); return v; };
    if (arg === '--deviation') {
      opt.deviation = Number(value());
      if (!(opt.deviation > 0) || !Number.isFinite(opt.deviation)) usage('--deviation needs a positive number');
    } else if (arg === '--interpolator') opt.interpolator = value();
    else if (arg === '--transform') opt.transform = value();
    else if (arg === '--samples') opt.samples = int(2);
    else if (arg === '--timeout') opt.timeout = int(1);
    else if (arg === '--protos') opt.protos = path.resolve(value());
    else if (arg === '--chromium') opt.chromium = value();
    else if (arg === '-h' || arg === '--help') usage();
    else if (arg.startsWith('--')) usage(`unknown option ${arg}`);
    else files.push(arg);
  }
}
if (files.length !== 2) usage('need ORIGINAL and FITTED');
if (opt.deviation === null) usage('need --deviation D');
for (const f of files) if (!fs.existsSync(f) || !fs.statSync(f).isFile()) usage(`no such file: ${f}`);
const [original, fitted] = files.map((f) => path.resolve(f));

const { xiteDist, chromium } = await requireXite('check_path_xite');
const session = new XiteSession({ xiteDist, sceneDir: path.dirname(original), protos: opt.protos, chromium: opt.chromium });

function fail(message) {
  const missing = session.missingFiles();
  const tail = missing.length ? ` | not found on the test server: ${missing.join(', ')}` : '';
  process.stderr.write(`check_path_xite: ${message}${tail}\n`);
  session.close().finally(() => process.exit(1));
}
const deadline = setTimeout(() => fail(`timed out after ${opt.timeout} s${session.errors.length ? ': ' + session.errors.join(' | ') : ''}`),
  opt.timeout * 1000);

// In the page: loads `url`, finds both nodes, and returns the interpolator's type and keys (null
// when it has no `key` field).
async function loadScene({ url, interpolator, transform }) {
  const X3D = window.X3D;
  if (!X3D) return { error: 'X_ITE did not load' };
  const browser = X3D.getBrowser(document.getElementById('canvas'));
  try {
    await browser.loadURL(new X3D.MFString(url));
  } catch (e) {
    return { error: `X_ITE failed to load the scene: ${e?.message ?? e}` };
  }
  await browser.nextFrame();
  const scene = browser.currentScene;
  const named = (name) => { try { return scene.getNamedNode(name); } catch { return null; } };
  const path = named(interpolator), moved = named(transform);
  if (!path) return { error: `no node DEF'd ${interpolator}` };
  if (!moved) return { error: `no node DEF'd ${transform}` };
  if (moved.getNodeTypeName() !== 'Transform') return { error: `${transform} is a ${moved.getNodeTypeName()}, not a Transform` };
  let keys = null;
  try { keys = Array.from(path.key, Number); } catch { /* no key field: a NURBS interpolator */ }
  return { type: path.getNodeTypeName(), keys };
}

// In the page: the Transform's translation after each fraction has gone through the cascade.
async function sampleScene({ interpolator, transform, fractions, maxFrames }) {
  const X3D = window.X3D;
  const browser = X3D.getBrowser(document.getElementById('canvas'));
  const scene = browser.currentScene;
  const path = scene.getNamedNode(interpolator), moved = scene.getNamedNode(transform);
  const sentinel = [12345.5, -23456.5, 34567.5];
  const read = () => { const t = moved.translation; return [t.x, t.y, t.z]; };
  const same = (a, b) => a[0] === b[0] && a[1] === b[1] && a[2] === b[2];
  const out = [];
  for (const fraction of fractions) {
    moved.translation = new X3D.SFVec3f(...sentinel);
    await browser.nextFrame();
    if (!same(read(), sentinel))
      return { error: `${transform} moved by itself before fraction ${fraction} was sent (a running TimeSensor?)` };
    path.set_fraction = fraction;
    let frames = 0, at = read();
    while (same(at, sentinel) && frames < maxFrames) {
      await browser.nextFrame();
      ++frames;
      at = read();
    }
    if (same(at, sentinel))
      return { error: `${transform} did not move within ${maxFrames} frames of set_fraction ${fraction}` };
    await browser.nextFrame();
    const settled = read();
    if (!same(settled, at))
      return { error: `${transform} moved again a frame after set_fraction ${fraction}: ${at} then ${settled}` };
    out.push({ fraction, translation: at, frames });
  }
  return { samples: out };
}

// 0, 1 and the midpoints of the key intervals that hold i / (samples - 1).
function fractionsBetween(keys, samples) {
  const out = [0];
  for (let i = 1; i < samples - 1; ++i) {
    const t = i / (samples - 1);
    let j = keys.findIndex((k) => k > t);
    if (j <= 0) { out.push(t); continue; } // outside the keys: the path is constant there
    out.push((keys[j - 1] + keys[j]) / 2);
  }
  out.push(1);
  return out;
}

const runs = [];
try {
  await session.serve();
  await session.launch(chromium);
  let fractions = null;
  for (const file of [original, fitted]) {
    session.sceneDir = path.dirname(file);
    const servedBefore = session.served.length;
    const name = path.relative(process.cwd(), file);
    const loaded = await session.page.evaluate(loadScene,
      { url: session.sceneURL(file), interpolator: opt.interpolator, transform: opt.transform });
    if (loaded.error) throw new Error(`${name}: ${loaded.error}`);
    if (session.errors.length) throw new Error(`${name}: ${session.errors.join(' | ')}`);
    if (fractions === null) {
      if (!loaded.keys || loaded.keys.length < 2) throw new Error(`${name}: ${opt.interpolator} (${loaded.type}) has no keys`);
      fractions = fractionsBetween(loaded.keys, opt.samples);
    } else if (loaded.type !== 'NurbsPositionInterpolator') {
      throw new Error(`${name}: ${opt.interpolator} is a ${loaded.type}, not a NurbsPositionInterpolator`);
    }
    const sampled = await session.page.evaluate(sampleScene,
      { interpolator: opt.interpolator, transform: opt.transform, fractions, maxFrames: 30 });
    if (sampled.error) throw new Error(`${name}: ${sampled.error}`);
    if (session.errors.length) throw new Error(`${name}: ${session.errors.join(' | ')}`);
    // What the load fetched besides the scene itself: for a VRML97 file, the PROTO library.
    const fetched = session.served.slice(servedBefore).filter((s) => s.startsWith('200 /scene/'))
      .map((s) => decodeURIComponent(s.slice('200 /scene/'.length))).filter((f) => f !== path.basename(file));
    runs.push({ name, type: loaded.type, samples: sampled.samples, fetched });
  }
} catch (e) {
  fail(oneLine(e?.message ?? e));
  await new Promise(() => {}); // fail() exits
}
clearTimeout(deadline);
await session.close();

const [a, b] = runs;
const f6 = (x) => x.toFixed(6).padStart(11);
process.stdout.write(`check_path_xite: ${a.name} (${a.type}) against ${b.name} (${b.type}), `
  + `${opt.interpolator} -> ${opt.transform}.translation, D = ${opt.deviation}\n`);
for (const run of runs.filter((r) => r.fetched.length))
  process.stdout.write(`check_path_xite: ${run.name} also fetched ${[...new Set(run.fetched)].join(', ')}\n`);
process.stdout.write('  fraction     original x,y,z                          fitted x,y,z                            distance   frames\n');
let worst = { distance: -1, fraction: NaN };
for (let i = 0; i < a.samples.length; ++i) {
  const p = a.samples[i].translation, q = b.samples[i].translation;
  const distance = Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
  if (distance > worst.distance) worst = { distance, fraction: a.samples[i].fraction };
  process.stdout.write(`  ${a.samples[i].fraction.toFixed(6)} ${p.map(f6).join('')} ${q.map(f6).join('')}  `
    + `${distance.toExponential(3)}  ${a.samples[i].frames}/${b.samples[i].frames}\n`);
}
const pass = worst.distance <= opt.deviation;
process.stdout.write(`check_path_xite: ${pass ? 'PASS' : 'FAIL'}: max distance ${worst.distance.toExponential(3)} `
  + `at fraction ${worst.fraction.toFixed(6)} ${pass ? '<=' : 'exceeds'} ${opt.deviation}\n`);
process.exit(pass ? 0 : 1);
