#!/usr/bin/env node
// Runs the PROTO Scripts of cadnurbs-nurbs-protos.wrl in node on every TrimmedSurface and
// NurbsSurface of a converted VRML97 file, as a browser with scripting would, and prints what
// they produce and how long they take (no browser: the time is the Scripts' own).
//
//   run_protos.mjs FILE.wrl [--protos PROTO_FILE] [--json]
//
// Reads the classic-encoding subset cadnurbs writes (nodes, DEF/USE, EXTERNPROTO and PROTO
// statements are skipped, ROUTEs ignored). Prints one line: instances, vertices, triangles,
// Script seconds, and the messages the Scripts printed (warnings). A NurbsSurface held by a
// TrimmedSurface is not run on its own (a browser runs it too, into a mesh nobody draws).
// Exit 1 when a Script throws.

import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadProtoLibrary, scriptOf, runScript, f32 } from './protos_sandbox.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
let protoFile = path.join(here, '../../formats/vrml/protos/cadnurbs-nurbs-protos.wrl');
let json = false;
const files = [];
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--protos') protoFile = args[++i];
  else if (args[i] === '--json') json = true;
  else files.push(args[i]);
}
if (files.length !== 1) {
  process.stderr.write('usage: run_protos.mjs FILE.wrl [--protos PROTO_FILE] [--json]\n');
  process.exit(2);
}

// ------------------------------------------------------------------ tokenizer and parser
function tokenize(text) {
  const tokens = [];
  const re = /[\s,]+|#[^\n]*|"(?:[^"\\]|\\.)*"|[[\]{}]|[^\s,[\]{}"#]+/gy;
  let m;
  while ((m = re.exec(text))) {
    const t = m[0];
    if (/^[\s,]/.test(t) || t[0] === '#') continue;
    tokens.push(t);
  }
  return tokens;
}

const { protos } = loadProtoLibrary(protoFile);
// Field types and defaults from the PROTO interfaces: types[node][field] = 'MFVec3f', ...
const types = {}, defaults = {};
for (const [name, p] of Object.entries(protos)) {
  types[name] = {};
  defaults[name] = {};
  for (const d of p.iface) {
    const [, type, field, ...rest] = d.split(' ');
    types[name][field] = type;
    defaults[name][field] = rest.join(' ');
  }
}

function convert(type, raw) {
  const nums = () => raw.filter((t) => typeof t === 'string').map(Number);
  switch (type) {
    case 'SFInt32': return Number(raw[0]) | 0;
    case 'SFFloat': return f32(Number(raw[0]));
    case 'SFBool': return raw[0] === 'TRUE';
    case 'MFFloat': return nums().map(f32);
    case 'MFInt32': return nums().map((v) => v | 0);
    case 'MFVec2f': { const n = nums(), out = []; for (let i = 0; i + 1 < n.length; i += 2) out.push({ x: f32(n[i]), y: f32(n[i + 1]) }); return out; }
    case 'MFVec3f': { const n = nums(), out = []; for (let i = 0; i + 2 < n.length; i += 3) out.push({ x: f32(n[i]), y: f32(n[i + 1]), z: f32(n[i + 2]) }); return out; }
    case 'SFNode': return raw.find((v) => typeof v === 'object') ?? null;
    case 'MFNode': return raw.filter((v) => typeof v === 'object');
    default: return raw;
  }
}

