#!/usr/bin/env node
// Logs a Transform's translation and rotation after every frame X_ITE draws on the standing clock
// (virtual_clock.mjs), to see what ROUTEs do to it frame by frame (e.g. robot_opengl's ROUTE loop,
// README.md "A ROUTE loop").
//
//   log_transform_xite.mjs FILE DEF T1,T2,... [FRAMES]
//
// Loads FILE as render_xite.mjs --times does, prints "frames during load N" (the frames X_ITE drew
// until loadURL resolved), then for each scene time T (seconds, increasing) draws FRAMES frames
// (default 4) ending at T and prints, after each, the number of frames drawn so far, DEF's translation
// and rotation (axis, angle). Exit 1 with one line when the load fails or DEF names no node.
import path from 'node:path';

import {kClockOrigin, setClockAndDraw, virtualClockInitScript} from './virtual_clock.mjs';
import {XiteSession, oneLine, requireXite} from './xite_page.mjs';

const [file, def, timesArg, framesArg = '4'] = process.argv.slice(2);
const times = (timesArg ?? '').split(',').map(Number);
const frames = Number(framesArg);
if (!file || !def || times.some((t) => !(t > 0)) || !(Number.isInteger(frames) && frames > 0)) {
  process.stderr.write('usage: log_transform_xite.mjs FILE DEF T1,T2,... [FRAMES]\n');
  process.exit(2);
}
const {xiteDist, chromium} = await requireXite('log_transform_xite');
const session = new XiteSession({
  xiteDist,
  sceneDir: path.dirname(path.resolve(file)),
  chromium: process.env.CHROMIUM || '/usr/bin/chromium',
  initScript: virtualClockInitScript,
});
let status = 0;
try {
  await session.serve();
  await session.launch(chromium);
  const loadFrames = await session.page.evaluate(async ({url, def}) => {
    const browser = X3D.getBrowser(document.getElementById('canvas'));
    browser.setBrowserOption('StraightenHorizon', false);
    window.cadnurbsClock.attach(browser);
    // Counts the frames: X_ITE calls advanceTime once a frame.
    window.framesDrawn = 0;
    const advanceTime = browser.advanceTime;
    browser.advanceTime = function() {
      const drawn = advanceTime.call(this);
      if (drawn) ++window.framesDrawn;
      return drawn;
    };
    await browser.loadURL(new X3D.MFString(url));
    window.cadnurbsClock.hold();
    browser.currentScene.getNamedNode(def);  // throws when DEF names no node
    return window.framesDrawn;
  }, {url: session.sceneURL(path.resolve(file)), def});
  console.log(`frames during load ${loadFrames}`);
  for (const t of times) {
    for (let i = frames - 1; i >= 0; --i) {
      await setClockAndDraw(session.page, t - i * 1e-3, 1);
      const line = await session.page.evaluate((def) => {
        const node = X3D.getBrowser(document.getElementById('canvas')).currentScene.getNamedNode(def);
        const f = (v) => Array.from(v, (x) => x.toFixed(4)).join(' ');
        const r = node.rotation;
        return `frame ${window.framesDrawn} translation ${f(node.translation)} rotation ${f([r.x, r.y, r.z, r.angle])}`;
      }, def);
      console.log(`t=${t} ${line}`);
    }
  }
} catch (e) {
  process.stderr.write(`log_transform_xite: ${file}: ${oneLine(e?.message ?? e)}\n`);
  status = 1;
}
await session.close();
process.exit(status);
