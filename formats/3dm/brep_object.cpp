#include "formats/3dm/brep_object.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>
#include <variant>

#include "core/geometry_error.hpp"
#include "core/split_curve.hpp"
#include "formats/3dm/brep_v2_layout.hpp"
#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/flipped_face.hpp"
#include "formats/3dm/oriented_loop.hpp"
#include "formats/3dm/rhino_object.hpp"
#include "formats/3dm/surface_objects.hpp"
#include "formats/3dm/typecodes.hpp"

// Layout of ON_Brep's class data, chunk version 3.x (opennurbs_brep_io.cpp): the 2D curves, 3D curves and
// surfaces (each an anonymous chunk holding a count and, per element, a flag and a WriteObject'ed
// object), then vertices, edges, trims, loops and faces (each an anonymous chunk, version 1.x, a count
// and the records), the bounding box, and from 3.1 on render/analysis meshes, 3.2 m_is_solid, 3.3 region
// topology. Only what a trimmed surface needs is kept; everything after the faces is left to the class
// data chunk's end. Chunk version 2.x (Rhino 2) is brep_v2_layout.hpp's.

namespace cadnurbs::rhino {

namespace {

// ON_BrepTrim::TYPE and ON_BrepLoop::TYPE values as the file stores them.
constexpr int kTrimSingular = 4;
constexpr int kTrimPointOnSurface = 6;
constexpr int kLoopOuter = 1;
constexpr int kLoopInner = 2;
constexpr int kLoopCurveOnSurface = 4;
constexpr int kLoopPointOnSurface = 5;

struct BrepTrim {
  int curve = -1;              // index into the 2D curves
  double from = 0, to = 0;     // the piece of that curve the trim uses (ON_CurveProxy's real-curve domain)
  bool curve_reversed = false; // the trim runs the piece backwards
  int edge = -1;
  bool against_edge = false;   // m_bRev3d
  int type = 0;
  double tolerance = 0;        // the larger of the trim's u and v tolerances
};

struct BrepLoop {
  std::vector<int> trims;
  int type = 0;
};

struct BrepFace {
  std::vector<int> loops;
  int surface = -1;
  bool reversed = false;
};

// A curve of the Brep's arrays, or why it is not there.
struct CurveSlot {
  std::optional<NurbsCurve> value;
  std::string missing;  // "null", or the class name read_object did not convert
};

// A surface of the Brep's arrays. A revolution keeps its data: its trims are written in its angle
// parameter, which the NURBS form does not share (see surface_objects.hpp).
struct SurfaceSlot {
  std::optional<NurbsSurface> value;
  std::optional<Revolution> revolution;
  std::string missing;
};

const Uuid kRevSurfaceId = uuid_from_text("A16220D3-163B-11D4-8000-0010830122F0");
const Uuid kLegacyRevSurfaceId = uuid_from_text("0A8401B6-4D34-4B99-8615-1B4E723DC4E5");  // TL_RevSurface

// Opens an object array's chunk (version 1.x) and returns its element count.
std::size_t begin_object_array(ArchiveReader& reader, const char* what) {
  reader.begin_chunk(tcode::kAnonymousChunk);
  const int major = reader.chunk_version().first;
  if (major != 1) reader.fail(std::string("Brep ") + what + " array: chunk version " + std::to_string(major) + " unknown");
  return reader.count(4);  // each element has at least its int32 flag
}

template <typename Slot>
void take(RhinoGeometry g, Slot& slot) {
  using T = typename decltype(Slot::value)::value_type;
  if (auto* value = std::get_if<T>(&g)) {
    slot.value = std::move(*value);
  } else if (auto* u = std::get_if<Unsupported>(&g)) {
    slot.missing = u->class_name;
  } else {
    slot.missing = "an object of another kind";
  }
}

std::vector<CurveSlot> read_curves(ArchiveReader& reader) {
  std::vector<CurveSlot> out(begin_object_array(reader, "2D curve"));
  for (auto& slot : out) {
    if (reader.i32() != 1)
      slot.missing = "null";
    else
      take(read_object(reader), slot);
  }
  reader.end_chunk();
  return out;
}

std::vector<SurfaceSlot> read_surfaces(ArchiveReader& reader) {
  std::vector<SurfaceSlot> out(begin_object_array(reader, "surface"));
  for (auto& slot : out) {
    if (reader.i32() != 1) {
      slot.missing = "null";
      continue;
    }
    ArchiveReader probe = reader;  // the class id, without moving `reader`
    probe.begin_chunk(tcode::kOpennurbsClass);
    probe.begin_chunk(tcode::kOpennurbsClassUuid);
    const Uuid id = probe.uuid();
    if (id != kRevSurfaceId && id != kLegacyRevSurfaceId) {
      take(read_object(reader), slot);
      continue;
    }
    reader.begin_chunk(tcode::kOpennurbsClass);
    reader.begin_chunk(tcode::kOpennurbsClassUuid);
    reader.end_chunk();
    reader.begin_chunk(tcode::kOpennurbsClassData);
    slot.revolution = read_revolution(reader);
    reader.end_chunk();
    reader.end_chunk();  // user data and the end mark
    slot.value = revolution_as_nurbs(*slot.revolution);
  }
  reader.end_chunk();
  return out;
}

std::vector<int> read_int_array(ArchiveReader& reader) {
  const std::size_t n = reader.count(4);
  std::vector<int> out(n);
  for (auto& v : out) v = reader.i32();
  return out;
}

// A topology array: an anonymous chunk (version 1.x) holding a count and the records, each read by
// read_one(reader, record). What follows the records in later minor versions (face ids and colours in
// the face array) is left to the chunk's end.
template <typename Record, typename ReadOne>
std::vector<Record> read_records(ArchiveReader& reader, const char* what, ReadOne read_one) {
  reader.begin_chunk(tcode::kAnonymousChunk);
  const int major = reader.chunk_version().first;
  if (major != 1) reader.fail(std::string("Brep ") + what + " array: chunk version " + std::to_string(major) + " unknown");
  std::vector<Record> records(reader.count(4));
  for (auto& record : records) read_one(reader, record);
  reader.end_chunk();
  return records;
}

// An edge's tolerance (the rest of the edge is not needed: faces carry the geometry).
void read_edge(ArchiveReader& reader, double& tolerance) {
  reader.i32();       // index
  reader.i32();       // 3D curve
  reader.i32();       // proxy reversed
  reader.doubles(2);  // proxy domain
  reader.i32();       // vertices
  reader.i32();
  read_int_array(reader);  // trims
  tolerance = reader.f64();
  if (!(tolerance >= 0)) tolerance = 0;  // ON_UNSET_VALUE: not computed
  if (reader.archive_version() >= 3) reader.doubles(2);  // the edge's own domain
}

void read_trim(ArchiveReader& reader, BrepTrim& t) {
  reader.i32();  // index
  t.curve = reader.i32();
  t.from = reader.f64();
  t.to = reader.f64();
  t.edge = reader.i32();
  reader.i32();  // vertices
  reader.i32();
  t.against_edge = reader.i32() != 0;
  t.type = reader.i32();
  reader.i32();  // iso
  reader.i32();  // loop
  const double tu = reader.f64(), tv = reader.f64();
  t.tolerance = std::max(std::isfinite(tu) ? tu : 0.0, std::isfinite(tv) ? tv : 0.0);
  if (reader.archive_version() >= 3) {
    reader.doubles(2);                         // the trim's own domain (a reparametrisation only)
    t.curve_reversed = reader.raw(8)[0] == 1;  // 8 flag bytes, the first says "reversed"
    reader.skip(24);                           // reserved
  } else {
    reader.point3();  // two unused points in version 2 files
    reader.point3();
  }
  reader.f64();  // legacy 2D and 3D tolerances
  reader.f64();
}

void read_loop(ArchiveReader& reader, BrepLoop& l) {
  reader.i32();  // index
  l.trims = read_int_array(reader);
  l.type = reader.i32();
  reader.i32();  // face
}

void read_face(ArchiveReader& reader, BrepFace& f) {
  reader.i32();  // index
  f.loops = read_int_array(reader);
  f.surface = reader.i32();
  f.reversed = reader.i32() != 0;
  reader.i32();  // material channel
}

// Chunk version 3.1 on: one flag byte per face, each 1 followed by the face's render mesh object.
// Returns one entry per face, or none when no face has a mesh.
std::vector<std::optional<TriangleMesh>> read_render_meshes(ArchiveReader& reader, std::size_t face_count) {
  std::vector<std::optional<TriangleMesh>> meshes(face_count);
  bool any = false;
  reader.begin_chunk(tcode::kAnonymousChunk);
  for (auto& mesh : meshes) {
    if (reader.u8() == 0) continue;
    RhinoGeometry g = read_object(reader);
    if (auto* m = std::get_if<TriangleMesh>(&g)) {
      mesh = std::move(*m);
      any = true;
    }
  }
  reader.end_chunk();
  if (!any) meshes.clear();
  return meshes;
}

// The part of `curve` over [from, to] (inside its domain), clamped at both ends. Ends within a
// billionth of the domain's length of the curve's own ends are taken as those ends.
NurbsCurve restricted(const NurbsCurve& curve, double from, double to) {
  const double a = curve.domain_start(), b = curve.domain_end();
  const double slack = 1e-9 * (b - a);
  NurbsCurve out = curve;
  if (from > a + slack) out = split_curve(out, from).second;
  if (to < b - slack) out = split_curve(out, to).first;
  return clamped(out);
}

// The NURBS form's angle parameter of a revolution's angle parameter s; outside [t0, t1] (trims leave
// the domain by round-off) the map continues with slope one.
double nurbs_angle(const Revolution& rev, double s) {
  const double inside = std::clamp(s, rev.t0, rev.t1);
  return revolution_nurbs_parameter(rev, inside) + (s - inside);
}

bool monotone(const std::vector<double>& v) {
  return std::is_sorted(v.begin(), v.end()) || std::is_sorted(v.rbegin(), v.rend());
}

// A trim of a revolution's face moved from the revolution's angle parameter (coordinate k) to the NURBS
// form's. The map acts on that coordinate alone, so a trim at a constant angle, or one running straight
// along the angle direction (its other coordinate constant, its angles monotone), keeps its locus when
// only its control points are mapped: exact. Any other trim becomes a polyline through mapped points of
// the curve, refined until every chord's midpoint is within `tolerance` of the mapped curve's.
TrimSegment to_nurbs_angle(const NurbsCurve& trim, const Revolution& rev, int k, double tolerance) {
  std::vector<double> angle, other;
  for (const auto& p : trim.points) {
    angle.push_back(p[k]);
    other.push_back(p[1 - k]);
  }
  const bool constant_angle = std::all_of(angle.begin(), angle.end(), [&](double a) { return a == angle[0]; });
  const bool along_angle = std::all_of(other.begin(), other.end(), [&](double b) { return b == other[0]; });
  if (constant_angle || (along_angle && monotone(angle))) {
    NurbsCurve out = trim;
    for (auto& p : out.points) p[k] = nurbs_angle(rev, p[k]);
    return out;
  }
  auto mapped = [&](double t) {
    Eigen::Vector2d q = curve_point(trim, t).head<2>();
    q[k] = nurbs_angle(rev, q[k]);
    return q;
  };
  Polyline2D out;
  // Start from a few points per knot span, so that no span's wiggle hides between two samples.
  std::vector<double> ts;
  for (int i = trim.order - 1; i < trim.count(); ++i) {
    const double a = trim.knots[i], b = trim.knots[i + 1];
    if (!(a < b)) continue;
    for (int j = 0; j < 4; ++j) ts.push_back(a + (b - a) * j / 4);
  }
  ts.push_back(trim.domain_end());
  out.points.push_back(mapped(ts[0]));
  constexpr int kMaxDepth = 12;
  struct Piece {
    double t0, t1;
    Eigen::Vector2d q0, q1;
    int depth;
  };
  for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
    std::vector<Piece> stack = {{ts[i], ts[i + 1], mapped(ts[i]), mapped(ts[i + 1]), 0}};
    while (!stack.empty()) {
      Piece piece = stack.back();
      stack.pop_back();
      const double tm = 0.5 * (piece.t0 + piece.t1);
      const Eigen::Vector2d qm = mapped(tm);
      if (piece.depth < kMaxDepth && (qm - 0.5 * (piece.q0 + piece.q1)).norm() > tolerance) {
        stack.push_back({tm, piece.t1, qm, piece.q1, piece.depth + 1});  // the second half after the first
        stack.push_back({piece.t0, tm, piece.q0, qm, piece.depth + 1});
      } else {
        out.points.push_back(piece.q1);
      }
    }
  }
  return out;
}

// Builds face `fi`; throws GeometryError(entity, reason) when it cannot.
TrimmedSurface build_face(int fi, const BrepFace& face, const std::vector<CurveSlot>& curves,
                          const std::vector<SurfaceSlot>& surfaces, const std::vector<BrepTrim>& trims,
                          const std::vector<BrepLoop>& loops) {
  const std::string entity = "face " + std::to_string(fi + 1);
  if (face.surface < 0 || face.surface >= static_cast<int>(surfaces.size()))
    throw GeometryError(entity, "surface index " + std::to_string(face.surface) + " out of range");
  const auto& slot = surfaces[face.surface];
  if (!slot.value)
    throw GeometryError(entity, "surface " + std::to_string(face.surface) + " is " + slot.missing);
  TrimmedSurface out;
  out.surface = *slot.value;
  const double size = std::max(out.surface.u_end() - out.surface.u_start(), out.surface.v_end() - out.surface.v_start());

  for (const int li : face.loops) {
    if (li < 0 || li >= static_cast<int>(loops.size()))
      throw GeometryError(entity, "loop index " + std::to_string(li) + " out of range");
    const BrepLoop& loop = loops[li];
    if (loop.type == kLoopCurveOnSurface || loop.type == kLoopPointOnSurface) continue;  // bounds nothing
    const std::string loop_name = entity + " loop " + std::to_string(li);
    TrimLoop built;
    double tolerance = 1e-9 * size;
    for (const int ti : loop.trims) {
      if (ti < 0 || ti >= static_cast<int>(trims.size()))
        throw GeometryError(loop_name, "trim index " + std::to_string(ti) + " out of range");
      const BrepTrim& trim = trims[ti];
      if (trim.type == kTrimPointOnSurface) continue;
      const std::string trim_name = loop_name + " trim " + std::to_string(ti);
      if (trim.curve < 0 || trim.curve >= static_cast<int>(curves.size()))
        throw GeometryError(trim_name, "2D curve index " + std::to_string(trim.curve) + " out of range");
      const auto& c = curves[trim.curve];
      if (!c.value) throw GeometryError(trim_name, "2D curve " + std::to_string(trim.curve) + " is " + c.missing);
      if (c.value->dimension != 2) throw GeometryError(trim_name, "2D curve " + std::to_string(trim.curve) + " is 3D");
      const double from = std::max(trim.from, c.value->domain_start());
      const double to = std::min(trim.to, c.value->domain_end());
      if (!(from < to)) throw GeometryError(trim_name, "empty piece of its 2D curve");
      NurbsCurve piece = restricted(*c.value, from, to);
      if (trim.curve_reversed) piece = reversed(piece);
      if (slot.revolution)
        built.segments.push_back(to_nurbs_angle(piece, *slot.revolution, slot.revolution->transposed ? 1 : 0, 1e-7 * size));
      else
        built.segments.emplace_back(std::move(piece));
      if (trim.type == kTrimSingular || trim.edge < 0)
        built.edges.push_back(TrimEdgeRef{});
      else
        built.edges.push_back(TrimEdgeRef{trim.edge, trim.against_edge});
      tolerance = std::max(tolerance, trim.tolerance);
    }
    if (built.segments.empty()) throw GeometryError(loop_name, "has no trims");
    // Consecutive trims meet within the trims' own tolerance.
    const LoopRole role = loop.type == kLoopOuter   ? LoopRole::outer
                          : loop.type == kLoopInner ? LoopRole::inner
                                                    : LoopRole::other;
    out.loops.push_back(oriented_loop(std::move(built), role, tolerance, loop.trims, loop_name));
  }
  if (face.reversed) out = flipped(out);
  validate(out, entity, 1e-9 * size);
  return out;
}

}  // namespace