function parse(tokens) {
  let i = 0;
  const defs = {};
  const roots = [];
  const skipBracketed = () => {
    const open = tokens[i], close = open === '[' ? ']' : '}';
    let depth = 0;
    do {
      if (tokens[i] === open) ++depth;
      else if (tokens[i] === close) --depth;
      ++i;
    } while (depth > 0 && i < tokens.length);
  };
  function node() {
    let def = null;
    if (tokens[i] === 'USE') { i += 2; return defs[tokens[i - 1]]; }
    if (tokens[i] === 'NULL') { ++i; return null; }
    if (tokens[i] === 'DEF') { def = tokens[i + 1]; i += 2; }
    const type = tokens[i++];
    const n = { type, fields: {} };
    if (def) defs[def] = n;
    if (tokens[i] !== '{') throw new Error(`expected { after ${type}`);
    ++i;
    while (tokens[i] !== '}') {
      const name = tokens[i++];
      const raw = [];
      const value = () => {
        const t = tokens[i];
        if (t === 'DEF' || t === 'USE' || t === 'NULL' || (/^[A-Z]/.test(t) && tokens[i + 1] === '{')) raw.push(node());
        else { raw.push(t); ++i; }
      };
      if (tokens[i] === '[') {
        ++i;
        while (tokens[i] !== ']') value();
        ++i;
      } else if (/^[A-Z]/.test(tokens[i]) && tokens[i + 1] === '{' || tokens[i] === 'DEF' || tokens[i] === 'USE' || tokens[i] === 'NULL') {
        value();
      } else {
        // scalars up to the next field name or the closing brace
        do { raw.push(tokens[i++]); } while (tokens[i] !== '}' && /^[-+.\d]|^TRUE$|^FALSE$|^"/.test(tokens[i]));
      }
      n.fields[name] = raw;
    }
    ++i;
    return n;
  }
  while (i < tokens.length) {
    const t = tokens[i];
    if (t === 'EXTERNPROTO') { i += 2; skipBracketed(); skipBracketed(); continue; }
    if (t === 'PROTO') { i += 2; skipBracketed(); skipBracketed(); continue; }
    if (t === 'ROUTE') { i += 4; continue; }
    if (t === 'PROFILE' || t === 'COMPONENT' || t === 'META' || t === 'UNIT') { i += t === 'META' ? 3 : t === 'UNIT' ? 4 : 2; continue; }
    roots.push(node());
  }
  return roots;
}

// Field values of a parsed node as the Script sees them (PROTO defaults filled in).
function scriptFields(n) {
  const t = types[n.type];
  if (!t) return null;
  const out = {};
  for (const f of Object.keys(t)) {
    const raw = n.fields[f] ?? (defaults[n.type][f] !== undefined ? tokenize(defaults[n.type][f]).filter((x) => x !== '[' && x !== ']') : []);
    out[f] = convert(t[f], raw.map((v) => (typeof v === 'object' && v !== null ? scriptFields(v) ?? v : v)));
  }
  return out;
}

// ------------------------------------------------------------------ run
const roots = parse(tokenize(fs.readFileSync(files[0], 'utf8').replace(/^#X3D[^\n]*|^#VRML[^\n]*/, '')));
const geometry = [];
(function walk(list) {
  for (const n of list) {
    if (!n || typeof n !== 'object') continue;
    for (const [name, raw] of Object.entries(n.fields)) {
      if (name === 'geometry') {
        const g = raw.find((v) => typeof v === 'object' && v);
        if (g && (g.type === 'TrimmedSurface' || g.type === 'NurbsSurface')) geometry.push(g);
      }
      walk(raw.filter((v) => typeof v === 'object'));
    }
  }
})(roots);

const scripts = { TrimmedSurface: scriptOf(protos, 'TrimmedSurface'), NurbsSurface: scriptOf(protos, 'NurbsSurface') };
let vertices = 0, triangles = 0, seconds = 0, failed = 0;
const messages = new Map();
const start = Date.now();
for (const g of geometry) {
  try {
    const r = runScript(scripts[g.type], scriptFields(g));
    vertices += r.points.length;
    triangles += r.tris.length;
    seconds += r.seconds;
    for (const m of r.messages) messages.set(m, (messages.get(m) ?? 0) + 1);
  } catch (e) {
    ++failed;
    messages.set(`Script threw: ${e.message}`, (messages.get(`Script threw: ${e.message}`) ?? 0) + 1);
  }
}
const result = {
  file: path.basename(files[0]), instances: geometry.length, vertices, triangles,
  script_seconds: Number(seconds.toFixed(3)), total_seconds: (Date.now() - start) / 1000, failed,
  messages: [...messages.entries()].map(([m, c]) => (c > 1 ? `${c}x ${m}` : m)),
};
if (json) console.log(JSON.stringify(result));
else {
  console.log(`${result.file}: ${result.instances} surfaces, ${vertices} vertices, ${triangles} triangles, Scripts ${result.script_seconds} s${failed ? `, ${failed} failed` : ''}`);
  for (const m of result.messages.slice(0, 20)) console.log(`  ${m}`);
}
process.exit(failed ? 1 : 0);
