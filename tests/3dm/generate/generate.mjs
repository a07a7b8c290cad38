// Writes .3dm test files with McNeel's rhino3dm (openNURBS compiled to WebAssembly) and, beside each, a
// JSON file with exactly what rhino3dm reports when it reads that file back: class, name, layer, and every
// order, count, knot, control point and weight. The native reader's tests (tests/3dm/rhino3dm_exact_test.cpp)
// compare their own reading of the same files against these values bit for bit.
//
//   node generate.mjs OUT_DIR
//
// Writes OUT_DIR/<group>_v<archive version>.3dm and .json for the groups curves, surfaces, breps, meshes and
// every archive version rhino3dm writes (File3dmWriteOptions.version 2..8 give archive versions 2, 3, 4, 50,
// 60, 70, 80; 0 and anything above 8 give 80), then OUT_DIR/index.json listing them. Deterministic: the
// same rhino3dm gives the same values (the random geometry comes from a fixed-seed generator).
//
// Numbers are written as JavaScript prints them (the shortest decimal that reads back as the same double),
// so strtod recovers each bit for bit; -0 is written as -0. Control points are what rhino3dm's getters
// return, which is openNURBS's stored (homogeneous) form: [w*x, w*y, w*z, w] ("point_style": "homogeneous";
// checked below on a rational circle, whose corner point must come back as radius*(1,1)*w).
import rhino3dm from 'rhino3dm';
import fs from 'node:fs';
import path from 'node:path';
import { createRequire } from 'node:module';

const outDir = process.argv[2];
if (!outDir) {
  console.error('usage: node generate.mjs OUT_DIR');
  process.exit(2);
}
fs.mkdirSync(outDir, { recursive: true });

const rh = await rhino3dm();
const rhinoVersion = createRequire(import.meta.url)('rhino3dm/package.json').version;

// Class ids openNURBS writes (ON_OBJECT_IMPLEMENT in its sources), for the names in the JSON.
const classNames = {
  '4ED7D4DD-E947-11D3-BFE5-0010830122F0': 'ON_NurbsCurve',
  '4ED7D4DE-E947-11D3-BFE5-0010830122F0': 'ON_NurbsSurface',
  '4ED7D4DF-E947-11D3-BFE5-0010830122F0': 'ON_PlaneSurface',
  'A16220D3-163B-11D4-8000-0010830122F0': 'ON_RevSurface',
  'C4CD5359-446D-4690-9FF5-29059732472B': 'ON_SumSurface',
  '4ED7D4E2-E947-11D3-BFE5-0010830122F0': 'ON_SurfaceProxy',
  'CF33BE2A-09B4-11D4-BFFB-0010830122F0': 'ON_ArcCurve',
  '4ED7D4DB-E947-11D3-BFE5-0010830122F0': 'ON_LineCurve',
  '4ED7D4E6-E947-11D3-BFE5-0010830122F0': 'ON_PolylineCurve',
  '4ED7D4E0-E947-11D3-BFE5-0010830122F0': 'ON_PolyCurve',
  '4ED7D4D9-E947-11D3-BFE5-0010830122F0': 'ON_CurveProxy',
  '60B5DBC5-E660-11D3-BFE4-0010830122F0': 'ON_Brep',
  '4ED7D4E4-E947-11D3-BFE5-0010830122F0': 'ON_Mesh',
};

// The class id of an object, from the archive rhino3dm's encode() writes: a TCODE_OPENNURBS_CLASS chunk
// whose first chunk (TCODE_OPENNURBS_CLASS_UUID) holds the id. Chunk lengths are 8 bytes from archive
// version 50 on, 4 before.
function classId(object) {
  const encoded = object.encode();
  const data = Buffer.from(encoded.data, 'base64');
  const lengthSize = encoded.archive3dm >= 50 ? 8 : 4;
  if (data.readUInt32LE(0) !== 0x00027ffa || data.readUInt32LE(4 + lengthSize) !== 0x0002fffb) {
    throw new Error('encode() did not start with a class chunk');
  }
  const b = data.subarray(2 * (4 + lengthSize), 2 * (4 + lengthSize) + 16);
  const hex = (buf) => Buffer.from(buf).toString('hex').toUpperCase();
  const d1 = hex([b[3], b[2], b[1], b[0]]);
  const d2 = hex([b[5], b[4]]);
  const d3 = hex([b[7], b[6]]);
  return `${d1}-${d2}-${d3}-${hex(b.subarray(8, 10))}-${hex(b.subarray(10, 16))}`;
}
const classOf = (object) => {
  const id = classId(object);
  return { class: classNames[id] ?? id, class_id: id };
};

