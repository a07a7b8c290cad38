#!/usr/bin/env node
// Checks formats/vrml/protos/cadnurbs-nurbs-protos.wrl without a browser:
//  1. the text contract cadnurbs' writer relies on (PROTO lines, one interface
//     declaration per line, "] {", body closed by "}" at column 0, nothing else at top
//     level) and the exact interface of every node;
//  2. that the shared evaluator text is identical in both Scripts;
//  3. the Scripts' results, run here in node with the inputs rounded to single precision
//     as a browser stores MFFloat / MFVec3f: points and normals of a rational quarter
//     cylinder and an ellipsoid (with poles) against the analytic shapes, the area and
//     extent of trimmed regions (disc, square with an L-shaped hole, a clockwise-only
//     hole, ccw FALSE), default knots, and refusal of invalid input; the tessellation
//     counts (> 0 and < 0 as X_ITE and view3dscene read them, rounded up per span); a
//     many-sided trimming loop on a fine grid (triangles grow with loop + grid, not their
//     product; no T junctions: every mesh edge not on the loop is shared by two triangles);
//  4. that the X_ITE fast paths (fields read with getValue(), written with setValue())
//     give exactly what the standard element-by-element paths give.
// Prints one line per check and "N passed, M failed"; exit 1 when a check fails.
//   check_protos.mjs [PROTO_FILE]

import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { runScript } from './protos_sandbox.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const protoFile = path.resolve(process.argv[2] ?? path.join(here, '../../formats/vrml/protos/cadnurbs-nurbs-protos.wrl'));
const text = fs.readFileSync(protoFile, 'utf8');