RhinoBrep read_brep(ArchiveReader& reader) {
  const auto [major, minor] = reader.chunk_version();
  if (major == 2) return read_brep_v2_layout(reader);
  if (major != 3) reader.fail("Brep chunk version " + std::to_string(major) + " is unknown");
  const auto curves2d = read_curves(reader);
  reader.begin_chunk(tcode::kAnonymousChunk);  // 3D curves: the edges' geometry comes from the faces
  reader.end_chunk();
  const auto surfaces = read_surfaces(reader);
  reader.begin_chunk(tcode::kAnonymousChunk);  // vertices
  reader.end_chunk();
  RhinoBrep brep;
  brep.edge_tolerances = read_records<double>(reader, "edge", read_edge);
  brep.edge_count = static_cast<int>(brep.edge_tolerances.size());
  const auto trims = read_records<BrepTrim>(reader, "trim", read_trim);
  const auto loops = read_records<BrepLoop>(reader, "loop", read_loop);
  const auto faces = read_records<BrepFace>(reader, "face", read_face);
  reader.point3();  // bounding box
  reader.point3();
  if (minor >= 1) brep.render_meshes = read_render_meshes(reader, faces.size());

  for (const auto& t : trims)
    if (t.edge >= brep.edge_count) reader.fail("Brep trim's edge index " + std::to_string(t.edge) + " out of range");
  for (std::size_t fi = 0; fi < faces.size(); ++fi) {
    try {
      brep.faces.push_back(build_face(static_cast<int>(fi), faces[fi], curves2d, surfaces, trims, loops));
      brep.face_indices.push_back(static_cast<int>(fi));
    } catch (const GeometryError& e) {
      const std::string name = "face " + std::to_string(fi + 1);
      const std::string what = e.what();
      brep.skipped_faces.push_back(what.rfind(name + " ", 0) == 0 || what.rfind(name + ":", 0) == 0 ? what : name + ": " + what);
      brep.skipped_face_indices.push_back(static_cast<int>(fi));
    }
  }
  return brep;
}

}  // namespace cadnurbs::rhino