// Fixed-seed 53-bit uniform numbers in [0, 1) (xorshift128+), so the files are the same every run.
let s0 = 0x9e3779b97f4a7c15n, s1 = 0xbf58476d1ce4e5b9n;
const mask = (1n << 64n) - 1n;
function random() {
  let x = s0;
  const y = s1;
  s0 = y;
  x = (x ^ (x << 23n)) & mask;
  s1 = x ^ y ^ (x >> 17n) ^ (y >> 26n);
  return Number(((s1 + y) & mask) >> 11n) / 2 ** 53;
}
const between = (lo, hi) => lo + (hi - lo) * random();

// Knots as openNURBS keeps them (order + count - 2 values, the two end knots left out): clamped (order - 1
// equal values at each end) with random increasing interior knots, or all distinct (unclamped).
function makeKnots(order, count, clamped) {
  const n = order + count - 2;
  const knots = [];
  if (clamped) {
    const start = between(-2, 2);
    const interior = [];
    let t = start;
    for (let i = 0; i < count - order; ++i) interior.push((t += between(0.1, 1.5)));
    const end = t + between(0.1, 1.5);
    for (let i = 0; i < order - 1; ++i) knots.push(start);
    knots.push(...interior);
    for (let i = 0; i < order - 1; ++i) knots.push(end);
  } else {
    let t = between(-2, 2);
    for (let i = 0; i < n; ++i) knots.push((t += between(0.1, 1.5)));
  }
  if (knots.length !== n) throw new Error('knot count');
  return knots;
}

function nurbsCurve(dimension, rational, order, count, clamped = true) {
  const curve = new rh.NurbsCurve(dimension, rational, order, count);
  const knots = makeKnots(order, count, clamped);
  const list = curve.knots();
  knots.forEach((k, i) => list.set(i, k));
  for (let i = 0; i < count; ++i) {
    const w = rational ? between(0.3, 3) : 1;
    const z = dimension === 3 ? between(-5, 5) * w : 0;
    curve.points().set(i, [between(-5, 5) * w, between(-5, 5) * w, z, w]);
  }
  if (!curve.isValid) throw new Error(`invalid curve d${dimension} o${order}`);
  return curve;
}

function nurbsSurface(rational, orderU, orderV, countU, countV) {
  const surface = rh.NurbsSurface.create(3, rational, orderU, orderV, countU, countV);
  makeKnots(orderU, countU, true).forEach((k, i) => surface.knotsU().set(i, k));
  makeKnots(orderV, countV, true).forEach((k, i) => surface.knotsV().set(i, k));
  for (let u = 0; u < countU; ++u) {
    for (let v = 0; v < countV; ++v) {
      const w = rational ? between(0.3, 3) : 1;
      surface.points().set(u, v, [(u + between(-0.3, 0.3)) * w, (v + between(-0.3, 0.3)) * w, between(-1, 1) * w, w]);
    }
  }
  if (!surface.isValid) throw new Error(`invalid surface ${orderU}x${orderV}`);
  return surface;
}

// What rhino3dm reports of a NURBS curve / surface.
function curveValues(curve) {
  const points = [];
  for (let i = 0; i < curve.points().count; ++i) points.push(curve.points().get(i));
  return {
    dimension: curve.dimension,
    order: curve.order,
    count: curve.points().count,
    rational: curve.isRational,
    knots: curve.knots().toList(),
    points,
  };
}
function surfaceValues(surface) {
  const list = surface.points();
  const points = [];  // u fastest, as the core model orders them: index u + v * count_u
  for (let v = 0; v < list.countV; ++v) for (let u = 0; u < list.countU; ++u) points.push(list.get(u, v));
  return {
    order_u: surface.orderU,
    order_v: surface.orderV,
    count_u: list.countU,
    count_v: list.countV,
    rational: surface.isRational,
    knots_u: surface.knotsU().toList(),
    knots_v: surface.knotsV().toList(),
    points,
  };
}

