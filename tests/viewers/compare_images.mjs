#!/usr/bin/env node
// Compares the silhouettes of two renderings of the same size.
//
//   compare_images.mjs A.png B.png [--max-diff F] [--min-foreground F]
//                      [--tolerance T] [--diff-image OUT.png]
//
// Each image is thresholded into foreground / background: the background colour is the
// most frequent colour of the image's one-pixel border, and a pixel is foreground when one
// of its channels differs from that colour by more than T (0..255, default 40) or when it
// is opaque on a transparent background. Prints one line of JSON:
//   { "width", "height", "background_a", "background_b", "foreground_a", "foreground_b",
//     "diff", "iou" }
// where foreground_* are the fractions of foreground pixels, diff is the fraction of all
// pixels that are foreground in exactly one image, and iou is |A and B| / |A or B| of the
// foreground masks (1 when both are empty).
// Exit status: 0, unless --max-diff F is given and diff > F, or --min-foreground F is
// given and either image has a foreground fraction below F: then 1, with a one-line
// reason on stderr. 2 on bad arguments or unreadable images.
// --diff-image writes A | B | masks side by side (masks: black both, red only A,
// blue only B, white neither), for looking at a failure.

import fs from 'node:fs';
import { PNG } from 'pngjs';

import { readPng, silhouetteMask } from './silhouette_mask.mjs';

function usage(msg) {
  if (msg) process.stderr.write(`compare_images: ${msg}\n`);
  process.stderr.write('usage: compare_images.mjs A.png B.png [--max-diff F] [--min-foreground F] [--tolerance T] [--diff-image OUT.png]\n');
  process.exit(2);
}

const args = process.argv.slice(2);
const files = [];
const opt = { maxDiff: null, minForeground: null, tolerance: 40, diffImage: null };
for (let i = 0; i < args.length; ++i) {
  const a = args[i];
  const num = (name) => {
    const v = Number(args[++i]);
    if (args[i] === undefined || !Number.isFinite(v)) usage(`${name} needs a number`);
    return v;
  };
  if (a === '--max-diff') opt.maxDiff = num(a);
  else if (a === '--min-foreground') opt.minForeground = num(a);
  else if (a === '--tolerance') opt.tolerance = num(a);
  else if (a === '--diff-image') { opt.diffImage = args[++i]; if (!opt.diffImage) usage('--diff-image needs a file'); }
  else if (a === '-h' || a === '--help') usage();
  else if (a.startsWith('--')) usage(`unknown option ${a}`);
  else files.push(a);
}
if (files.length !== 2) usage('need exactly two images');

const read = (file) => readPng(file);

const [imgA, imgB] = files.map(read);
if (imgA.width !== imgB.width || imgA.height !== imgB.height) {
  process.stderr.write(`compare_images: sizes differ: ${files[0]} is ${imgA.width}x${imgA.height}, ${files[1]} is ${imgB.width}x${imgB.height}\n`);
  process.exit(opt.maxDiff !== null || opt.minForeground !== null ? 1 : 2);
}
const { width, height } = imgA;

const mask = (img) => silhouetteMask(img, opt.tolerance);

const A = mask(imgA), B = mask(imgB);
let both = 0, either = 0, onlyA = 0, onlyB = 0;
for (let i = 0; i < A.m.length; ++i) {
  const a = A.m[i], b = B.m[i];
  if (a && b) ++both;
  if (a || b) ++either;
  if (a && !b) ++onlyA;
  if (b && !a) ++onlyB;
}
const total = width * height;
const round = (x) => Math.round(x * 1e6) / 1e6;
const result = {
  width,
  height,
  background_a: A.bg.slice(0, 3),
  background_b: B.bg.slice(0, 3),
  foreground_a: round(A.fraction),
  foreground_b: round(B.fraction),
  diff: round((onlyA + onlyB) / total),
  iou: round(either ? both / either : 1),
};
process.stdout.write(JSON.stringify(result) + '\n');

if (opt.diffImage) {
  const out = new PNG({ width: 3 * width, height });
  for (let y = 0; y < height; ++y)
    for (let x = 0; x < width; ++x) {
      const i = y * width + x, s = 4 * i;
      const put = (col, rgba) => {
        const o = 4 * (y * 3 * width + col * width + x);
        out.data[o] = rgba[0]; out.data[o + 1] = rgba[1]; out.data[o + 2] = rgba[2]; out.data[o + 3] = 255;
      };
      put(0, imgA.data.subarray(s, s + 4));
      put(1, imgB.data.subarray(s, s + 4));
      const a = A.m[i], b = B.m[i];
      put(2, a && b ? [0, 0, 0] : a ? [220, 0, 0] : b ? [0, 0, 220] : [255, 255, 255]);
    }
  fs.writeFileSync(opt.diffImage, PNG.sync.write(out));
}

const failures = [];
if (opt.minForeground !== null) {
  if (A.fraction < opt.minForeground) failures.push(`blank image: ${files[0]} has foreground ${round(A.fraction)} < ${opt.minForeground}`);
  if (B.fraction < opt.minForeground) failures.push(`blank image: ${files[1]} has foreground ${round(B.fraction)} < ${opt.minForeground}`);
}
if (opt.maxDiff !== null && result.diff > opt.maxDiff)
  failures.push(`silhouette differs in ${result.diff} of pixels > ${opt.maxDiff} (IoU ${result.iou})`);
if (failures.length) {
  process.stderr.write(`compare_images: ${failures.join('; ')}\n`);
  process.exit(1);
}
process.exit(0);
