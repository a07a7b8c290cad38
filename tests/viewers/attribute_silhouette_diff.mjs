#!/usr/bin/env node
// Splits the silhouette difference of two renderings of the same scene between them, by a third
// rendering of a reference (a certified mesh of the same shapes, same Viewpoint).
//
//   attribute_silhouette_diff.mjs A.png B.png REFERENCE.png [--tolerance T] [--max-a F] [--max-b F]
//
// Prints one line of JSON (fractions of all pixels):
//   diff_ab   foreground in exactly one of A and B (compare_images' diff)
//   a_wrong   of those, the pixels where A disagrees with REFERENCE (B agrees): A's share
//   b_wrong   the pixels where B disagrees with REFERENCE (A agrees): B's share; a_wrong + b_wrong = diff_ab
//   diff_a_ref, diff_b_ref   each picture's whole difference from REFERENCE (these also count what
//             A and B share and REFERENCE lacks, e.g. line sets a mesh output leaves out)
// Exit 1 with a one-line reason when --max-a F and a_wrong > F, or --max-b F and b_wrong > F; 2 on
// bad arguments, unreadable or differently sized images. Silhouettes as compare_images.mjs takes them.

import { readPng, silhouetteMask } from './silhouette_mask.mjs';

function usage(msg) {
  if (msg) process.stderr.write(`attribute_silhouette_diff: ${msg}\n`);
  process.stderr.write('usage: attribute_silhouette_diff.mjs A.png B.png REFERENCE.png [--tolerance T] [--max-a F] [--max-b F]\n');
  process.exit(2);
}
const files = [];
const opt = { tolerance: 40, maxA: null, maxB: null };
const args = process.argv.slice(2);
for (let i = 0; i < args.length; ++i) {
  const a = args[i];
  const num = () => {
    const v = Number(args[++i]);
    if (args[i] === undefined || !Number.isFinite(v)) usage(`${a} needs a number`);
    return v;
  };
  if (a === '--tolerance') opt.tolerance = num();
  else if (a === '--max-a') opt.maxA = num();
  else if (a === '--max-b') opt.maxB = num();
  else if (a.startsWith('--')) usage(`unknown option ${a}`);
  else files.push(a);
}
if (files.length !== 3) usage('need A, B and REFERENCE');
const images = files.map((f) => readPng(f, 'attribute_silhouette_diff'));
if (images.some((img) => img.width !== images[0].width || img.height !== images[0].height)) usage('the three images differ in size');
const [A, B, R] = images.map((img) => silhouetteMask(img, opt.tolerance).m);

let diffAB = 0, aWrong = 0, bWrong = 0, diffAR = 0, diffBR = 0;
for (let i = 0; i < A.length; ++i) {
  if (A[i] !== R[i]) ++diffAR;
  if (B[i] !== R[i]) ++diffBR;
  if (A[i] === B[i]) continue;
  ++diffAB;
  if (A[i] !== R[i]) ++aWrong;
  else ++bWrong;
}
const total = A.length;
const round = (x) => Math.round((x / total) * 1e6) / 1e6;
const result = { diff_ab: round(diffAB), a_wrong: round(aWrong), b_wrong: round(bWrong), diff_a_ref: round(diffAR), diff_b_ref: round(diffBR) };
process.stdout.write(JSON.stringify(result) + '\n');
const failures = [];
if (opt.maxA !== null && result.a_wrong > opt.maxA) failures.push(`${files[0]} is off the reference where ${files[1]} is not in ${result.a_wrong} of pixels > ${opt.maxA}`);
if (opt.maxB !== null && result.b_wrong > opt.maxB) failures.push(`${files[1]} is off the reference where ${files[0]} is not in ${result.b_wrong} of pixels > ${opt.maxB}`);
if (failures.length) {
  process.stderr.write(`attribute_silhouette_diff: ${failures.join('; ')}\n`);
  process.exit(1);
}