// The values of one object read back from a file. `exact`: the NURBS values are the file's own doubles (the
// object is stored as NURBS); otherwise they are rhino3dm's NURBS form of another class (arc, plane,
// revolution), computed, so a reader's own conversion can agree only to rounding.
function objectValues(object, index, doc) {
  const geometry = object.geometry();
  const attributes = object.attributes();
  const out = { index, name: attributes.name, layer_index: attributes.layerIndex, ...classOf(geometry) };
  if (out.class === 'ON_Mesh') {
    const vertices = [], faces = [];
    for (let i = 0; i < geometry.vertices().count; ++i) vertices.push(geometry.vertices().get(i));
    for (let i = 0; i < geometry.faces().count; ++i) {
      const f = geometry.faces().get(i);
      faces.push(f[2] === f[3] ? f.slice(0, 3) : f);  // openNURBS stores a triangle as a quad with c == d
    }
    out.mesh = { vertices, faces, quad_count: geometry.faces().quadCount, triangle_count: geometry.faces().triangleCount };
  } else if (out.class === 'ON_Brep') {
    const faces = [];
    for (let i = 0; i < geometry.faces().count; ++i) {
      const face = geometry.faces().get(i);
      const surface = face.underlyingSurface();
      const loops = [];
      for (let l = 0; l < face.loops.count; ++l) {
        const loop = face.loops.get(l);
        const trims = [];
        for (let t = 0; t < loop.trims.count; ++t) {
          const trim = loop.trims.get(t);
          trims.push({ edge: trim.edgeIndex, reversed: trim.isReversed });
        }
        loops.push({ type: loop.loopType.value, trims });
      }
      const { class: surfaceClass, class_id } = classOf(surface);
      faces.push({
        reversed: face.orientationIsReversed,
        surface_class: surfaceClass,
        surface_class_id: class_id,
        exact: surfaceClass === 'ON_NurbsSurface',
        nurbs_surface: surfaceValues(surface.toNurbsSurface()),
        loops,
      });
    }
    out.brep = { faces, edge_count: geometry.edges().count, vertex_count: geometry.vertices().count };
  } else if (out.class.endsWith('Surface')) {
    out.exact = out.class === 'ON_NurbsSurface';
    out.nurbs_surface = surfaceValues(geometry.toNurbsSurface());
  } else if (out.class.endsWith('Curve')) {
    // Lines and polylines: the NURBS form copies the stored points and parameters, so it is exact too.
    out.exact = ['ON_NurbsCurve', 'ON_LineCurve', 'ON_PolylineCurve'].includes(out.class);
    out.nurbs_curve = curveValues(geometry.toNurbsCurve());
  }
  return out;
}