let passed = 0, failed = 0;
function check(name, ok, detail = '') {
  if (ok) ++passed; else ++failed;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}${detail ? ': ' + detail : ''}`);
}

// ------------------------------------------------------------------ 1. contract
const expected = {
  NurbsSurface: [
    'field SFInt32 uDimension 0', 'field SFInt32 vDimension 0', 'field MFFloat uKnot []',
    'field MFFloat vKnot []', 'field SFInt32 uOrder 3', 'field SFInt32 vOrder 3',
    'exposedField MFVec3f controlPoint []', 'field MFFloat weight []', 'field SFInt32 uTessellation 0',
    'field SFInt32 vTessellation 0', 'field SFBool ccw TRUE', 'field SFBool solid TRUE',
  ],
  NurbsGroup: ['field MFNode children []', 'field SFFloat tessellationScale 1'],
  TrimmedSurface: ['field SFNode surface NULL', 'field MFNode trimmingContour []'],
  Contour2D: ['field MFNode children []'],
  NurbsCurve2D: [
    'field MFVec2f point []', 'field MFFloat knot []', 'field SFInt32 order 3',
    'field MFFloat weight []', 'field SFInt32 tessellation 0',
  ],
  Polyline2D: ['field MFVec2f point []'],
  NurbsCurve: [
    'field MFVec3f controlPoint []', 'field MFFloat knot []', 'field SFInt32 order 3',
    'field MFFloat weight []', 'field SFInt32 tessellation 0',
  ],
  NurbsPositionInterpolator: [
    'eventIn SFFloat set_fraction', 'field SFInt32 dimension 0', 'field MFFloat knot []',
    'field SFInt32 order 3', 'field MFVec3f keyValue []', 'field MFFloat keyWeight []',
    'eventOut SFVec3f value_changed',
  ],
};

const lines = text.split('\n');
const protos = {};
const contractErrors = [];
{
  if (lines[0] !== '#VRML V2.0 utf8') contractErrors.push('line 1 is not "#VRML V2.0 utf8"');
  let i = 1;
  while (i < lines.length) {
    const line = lines[i];
    if (line.trim() === '' || line.startsWith('#')) { ++i; continue; }
    const m = /^PROTO (\w+) \[$/.exec(line);
    if (!m) { contractErrors.push(`line ${i + 1}: unexpected top-level text: ${line}`); ++i; continue; }
    const name = m[1], iface = [];
    ++i;
    while (i < lines.length && lines[i] !== '] {') {
      const d = /^  (field|exposedField|eventIn|eventOut) (\w+) (\w+)(?: (\S.*))?$/.exec(lines[i]);
      if (!d) contractErrors.push(`line ${i + 1}: not an interface declaration: ${lines[i]}`);
      else iface.push(`${d[1]} ${d[2]} ${d[3]}${d[4] !== undefined ? ' ' + d[4] : ''}`);
      ++i;
    }
    const bodyStart = ++i;
    while (i < lines.length && lines[i] !== '}') ++i;
    if (i >= lines.length) contractErrors.push(`PROTO ${name}: no closing "}" line`);
    protos[name] = { iface, body: lines.slice(bodyStart, i).join('\n') };
    ++i;
  }
}
check('contract: file layout', contractErrors.length === 0, contractErrors.slice(0, 3).join('; '));
for (const [name, iface] of Object.entries(expected)) {
  const got = protos[name]?.iface;
  check(`contract: PROTO ${name} interface`, JSON.stringify(got) === JSON.stringify(iface),
    got ? `got [${got.join(', ')}]` : 'missing');
}
check('contract: no other PROTOs', Object.keys(protos).every((n) => n in expected), Object.keys(protos).join(' '));
for (const [name, p] of Object.entries(protos)) {
  // a line exactly "}" ends the body (the parse above); no body line may look like the
  // start of a PROTO or the end of an interface either
  check(`contract: PROTO ${name} body has no line a writer could mistake`,
    !p.body.split('\n').some((l) => l.startsWith('PROTO ') || l === '] {'));
}

// ------------------------------------------------------------------ 2. shared evaluator
function scriptOf(name) {
  const body = protos[name]?.body ?? '';
  const m = /url "javascript:([^"]*)"/.exec(body);
  return m ? m[1] : null;
}
const surfaceScript = scriptOf('NurbsSurface');
const trimScript = scriptOf('TrimmedSurface');
check('scripts: NurbsSurface and TrimmedSurface have javascript: Scripts', !!surfaceScript && !!trimScript);
const shared = (s) => {
  const a = s?.indexOf('// BEGIN shared evaluator'), b = s?.indexOf('// END shared evaluator');
  return a >= 0 && b > a ? s.slice(a, b) : null;
};
check('scripts: shared evaluator text identical', shared(surfaceScript) !== null && shared(surfaceScript) === shared(trimScript));
check('scripts: no double quote or backslash inside', !/[\\]/.test(surfaceScript + trimScript));

// ------------------------------------------------------------------ 3. numeric
const f32 = Math.fround;
class MFArray extends Array {}
const sandbox = {
  MFVec3f: MFArray,
  MFInt32: MFArray,
  SFVec3f: function SFVec3f(x, y, z) { return { x: f32(x), y: f32(y), z: f32(z) }; },
};
function run(script, fields) {
  const messages = [];
  // NurbsSurface's Script reads its control points from the PROTO's Coordinate (control.point).
  const control = { point: fields.controlPoint };
  const env = { ...sandbox, print: (m) => messages.push(String(m)), coord: {}, normal: {}, control, ...fields };
  const names = Object.keys(env);
  const fn = new Function(...names, 'var coordIndex_changed = null;\n' + script + '\ninitialize();\nreturn coordIndex_changed;');
  const index = fn(...names.map((n) => env[n]));
  const tris = [];
  for (let i = 0; index && i < index.length; i += 4) tris.push([index[i], index[i + 1], index[i + 2]]);
  return { points: env.coord.point ?? [], normals: env.normal.vector ?? [], tris, messages };
}
const v3 = (p) => ({ x: f32(p[0]), y: f32(p[1]), z: f32(p[2]) });
const v2 = (p) => ({ x: f32(p[0]), y: f32(p[1]) });
const fl = (a) => a.map(f32);
const W = Math.SQRT1_2;
const surfaceFields = (o) => ({
  uDimension: 0, vDimension: 0, uKnot: [], vKnot: [], uOrder: 3, vOrder: 3, controlPoint: [], weight: [],
  uTessellation: 0, vTessellation: 0, ccw: true, solid: true, ...o,
});

// quarter cylinder radius 1, z in [-1, 1]
const cylinder = (() => {
  const arc = [[1, 0], [1, 1], [0, 1]], aw = [1, W, 1], cp = [], w = [];
  for (const z of [-1, 1]) arc.forEach(([x, y], i) => { cp.push([x * aw[i], y * aw[i], z * aw[i]]); w.push(aw[i]); });
  return surfaceFields({
    uDimension: 3, vDimension: 2, uOrder: 3, vOrder: 2, uKnot: fl([0, 0, 0, 1, 1, 1]), vKnot: fl([0, 0, 1, 1]),
    controlPoint: cp.map(v3), weight: fl(w),
  });
})();
{
  const r = run(surfaceScript, cylinder);
  let radial = 0, normal = 0, zmin = Infinity, zmax = -Infinity;
  r.points.forEach((p, i) => {
    radial = Math.max(radial, Math.abs(Math.hypot(p.x, p.y) - 1));
    const n = r.normals[i], l = Math.hypot(p.x, p.y);
    normal = Math.max(normal, 1 - (n.x * p.x / l + n.y * p.y / l));
    zmin = Math.min(zmin, p.z); zmax = Math.max(zmax, p.z);
  });
  check('NurbsSurface: quarter cylinder points on radius 1', r.points.length > 0 && radial < 1e-6, `max error ${radial.toExponential(2)}, ${r.points.length} points`);
  check('NurbsSurface: quarter cylinder normals radial, outward', normal < 1e-6, `max 1-cos ${normal.toExponential(2)}`);
  check('NurbsSurface: quarter cylinder spans z -1..1', Math.abs(zmin + 1) < 1e-6 && Math.abs(zmax - 1) < 1e-6);
  // default tessellation: quadratic span 8 steps, linear 1 -> 9 x 2 vertices, 16 triangles
  check('NurbsSurface: default tessellation 8 steps per quadratic span, 1 per linear', r.points.length === 18 && r.tris.length === 16, `${r.points.length} points, ${r.tris.length} triangles`);
  // orientation: triangle normal (right-hand) agrees with the vertex normals
  let agree = true;
  for (const [a, b, c] of r.tris) {
    const P = [r.points[a], r.points[b], r.points[c]];
    const e1 = [P[1].x - P[0].x, P[1].y - P[0].y, P[1].z - P[0].z], e2 = [P[2].x - P[0].x, P[2].y - P[0].y, P[2].z - P[0].z];
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const vn = r.normals[a];
    if (n[0] * vn.x + n[1] * vn.y + n[2] * vn.z <= 0) agree = false;
  }
  check('NurbsSurface: triangles counter-clockwise around the normals', agree);
  const rt = run(surfaceScript, { ...cylinder, uTessellation: 20, vTessellation: 3 });
  check('NurbsSurface: uTessellation 20, vTessellation 3 -> 21 x 4 vertices', rt.points.length === 84, `${rt.points.length}`);
  const rn = run(surfaceScript, { ...cylinder, ccw: false });
  check('NurbsSurface: ccw FALSE flips the normals', rn.normals.length && rn.normals.every((n, i) => Math.abs(n.x + r.normals[i].x) < 1e-9 && Math.abs(n.y + r.normals[i].y) < 1e-9));
  const re = run(surfaceScript, { ...cylinder, uKnot: [] , vKnot: []});
  check('NurbsSurface: empty knots -> uniform clamped, same shape', re.points.length === 18 && re.messages.length === 0);
  const rb = run(surfaceScript, { ...cylinder, uKnot: fl([0, 0, 1, 1]) });
  check('NurbsSurface: wrong knot count warned and replaced', rb.points.length === 18 && rb.messages.some((m) => /invalid knot vector/.test(m)), rb.messages.join(' / '));
  const ri = run(surfaceScript, { ...cylinder, uDimension: 2 });
  check('NurbsSurface: fewer points than the order draws nothing, warns', ri.points.length === 0 && ri.messages.length === 1, ri.messages.join(' / '));
}

// ellipsoid radii 1, 1, 1.4 with poles
const ellipsoid = (() => {
  const ring = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]];
  const rw = ring.map((_, i) => (i % 2 ? W : 1));
  const mer = [[0, -1], [1, -1], [1, 0], [1, 1], [0, 1]], mw = [1, W, 1, W, 1], cp = [], w = [];
  mer.forEach(([r, z], j) => ring.forEach(([x, y], i) => {
    const ww = rw[i] * mw[j];
    cp.push([x * r * ww, y * r * ww, 1.4 * z * ww]);
    w.push(ww);
  }));
  return surfaceFields({
    uDimension: 9, vDimension: 5, uKnot: fl([0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]), vKnot: fl([0, 0, 0, 1, 1, 2, 2, 2]),
    controlPoint: cp.map(v3), weight: fl(w),
  });
})();
{
  const r = run(surfaceScript, ellipsoid);
  let surf = 0, normal = 0, poleNormal = 0;
  r.points.forEach((p, i) => {
    surf = Math.max(surf, Math.abs(Math.hypot(p.x, p.y, p.z / 1.4) - 1));
    const g = [p.x, p.y, p.z / 1.96], l = Math.hypot(...g), n = r.normals[i];
    const e = 1 - (g[0] * n.x + g[1] * n.y + g[2] * n.z) / l;
    normal = Math.max(normal, e);
    if (Math.hypot(p.x, p.y) < 1e-6) poleNormal = Math.max(poleNormal, e);
  });
  check('NurbsSurface: ellipsoid points on the surface', r.points.length > 0 && surf < 1e-6, `max error ${surf.toExponential(2)}`);
  check('NurbsSurface: ellipsoid normals analytic, outward, also at the poles', normal < 1e-4 && poleNormal < 1e-4, `max 1-cos ${normal.toExponential(2)}, at poles ${poleNormal.toExponential(2)}`);
}

// trimmed surfaces on the plane square [-1,1]^2, domain [0,1]^2
const plane = surfaceFields({
  uDimension: 2, vDimension: 2, uOrder: 2, vOrder: 2, uKnot: fl([0, 0, 1, 1]), vKnot: fl([0, 0, 1, 1]),
  controlPoint: [[-1, -1, 0], [1, -1, 0], [-1, 1, 0], [1, 1, 0]].map(v3), solid: false,
});
function circleCurve(cx, cy, r, clockwise = false) {
  let unit = [[1, 0], [1, 1], [0, 1], [-1, 1], [-1, 0], [-1, -1], [0, -1], [1, -1], [1, 0]];
  if (clockwise) unit = unit.map(([x, y]) => [x, -y]);
  const w = unit.map((_, i) => (i % 2 ? W : 1));
  return {
    point: unit.map(([x, y], i) => v2([(cx + r * x) * w[i], (cy + r * y) * w[i]])),
    knot: fl([0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4]), order: 3, weight: fl(w), tessellation: 0,
  };
}
function meshStats(r) {
  // area and bounds in space (plane z = 0 -> area in xy), and orientation
  let area = 0, minx = Infinity, maxx = -Infinity, miny = Infinity, maxy = -Infinity, negative = 0;
  for (const [a, b, c] of r.tris) {
    const A = r.points[a], B = r.points[b], C = r.points[c];
    const s = ((B.x - A.x) * (C.y - A.y) - (B.y - A.y) * (C.x - A.x)) / 2;
    area += Math.abs(s);
    if (s < 0) ++negative;
  }
  for (const p of r.points) { minx = Math.min(minx, p.x); maxx = Math.max(maxx, p.x); miny = Math.min(miny, p.y); maxy = Math.max(maxy, p.y); }
  return { area, minx, maxx, miny, maxy, negative };
}
{
  // disc: centre (0.45,0.55) radius 0.35 in (u,v) -> radius 0.7 at (-0.1, 0.1) in space
  const r = run(trimScript, { surface: plane, trimmingContour: [{ children: [circleCurve(0.45, 0.55, 0.35)] }] });
  const s = meshStats(r);
  // 4 spans x 12 chords inscribed in the circle (chords not quite equal: the rational
  // arc's parameter is not the angle): area a little below the circle's, above the
  // regular 24-gon's.
  const circleArea = Math.PI * 0.49, n24 = 12 * 0.49 * Math.sin((2 * Math.PI) / 24);
  let onCircle = 0;
  for (const p of r.points) { const d = Math.hypot(p.x + 0.1, p.y - 0.1); if (d > 0.35) onCircle = Math.max(onCircle, Math.abs(d - 0.7)); }
  check('TrimmedSurface: disc area just below the circle', s.area < circleArea && s.area > n24 && circleArea - s.area < 0.003 * circleArea, `area ${s.area.toFixed(6)}, circle ${circleArea.toFixed(6)}`);
  check('TrimmedSurface: disc boundary vertices on the circle', onCircle < 1e-6, `max error ${onCircle.toExponential(2)}`);
  check('TrimmedSurface: disc extent', Math.abs(s.minx + 0.8) < 1e-5 && Math.abs(s.maxx - 0.6) < 1e-5 && Math.abs(s.miny + 0.6) < 1e-5 && Math.abs(s.maxy - 0.8) < 1e-5,
    `x ${s.minx.toFixed(4)}..${s.maxx.toFixed(4)}, y ${s.miny.toFixed(4)}..${s.maxy.toFixed(4)}`);
  check('TrimmedSurface: triangles counter-clockwise (front +z)', s.negative === 0 && r.normals.every((q) => q.z > 0.999));
  const rc = run(trimScript, { surface: { ...plane, ccw: false }, trimmingContour: [{ children: [circleCurve(0.45, 0.55, 0.35)] }] });
  const sc = meshStats(rc);
  check('TrimmedSurface: ccw FALSE turns triangles and normals round', sc.negative === rc.tris.length && rc.tris.length > 0 && rc.normals.every((q) => q.z < -0.999));
  // a clockwise-only loop: domain boundary added, the circle is a hole
  const rh = run(trimScript, { surface: plane, trimmingContour: [{ children: [circleCurve(0.5, 0.5, 0.25, true)] }] });
  const sh = meshStats(rh);
  const hole = Math.PI * 0.25 * 0.25 * 4; // area in space: x4
  check('TrimmedSurface: clockwise-only loop cuts a hole in the whole surface', sh.area > 4 - hole && sh.area - (4 - hole) < 0.003 * hole, `area ${sh.area.toFixed(6)}, exact ${(4 - hole).toFixed(6)}`);
  // no loops: the whole surface
  const rw = run(trimScript, { surface: plane, trimmingContour: [] });
  check('TrimmedSurface: no trimming contour -> whole surface', Math.abs(meshStats(rw).area - 4) < 1e-9);
  // square with an L-shaped hole made of a line, two arcs and a polyline (fixture trimmed_hole.wrl)
  const arcPts = [[0.2, 0.65], [0.2, 0.75], [0.3, 0.75], [0.4, 0.75], [0.4, 0.65]], arcW = [1, W, 1, W, 1];
  const rl = run(trimScript, {
    surface: plane,
    trimmingContour: [
      { children: [{ point: [[0, 0], [1, 0], [1, 1], [0, 1], [0, 0]].map(v2) }] },
      { children: [
        { point: [[0.2, 0.2], [0.2, 0.65]].map(v2), knot: fl([0, 0, 1, 1]), order: 2, weight: [], tessellation: 0 },
        { point: arcPts.map(([x, y], i) => v2([x * arcW[i], y * arcW[i]])), knot: fl([0, 0, 0, 1, 1, 2, 2, 2]), order: 3, weight: fl(arcW), tessellation: 0 },
        { point: [[0.4, 0.65], [0.4, 0.4], [0.8, 0.4], [0.8, 0.2], [0.2, 0.2]].map(v2) },
      ] },
    ],
  });
  const sl = meshStats(rl);
  const lArea = 0.6 * 0.2 + 0.2 * 0.25 + Math.PI * 0.1 * 0.1 / 2; // (u,v): bar, leg, half disc
  const expectL = 4 * (1 - lArea);
  check('TrimmedSurface: square minus L-shaped hole (NurbsCurve2D + Polyline2D, non-convex)', sl.area > expectL && sl.area - expectL < 4 * 0.003 * Math.PI * 0.01 / 2 && sl.negative === 0,
    `area ${sl.area.toFixed(6)}, exact ${expectL.toFixed(6)}`);
  // handrail-like lid profile (fixture trimmed_profile.wrl): one order-3 NurbsCurve2D of
  // 7 segments (lines, two concave quarter arcs, a convex half circle), double knots
  const segs = [
    [[0.5, 0.1], [0.7, 0.1], 1], [[0.7, 0.25], [0.7, 0.4], 1], [[0.7, 0.5], [0.8, 0.5], W], [[0.8, 0.8], [0.5, 0.8], W],
    [[0.2, 0.8], [0.2, 0.5], W], [[0.3, 0.5], [0.3, 0.4], W], [[0.3, 0.25], [0.3, 0.1], 1],
  ];
  const pp = [[0.3, 0.1]], pw = [1], pk = [0, 0, 0];
  segs.forEach(([m, e, w], k) => { pp.push(m, e); pw.push(w, 1); if (k < 6) pk.push(k + 1, k + 1); });
  pk.push(7, 7, 7);
  const rp = run(trimScript, { surface: plane, trimmingContour: [{ children: [
    { point: pp.map(([x, y], i) => v2([x * pw[i], y * pw[i]])), knot: fl(pk), order: 3, weight: fl(pw), tessellation: 0 }] }] });
  const sp = meshStats(rp), exactP = 4 * (0.18 + 0.04 * Math.PI);
  check('TrimmedSurface: handrail-like lid profile (one curve, concave and convex arcs)', sp.area < exactP && exactP - sp.area < 0.003 * exactP && sp.negative === 0,
    `area ${sp.area.toFixed(6)}, exact ${exactP.toFixed(6)}`);
  // curved trimmed surface: the quarter cylinder trimmed to a band v in [0.25, 0.75]
  const rb = run(trimScript, { surface: cylinder, trimmingContour: [{ children: [{ point: [[0, 0.25], [1, 0.25], [1, 0.75], [0, 0.75], [0, 0.25]].map(v2) }] }] });
  let ok = rb.points.length > 0;
  for (const p of rb.points) if (Math.abs(Math.hypot(p.x, p.y) - 1) > 1e-6 || p.z < -0.5 - 1e-6 || p.z > 0.5 + 1e-6) ok = false;
  check('TrimmedSurface: trimmed quarter cylinder band on the cylinder, z -0.5..0.5', ok, `${rb.points.length} points`);
}

// ------------------------------------------------------------------ tessellation counts
{
  // ellipsoid u: 4 equal spans; uTessellation 10 -> ceil(10/4) = 3 steps a span -> 13 values
  const r = run(surfaceScript, { ...ellipsoid, uTessellation: 10, vTessellation: 0 });
  check('NurbsSurface: uTessellation > 0 shared among the spans, rounded up (10 over 4 spans -> 12 steps)', r.points.length === 13 * 17, `${r.points.length} points`);
  // quarter cylinder u: 3 control points; uTessellation -2 -> 2 x 3 = 6 steps
  const n = run(surfaceScript, { ...cylinder, uTessellation: -2 });
  check('NurbsSurface: uTessellation < 0 means -value x control points steps (-2 x 3 = 6)', n.points.length === 7 * 2, `${n.points.length} points`);
  // a trimming circle of 4 quadratic spans with tessellation 10: 3 chords a span
  const c = run(trimScript, { surface: plane, trimmingContour: [{ children: [{ ...circleCurve(0.5, 0.5, 0.3), tessellation: 10 }] }] });
  let onLoop = 0;
  for (const p of c.points) if (Math.abs(Math.hypot(p.x, p.y) - 0.6) < 1e-5) ++onLoop;
  check('NurbsCurve2D: tessellation > 0 shared among the spans, rounded up (10 over 4 spans -> 12 chords)', onLoop === 12, `${onLoop} points on the circle`);
}

// ------------------------------------------------------------------ triangulation size and T junctions
function edgeCounts(tris) {
  const m = new Map();
  for (const [a, b, c] of tris)
    for (const [p, q] of [[a, b], [b, c], [c, a]]) {
      const k = p < q ? `${p} ${q}` : `${q} ${p}`;
      m.set(k, (m.get(k) ?? 0) + 1);
    }
  return m;
}
{
  // a 400-sided polygon hole in a plane tessellated 40 x 40
  const N = 400, hole = [];
  for (let i = 0; i <= N; ++i) { const a = -2 * Math.PI * i / N; hole.push([0.5 + 0.35 * Math.cos(a), 0.5 + 0.35 * Math.sin(a)]); }
  const fine = { ...plane, uTessellation: 40, vTessellation: 40 };
  const r = run(trimScript, { surface: fine, trimmingContour: [{ children: [{ point: hole.map(v2) }] }] });
  const st = meshStats(r), exact = 4 * (1 - N / 2 * 0.35 * 0.35 * Math.sin(2 * Math.PI / N));
  check('TrimmedSurface: 400-gon hole in a 40 x 40 grid: area exact', Math.abs(st.area - exact) < 1e-5 && st.negative === 0, `area ${st.area.toFixed(6)}, exact ${exact.toFixed(6)}`);
  // grid cells 1600 x 2 triangles plus a few per loop vertex and crossing; the product
  // of loop vertices and grid lines (400 x 40) would be far more
  check('TrimmedSurface: triangles grow with loop + grid, not their product', r.tris.length < 2 * 1600 + 8 * N, `${r.tris.length} triangles`);
  // every edge used once lies on the loop (radius 0.7 in space) or the square's border
  let inner = 0;
  for (const [k, c] of edgeCounts(r.tris)) {
    if (c !== 1) continue;
    const [a, b] = k.split(' ').map(Number);
    for (const p of [r.points[a], r.points[b]]) {
      const onHole = Math.abs(Math.hypot(p.x, p.y) - 0.7) < 1e-3, onBorder = Math.max(Math.abs(p.x), Math.abs(p.y)) > 1 - 1e-6;
      if (!onHole && !onBorder) ++inner;
    }
  }
  check('TrimmedSurface: no T junctions (every edge off the loop shared by two triangles)', inner === 0, `${inner} loose edge ends inside`);
  // the L-shaped hole and the lid profile: same property
  for (const [name, fields] of [['disc', { surface: fine, trimmingContour: [{ children: [circleCurve(0.45, 0.55, 0.35)] }] }],
    ['profile on a curved surface', { surface: { ...cylinder, uTessellation: 24, vTessellation: 12 }, trimmingContour: [{ children: [{ point: [[0.1, 0.1], [0.9, 0.2], [0.7, 0.9], [0.5, 0.4], [0.2, 0.8], [0.1, 0.1]].map(v2) }] }] }]]) {
    const q = run(trimScript, fields), counts = edgeCounts(q.tris);
    const used = new Map();
    for (const [k, c] of counts) if (c === 1) for (const v of k.split(' ')) used.set(v, (used.get(v) ?? 0) + 1);
    // on a closed boundary every loose vertex has exactly two loose edges
    const odd = [...used.values()].filter((c) => c !== 2).length;
    check(`TrimmedSurface: ${name}: boundary is one closed chain (no T junctions)`, odd === 0 && q.tris.length > 0, `${odd} vertices with an odd boundary`);
  }
}

// ------------------------------------------------------------------ NurbsPositionInterpolator
// The path Script evaluated at fractions: a rational quarter circle (keyValue as w*P), and the
// same fields as X_ITE hands them (getValue()) giving the very same points.
{
  const pathScript = scriptOf('NurbsPositionInterpolator');
  const at = (fields, fractions) => {
    const env = { ...sandbox, print: () => {}, value_changed: null, ...fields };
    const names = Object.keys(env);
    const fn = new Function(...names, 'fractions', pathScript + '\nvar out = [];\n' +
      'for (var i = 0; i < fractions.length; ++i) { set_fraction(fractions[i]); out.push(value_changed); }\nreturn out;');
    return fn(...names.map((n) => env[n]), fractions);
  };
  const quarter = { order: 3, knot: fl([0, 0, 0, 1, 1, 1]), keyValue: [[1, 0, 0], [W, W, 0], [0, 1, 0]].map(v3), keyWeight: fl([1, W, 1]) };
  const fractions = [-0.5, 0, 0.1, 0.25, 0.5, 0.75, 0.9, 1, 1.5];
  const a = at(quarter, fractions);
  const radial = Math.max(...a.map((p) => Math.abs(Math.hypot(p.x, p.y) - 1)));
  check('NurbsPositionInterpolator: a rational quarter circle stays on radius 1', radial < 1e-6, `max error ${radial.toExponential(2)}`);
  check('NurbsPositionInterpolator: fractions clamped to [0, 1], ends at the end points',
    a[0].x === 1 && a[0].y === 0 && a[1].x === 1 && Math.abs(a[7].y - 1) < 1e-6 && a[8].y === a[7].y);
  const mid = a[4];
  check('NurbsPositionInterpolator: fraction 0.5 at 45 degrees', Math.abs(mid.x - mid.y) < 1e-6);
  const b = at({ order: 3, knot: xiteFields(quarter.knot), keyValue: xiteFields(quarter.keyValue), keyWeight: xiteFields(quarter.keyWeight) }, fractions);
  check('NurbsPositionInterpolator: X_ITE fast path identical', a.every((p, i) => p.x === b[i].x && p.y === b[i].y && p.z === b[i].z));
  // a cubic with an interior double knot: fraction 0.5 lands on the control point such a knot pins
  const cubic = { order: 4, knot: fl([0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1]), keyValue: [[0, 0, 0], [1, 2, 0], [2, 2, 0], [3, 0, 0], [4, 1, 0], [5, 1, 0], [6, 0, 0]].map(v3), keyWeight: [] };
  const c = at(cubic, [0.5, 1]);
  check('NurbsPositionInterpolator: a knot repeated degree times pins its control point', c[0].x === 3 && c[0].y === 0 && c[1].x === 6, `${JSON.stringify(c)}`);
}

// ------------------------------------------------------------------ NurbsCurve
// The curve Script's polyline: a rational quarter circle (controlPoint as w*P) lies on radius 1 at
// every sample, 12 steps (6 x degree 2) from end to end; X_ITE's getValue() fields give the same points.
{
  const curveScript = scriptOf('NurbsCurve');
  const quarter = { order: 3, knot: fl([0, 0, 0, 1, 1, 1]), controlPoint: [[1, 0, 0], [W, W, 0], [0, 1, 0]].map(v3), weight: fl([1, W, 1]), tessellation: 0 };
  const line = (fields) => {
    const env = { ...sandbox, print: () => {}, coord: {}, ...fields };
    const names = Object.keys(env);
    const fn = new Function(...names, 'var coordIndex_changed = null;\n' + curveScript + '\ninitialize();\nreturn coordIndex_changed;');
    const index = fn(...names.map((n) => env[n]));
    return { points: env.coord.point ?? [], index: index ?? [] };
  };
  const a = line(quarter);
  const radial = Math.max(...a.points.map((p) => Math.abs(Math.hypot(p.x, p.y) - 1)));
  check('NurbsCurve: a rational quarter circle lies on radius 1', a.points.length === 13 && radial < 1e-6,
    `${a.points.length} points, max error ${radial.toExponential(2)}`);
  check('NurbsCurve: one polyline through every point', a.index.length === 14 && a.index[13] === -1 && a.index[12] === 12);
  check('NurbsCurve: ends at the end points', a.points[0].x === 1 && Math.abs(a.points[12].y - 1) < 1e-6);
  const b = line({ ...quarter, knot: xiteFields(quarter.knot), controlPoint: xiteFields(quarter.controlPoint), weight: xiteFields(quarter.weight) });
  check('NurbsCurve: X_ITE fast path identical', a.points.every((p, i) => p.x === b.points[i].x && p.y === b.points[i].y));
}

// ------------------------------------------------------------------ 4. X_ITE fast paths
// Fields as X_ITE hands them to a Script: MF fields with getValue() (their typed array) and
// live Coordinate / Normal fields with setValue(); runScript's stand-ins take both.
function xiteFields(value) {
  if (Array.isArray(value)) {
    if (value.length && typeof value[0] === 'object' && value[0] !== null && 'x' in value[0]) {
      const c = 'z' in value[0] ? 3 : 2, flat = new Float32Array(value.length * c + 4);
      value.forEach((e, i) => { flat[c * i] = e.x; flat[c * i + 1] = e.y; if (c === 3) flat[c * i + 2] = e.z; });
      const out = value.slice();
      out.getValue = () => flat;
      return out;
    }
    if (value.length && typeof value[0] === 'number') {
      const out = value.slice(), flat = Float32Array.from(value);
      out.getValue = () => flat;
      return out;
    }
    return value.map(xiteFields);
  }
  if (value && typeof value === 'object') return Object.fromEntries(Object.entries(value).map(([k, v]) => [k, xiteFields(v)]));
  return value;
}
for (const [name, script, fields] of [
  ['NurbsSurface ellipsoid', surfaceScript, ellipsoid],
  ['TrimmedSurface disc', trimScript, { surface: plane, trimmingContour: [{ children: [circleCurve(0.45, 0.55, 0.35)] }] }],
  ['TrimmedSurface cylinder band', trimScript, { surface: cylinder, trimmingContour: [{ children: [{ point: [[0, 0.25], [1, 0.25], [1, 0.75], [0, 0.75], [0, 0.25]].map(v2) }] }] }],
]) {
  const a = run(script, fields), b = runScript(script, xiteFields(fields), { bulk: true });
  const same = a.points.length === b.points.length && a.tris.length === b.tris.length
    && a.points.every((p, i) => p.x === b.points[i].x && p.y === b.points[i].y && p.z === b.points[i].z)
    && a.normals.every((p, i) => p.x === b.normals[i].x && p.y === b.normals[i].y && p.z === b.normals[i].z)
    && a.tris.every((t, i) => t.every((v, j) => v === b.tris[i][j]));
  check(`fast paths: ${name} identical to the element-by-element paths`, same && b.points.length > 0, `${a.points.length} / ${b.points.length} points`);
}

console.log(`${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
