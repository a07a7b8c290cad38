#!/usr/bin/env node
// Writes the files of the fit-path viewer check (check_path_xite.mjs) into OUT_DIR:
//
//   make_path_files.mjs CADNURBS OUT_DIR [--deviation D]
//
//   helix.x3dv, helix.wrl       a Transform "Ball" driven by PositionInterpolator "PATH": a helix
//                               of radius 5, two turns rising 2 per turn, 400 evenly spaced keys
//   helix-nurbs.x3dv, .wrl      `CADNURBS fit-path` of each at --deviation D (default 0.01); the
//                               .wrl gets the PROTO library beside it from fit-path itself
//   helix-nurbs-moved.x3dv      helix-nurbs.x3dv with its middle control point moved by 10 D
//                               along x: the check must fail on it
//
// The TimeSensor is disabled: the check drives set_fraction itself, and a running clock would
// overwrite the fractions it sets. Exit status 0 when every file is written; 1 with a one-line
// error when fit-path fails or its output holds no controlPoint Coordinate point list; 2 on bad arguments.

import fs from 'node:fs';
import path from 'node:path';
import { execFileSync } from 'node:child_process';

function usage(msg) {
  if (msg) process.stderr.write(`make_path_files: ${msg}\n`);
  process.stderr.write('usage: make_path_files.mjs CADNURBS OUT_DIR [--deviation D]\n');
  process.exit(2);
}
function fail(msg) {
  process.stderr.write(`make_path_files: ${msg}\n`);
  process.exit(1);
}

let deviation = 0.01;
const positional = [];
{
  const a = process.argv.slice(2);
  for (let i = 0; i < a.length; ++i) {
    if (a[i] === '--deviation') {
      deviation = Number(a[++i]);
      if (!(deviation > 0)) usage('--deviation needs a positive number');
    } else if (a[i].startsWith('--')) usage(`unknown option ${a[i]}`);
    else positional.push(a[i]);
  }
}
if (positional.length !== 2) usage('need CADNURBS and OUT_DIR');
const [cadnurbs, outDir] = positional.map((p) => path.resolve(p));
fs.mkdirSync(outDir, { recursive: true });

// The keyframes: evenly spaced keys on [0, 1], so the first and last keys span the whole fraction range.
const keyCount = 400, radius = 5, turns = 2, rise = 2;
const keys = [], points = [];
for (let i = 0; i < keyCount; ++i) {
  const t = i / (keyCount - 1), angle = 2 * Math.PI * turns * t;
  keys.push(t);
  points.push([radius * Math.cos(angle), radius * Math.sin(angle), rise * turns * t]);
}
const number = (x) => String(Number(x.toFixed(9)));
const keyText = keys.map(number).join(' ');
const keyValueText = points.map((p) => p.map(number).join(' ')).join(', ');

const body = `Viewpoint { position 0 -22 2 orientation 1 0 0 1.5708 description "side" }
DEF Ball Transform {
  children Shape {
    appearance Appearance { material Material { diffuseColor 0.8 0.2 0.1 } }
    geometry Sphere { radius 0.3 }
  }
}
# Disabled: check_path_xite.mjs sets PATH's set_fraction itself.
DEF Clock TimeSensor { cycleInterval 10 loop TRUE enabled FALSE }
DEF PATH PositionInterpolator {
  key [ ${keyText} ]
  keyValue [ ${keyValueText} ]
}
ROUTE Clock.fraction_changed TO PATH.set_fraction
ROUTE PATH.value_changed TO Ball.set_translation
`;
const comment = `# A helix path (radius ${radius}, ${turns} turns, ${keyCount} keys) for the fit-path viewer check.\n`;
const files = {
  x3dv: `#X3D V3.3 utf8\nPROFILE Interchange\n${comment}${body}`,
  wrl: `#VRML V2.0 utf8\n${comment}${body}`,
};

for (const [extension, text] of Object.entries(files)) {
  const original = path.join(outDir, `helix.${extension}`);
  const fitted = path.join(outDir, `helix-nurbs.${extension}`);
  fs.writeFileSync(original, text);
  fs.rmSync(fitted, { force: true });
  try {
    const said = execFileSync(cadnurbs, ['fit-path', original, '-o', fitted, '--deviation', String(deviation)],
      { encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
    process.stdout.write(said);
  } catch (e) {
    fail(`fit-path ${original}: ${String(e.stderr || e.message).trim()}`);
  }
}

// The negative control: the middle control point of the X3D output moved by 10 D along x.
const fittedX3d = path.join(outDir, 'helix-nurbs.x3dv');
const text = fs.readFileSync(fittedX3d, 'utf8');
const list = /controlPoint\s*Coordinate\s*\{\s*point\s*\[([^\]]*)\]/.exec(text);
if (!list) fail(`${fittedX3d}: no controlPoint Coordinate point list`);
// Only the one number changes; every other byte stays as fit-path wrote it.
const numbers = [...list[1].matchAll(/[^\s,]+/g)];
if (numbers.length < 9 || numbers.length % 3 !== 0 || numbers.some((m) => !Number.isFinite(Number(m[0]))))
  fail(`${fittedX3d}: controlPoint list of ${numbers.length} numbers`);
const middle = Math.floor(numbers.length / 6) * 3;
const x = numbers[middle];
const at = list.index + list[0].indexOf('[') + 1 + x.index;
fs.writeFileSync(path.join(outDir, 'helix-nurbs-moved.x3dv'),
  text.slice(0, at) + number(Number(x[0]) + 10 * deviation) + text.slice(at + x[0].length));
process.stdout.write(`make_path_files: control point ${middle / 3} of ${numbers.length / 3} moved by ${10 * deviation} in helix-nurbs-moved.x3dv\n`);