// One model per group, the same for every version. Each object gets a name and a layer of its group.
function buildModel(group) {
  const doc = new rh.File3dm();
  const units = { curves: 'Millimeters', surfaces: 'Inches', breps: 'Meters', meshes: 'Centimeters' }[group];
  doc.settings().modelUnitSystem = rh.UnitSystem[units];
  const layers = [
    { name: `${group}_a`, color: { r: 200, g: 30, b: 30, a: 255 } },
    { name: `${group}_b`, color: { r: 20, g: 120, b: 240, a: 255 } },
  ];
  const layerIndex = layers.map((l) => {
    const layer = new rh.Layer();
    layer.name = l.name;
    layer.color = l.color;
    return doc.layers().add(layer);
  });
  let serial = 0;
  const add = (kind, name, geometry) => {
    const attributes = new rh.ObjectAttributes();
    attributes.name = name;
    attributes.layerIndex = layerIndex[serial++ % 2];
    const id = doc.objects()[kind](geometry, attributes);
    if (!id || /^0{8}-/.test(id)) throw new Error(`rhino3dm refused ${name}`);
  };

  if (group === 'curves') {
    for (const dimension of [2, 3]) {
      for (const rational of [false, true]) {
        for (let degree = 1; degree <= 5; ++degree) {
          const order = degree + 1;
          add('addCurve', `nurbs_d${dimension}_${rational ? 'rational' : 'poly'}_deg${degree}`,
            nurbsCurve(dimension, rational, order, order + 3));
        }
      }
    }
    add('addCurve', 'nurbs_d3_rational_deg3_unclamped', nurbsCurve(3, true, 4, 7, false));
    add('addCurve', 'nurbs_d3_poly_deg2_bezier', nurbsCurve(3, false, 3, 3));
    add('addCurve', 'nurbs_circle', rh.NurbsCurve.createFromCircle(new rh.Circle(2.5)));
    add('addCurve', 'line', new rh.LineCurve([0.1, -0.2, 0.3], [1.7, 2.9, -0.4]));
    add('addCurve', 'polyline', new rh.PolylineCurve([[0, 0, 0], [1.5, 0.25, 0], [1.75, 1.125, 0.5], [0.3, 2.2, 0.1]]));
    add('addArc', 'arc', new rh.Arc([1, 2, 3], 1.75, 2.0));
    add('addCircle', 'circle', new rh.Circle([1, 2, 3], 0.8));
  } else if (group === 'surfaces') {
    add('addSurface', 'nurbs_poly_2x2', nurbsSurface(false, 2, 2, 3, 4));
    add('addSurface', 'nurbs_rational_3x4', nurbsSurface(true, 3, 4, 5, 6));
    add('addSurface', 'nurbs_rational_4x3', nurbsSurface(true, 4, 3, 6, 4));
    add('addSurface', 'nurbs_rational_5x6', nurbsSurface(true, 5, 6, 7, 8));
    add('addSurface', 'nurbs_sphere', rh.NurbsSurface.createFromSphere(new rh.Sphere([0.5, -1, 2], 3)));
    const profile = nurbsCurve(3, true, 3, 5);
    add('addSurface', 'revolution', rh.RevSurface.create(profile, new rh.Line([0, 0, -1], [0, 0.5, 4]), 0, 5.0));
  } else if (group === 'breps') {
    add('addBrep', 'brep_nurbs_surface', rh.Brep.createFromSurface(nurbsSurface(true, 3, 4, 5, 6)));
    add('addBrep', 'box', rh.Brep.createFromBox(new rh.Box(new rh.BoundingBox([-1, -2, -3], [1.5, 2.25, 0.75]))));
    add('addBrep', 'cylinder', rh.Brep.createFromCylinder(new rh.Cylinder(new rh.Circle([0.5, 0.25, -1], 1.25), 3.5), true, true));
    add('addBrep', 'sphere', rh.Brep.createFromSphere(new rh.Sphere([1, 2, 3], 2.5)));
    const profile = new rh.PolylineCurve([[1, 0, 0], [2, 0, 0.5], [1.5, 0, 2], [0.75, 0, 3]]);
    const rev = rh.RevSurface.create(profile, new rh.Line([0, 0, 0], [0, 0, 1]), 0, 2 * Math.PI);
    add('addBrep', 'revolution', rh.Brep.createFromRevSurface(rev, false, false));
    add('addBrep', 'trimmed_plane_polygon', rh.Brep.createTrimmedPlane(rh.Plane.worldXY(),
      new rh.PolylineCurve([[0, 0, 0], [4, 0, 0], [4.5, 3, 0], [1, 2.5, 0], [0, 0, 0]])));
    add('addBrep', 'trimmed_plane_circle', rh.Brep.createTrimmedPlane(rh.Plane.worldXY(),
      rh.NurbsCurve.createFromCircle(new rh.Circle(1.5))));
  } else if (group === 'meshes') {
    const mesh = new rh.Mesh();
    const n = 5;
    for (let j = 0; j < n; ++j) {
      for (let i = 0; i < n; ++i) mesh.vertices().add(i * 0.37 + between(-0.1, 0.1), j * 0.41, Math.sin(i + j) * 0.3);
    }
    for (let j = 0; j + 1 < n; ++j) {
      for (let i = 0; i + 1 < n; ++i) {
        const a = i + j * n, b = a + 1, c = a + n + 1, d = a + n;
        if ((i + j) % 3 === 0) {
          mesh.faces().addTriFace(a, b, c);
          mesh.faces().addTriFace(a, c, d);
        } else {
          mesh.faces().addQuadFace(a, b, c, d);
        }
      }
    }
    add('addMesh', 'grid_quads_and_triangles', mesh);
    const tet = new rh.Mesh();
    for (const p of [[0, 0, 0], [1.1, 0, 0], [0, 1.3, 0], [0.2, 0.3, 1.7]]) tet.vertices().add(...p);
    for (const f of [[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]) tet.faces().addTriFace(...f);
    add('addMesh', 'tetrahedron', tet);
  }
  return { doc, units, layers };
}

// The rational circle's corner control point tells which form the getters return.
function pointStyle() {
  const circle = rh.NurbsCurve.createFromCircle(new rh.Circle(2));
  const [x, y, , w] = circle.points().get(1);
  if (w === 1) throw new Error('circle corner weight is 1');
  if (Math.abs(x - 2 * w) < 1e-12 && Math.abs(y - 2 * w) < 1e-12) return 'homogeneous';
  if (Math.abs(x - 2) < 1e-12 && Math.abs(y - 2) < 1e-12) return 'euclidean';
  throw new Error(`unexpected circle corner ${[x, y, w]}`);
}

// JSON with -0 kept (JSON.stringify writes it as 0) and non-finite numbers refused.
function toJson(value) {
  const text = JSON.stringify(value, (key, v) => {
    if (typeof v === 'number') {
      if (!Number.isFinite(v)) throw new Error(`non-finite number at ${key}`);
      if (Object.is(v, -0)) return '\u0000-0';
    }
    return v;
  }, 1);
  return text.replaceAll('"\\u0000-0"', '-0') + '\n';
}

const style = pointStyle();
const index = { generator: `rhino3dm ${rhinoVersion}`, point_style: style, files: [], versions: [] };
for (const group of ['curves', 'surfaces', 'breps', 'meshes']) {
  const { doc, units, layers } = buildModel(group);
  for (const optionVersion of [2, 3, 4, 5, 6, 7, 8]) {
    const options = new rh.File3dmWriteOptions();
    options.version = optionVersion;
    const bytes = doc.toByteArrayOptions(options);
    // The start section: "3D Geometry File Format " then the version right-aligned in 8 characters.
    const head = Buffer.from(bytes.subarray(0, 32)).toString('latin1');
    if (!head.startsWith('3D Geometry File Format ')) throw new Error('no 3dm header');
    const archiveVersion = Number(head.slice(24, 32).trim());
    const back = rh.File3dm.fromByteArray(bytes);
    if (!back || back.archiveVersion !== archiveVersion) throw new Error(`v${archiveVersion}: rhino3dm cannot read it back`);
    const objects = [];
    for (let i = 0; i < back.objects().count; ++i) objects.push(objectValues(back.objects().get(i), i, back));
    const backLayers = [];
    for (let i = 0; i < back.layers().count; ++i) {
      const layer = back.layers().get(i);
      const c = layer.color;
      backLayers.push({ index: i, name: layer.name, color: [c.r, c.g, c.b, c.a] });
    }
    const unit = back.settings().modelUnitSystem;
    const base = `${group}_v${archiveVersion}`;
    const record = {
      generator: `rhino3dm ${rhinoVersion}`,
      file: `${base}.3dm`,
      group,
      write_option_version: optionVersion,
      archive_version: archiveVersion,
      // "homogeneous": each point is [w*x, w*y, w*z, w] as openNURBS stores it; "euclidean": [x, y, z, w].
      point_style: style,
      // openNURBS keeps order + count - 2 knots (no end knots); these lists are the same.
      knot_convention: 'opennurbs',
      units: { name: units, value: unit.value },
      layers: backLayers,
      objects,
    };
    if (objects.length === 0) throw new Error(`${base}: no objects read back`);
    fs.writeFileSync(path.join(outDir, `${base}.3dm`), bytes);
    fs.writeFileSync(path.join(outDir, `${base}.json`), toJson(record));
    index.files.push(base);
    if (!index.versions.includes(archiveVersion)) index.versions.push(archiveVersion);
  }
  doc.delete?.();
}
fs.writeFileSync(path.join(outDir, 'index.json'), toJson(index));
console.log(`generate.mjs: ${index.files.length} files (archive versions ${index.versions.join(', ')}), points ${style}`);
