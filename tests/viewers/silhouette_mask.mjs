// The silhouette of a rendering: which pixels are foreground. Shared by compare_images.mjs and
// attribute_silhouette_diff.mjs.
//
//   readPng(file)                 -> pngjs image { width, height, data: RGBA bytes }; exits 2 naming
//                                    the file when it cannot be read
//   silhouetteMask(img, tolerance) -> { bg: [r, g, b, a], m: Uint8Array (1 = foreground), fraction }
//
// The background colour is the most frequent colour of the image's one-pixel border; a pixel is
// foreground when one of its channels differs from it by more than `tolerance` (0..255), or when
// it is opaque on a transparent background.

import fs from 'node:fs';
import { PNG } from 'pngjs';

export function readPng(file, program = 'compare_images') {
  try {
    return PNG.sync.read(fs.readFileSync(file));
  } catch (e) {
    process.stderr.write(`${program}: cannot read ${file}: ${e.message}\n`);
    process.exit(2);
  }
}

function backgroundOf(img) {
  const { width, height, data: d } = img;
  const counts = new Map();
  const add = (x, y) => {
    const o = 4 * (y * width + x);
    const key = (d[o] << 24 >>> 0) + (d[o + 1] << 16) + (d[o + 2] << 8) + d[o + 3];
    counts.set(key, (counts.get(key) || 0) + 1);
  };
  for (let x = 0; x < width; ++x) { add(x, 0); add(x, height - 1); }
  for (let y = 1; y < height - 1; ++y) { add(0, y); add(width - 1, y); }
  let best = 0, bestCount = -1;
  for (const [k, c] of counts) if (c > bestCount) { best = k; bestCount = c; }
  return [(best >>> 24) & 255, (best >>> 16) & 255, (best >>> 8) & 255, best & 255];
}

export function silhouetteMask(img, tolerance = 40) {
  const bg = backgroundOf(img);
  const d = img.data, m = new Uint8Array(img.width * img.height);
  let n = 0;
  for (let i = 0, o = 0; i < m.length; ++i, o += 4) {
    let fg;
    if (bg[3] < 128) fg = d[o + 3] >= 128; // transparent background: opaque pixels
    else fg = d[o + 3] >= 128 && (Math.abs(d[o] - bg[0]) > tolerance || Math.abs(d[o + 1] - bg[1]) > tolerance || Math.abs(d[o + 2] - bg[2]) > tolerance);
    if (fg) { m[i] = 1; ++n; }
  }
  return { bg, m, fraction: n / m.length };
}
