// Runs the ECMAScript of cadnurbs' VRML97 implementation PROTOs in node, without a browser:
// the same Script text a browser runs, with its fields given as plain values rounded to single
// precision (as a browser stores MFFloat / MFVec3f) and minimal MFVec3f / MFInt32 / SFVec3f
// stand-ins. Used by check_protos.mjs (analytic shapes) and run_protos.mjs (converted files).

import fs from 'node:fs';

// The PROTOs of a library written to the contract in the file's header:
// { name: { iface: ['field SFInt32 uDimension 0', ...], body } }, plus layout errors.
export function parseProtoLibrary(text) {
  const lines = text.split('\n');
  const protos = {};
  const errors = [];
  if (lines[0] !== '#VRML V2.0 utf8') errors.push('line 1 is not "#VRML V2.0 utf8"');
  let i = 1;
  while (i < lines.length) {
    const line = lines[i];
    if (line.trim() === '' || line.startsWith('#')) { ++i; continue; }
    const m = /^PROTO (\w+) \[$/.exec(line);
    if (!m) { errors.push(`line ${i + 1}: unexpected top-level text: ${line}`); ++i; continue; }
    const name = m[1], iface = [];
    ++i;
    while (i < lines.length && lines[i] !== '] {') {
      const d = /^  (field|exposedField|eventIn|eventOut) (\w+) (\w+)(?: (\S.*))?$/.exec(lines[i]);
      if (!d) errors.push(`line ${i + 1}: not an interface declaration: ${lines[i]}`);
      else iface.push(`${d[1]} ${d[2]} ${d[3]}${d[4] !== undefined ? ' ' + d[4] : ''}`);
      ++i;
    }
    const bodyStart = ++i;
    while (i < lines.length && lines[i] !== '}') ++i;
    if (i >= lines.length) errors.push(`PROTO ${name}: no closing "}" line`);
    protos[name] = { iface, body: lines.slice(bodyStart, i).join('\n') };
    ++i;
  }
  return { protos, errors };
}

export function loadProtoLibrary(file) {
  return parseProtoLibrary(fs.readFileSync(file, 'utf8'));
}

// The text after "javascript:" of the PROTO's Script, or null.
export function scriptOf(protos, name) {
  const body = protos[name]?.body ?? '';
  const m = /url \[?\s*"javascript:([^"]*)"/.exec(body);
  return m ? m[1] : null;
}

export const f32 = Math.fround;

// Browser-like MF fields: an Array; setValue(flat numbers) is X_ITE's bulk assignment, which
// the Scripts use when a field offers it (so both paths get run: see `bulk` below).
class MFVec3fStandIn extends Array {
  setValue(flat) {
    this.length = 0;
    for (let i = 0; i + 2 < flat.length; i += 3) this.push({ x: f32(flat[i]), y: f32(flat[i + 1]), z: f32(flat[i + 2]) });
  }
}
class MFInt32StandIn extends Array {
  setValue(flat) {
    this.length = 0;
    for (const v of flat) this.push(v | 0);
  }
}

// Runs `script` (Script source without "javascript:") with `fields` as its fields and calls
// initialize(). bulk = false hides setValue, so the Scripts take the standard element-wise path.
// Returns { points: [{x,y,z}], normals, tris: [[a,b,c]], messages, seconds }.
export function runScript(script, fields, { bulk = true } = {}) {
  const messages = [];
  const MFVec3f = bulk ? MFVec3fStandIn : class extends Array {};
  const MFInt32 = bulk ? MFInt32StandIn : class extends Array {};
  const SFVec3f = function SFVec3f(x, y, z) { return { x: f32(x), y: f32(y), z: f32(z) }; };
  const coord = {}, normal = {};
  if (bulk) {
    // A live node's field is a field object too: the Script may call setValue on it.
    coord.point = new MFVec3f();
    normal.vector = new MFVec3f();
  }
  // NurbsSurface's Script reads its control points from the PROTO's Coordinate node (control.point).
  const control = { point: fields.controlPoint };
  const env = { MFVec3f, MFInt32, SFVec3f, print: (m) => messages.push(String(m)), coord, normal, control, ...fields };
  const names = Object.keys(env);
  const fn = new Function(...names, 'var coordIndex_changed = null;\n' + script + '\nvar t0 = Date.now();\ninitialize();\nreturn [coordIndex_changed, (Date.now() - t0) / 1000];');
  const [index, seconds] = fn(...names.map((n) => env[n]));
  const tris = [];
  for (let i = 0; index && i < index.length; i += 4) tris.push([index[i], index[i + 1], index[i + 2]]);
  const points = coord.point ?? [], normals = normal.vector ?? [];
  return { points: Array.from(points), normals: Array.from(normals), tris, messages, seconds };
}
