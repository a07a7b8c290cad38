#include "formats/3dm/legacy_brep.hpp"

#include <algorithm>
#include <numeric>
#include <string>
#include <vector>

#include "core/geometry_error.hpp"
#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/flipped_face.hpp"
#include "formats/3dm/legacy_nurbs.hpp"
#include "formats/3dm/object_checks.hpp"
#include "formats/3dm/oriented_loop.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {

namespace {

constexpr const char* kShellRecord = "legacy shell";
constexpr const char* kFaceRecord = "legacy face";
constexpr const char* kLoopRecord = "legacy loop";
constexpr std::size_t kChunkHeader = 8;  // every face, loop and trim needs at least its chunk's header

// The trim kinds of ON_BrepTrim that a legacy trim's flag byte decides.
enum class TrimKind { boundary, mated, seam, singular };

struct LegacyTrim {
  NurbsCurve curve;  // in the face's (u, v)
  int edge = -1;
  bool against_edge = false;
  TrimKind kind = TrimKind::singular;
  double tolerance_2d = 0, tolerance_3d = 0;
};

struct LegacyLoop {
  int type = 0;  // -1 slit, 0 outer, 1 inner
  std::vector<int> trims;
};

struct LegacyFace {
  NurbsSurface surface;
  bool flipped = false;
  std::vector<LegacyLoop> loops;
};

struct LegacyBrep {
  std::vector<LegacyTrim> trims;
  std::vector<LegacyFace> faces;
  int edge_count = 0;
};

// An int32 count of records, each at least a chunk header long; refused when negative or when they
// would not fit in what is left of the chunk.
std::size_t record_count(ArchiveReader& reader, const char* record, const std::string& what, std::int32_t count) {
  if (count < 0) refuse(reader, record, what + " count " + std::to_string(count) + " is negative");
  if (static_cast<std::uint64_t>(count) * kChunkHeader > reader.bytes_left())
    refuse(reader, record,
           std::to_string(count) + " " + what + " cannot fit in the " + std::to_string(reader.bytes_left()) +
               " bytes left");
  return static_cast<std::size_t>(count);
}

std::vector<int> read_glue(ArchiveReader& reader) {
  std::vector<int> glue(reader.count(2));
  for (auto& g : glue) g = reader.i16();
  return glue;
}

// Gives each trim of `kind` from `first` on without an edge the edge of the trim its glue entry pairs it
// with (the i-th such trim pairs with the glue[i]-th), when their count equals the glue's.
void apply_glue(LegacyBrep& brep, std::size_t first, TrimKind kind, const std::vector<int>& glue) {
  std::vector<std::size_t> glued;
  for (std::size_t t = first; t < brep.trims.size(); ++t)
    if (brep.trims[t].kind == kind) glued.push_back(t);
  if (glued.size() != glue.size()) return;
  const int n = static_cast<int>(glue.size());
  for (int i = 0; i < n; ++i) {
    if (glue[i] < 0 || glue[i] >= n) continue;
    LegacyTrim& a = brep.trims[glued[i]];
    LegacyTrim& b = brep.trims[glued[glue[i]]];
    if (a.edge < 0 && b.edge >= 0) a.edge = b.edge;
    if (b.edge < 0 && a.edge >= 0) b.edge = a.edge;
  }
}

// A curve chunk (TCODE_LEGACY_CRV wrapping its stuff chunk); `keep` false steps over it.
NurbsCurve read_wrapped_curve(ArchiveReader& reader, bool keep) {
  open_legacy_chunk(reader, tcode::kLegacyCurve, "legacy curve");
  NurbsCurve curve;
  if (keep) {
    open_legacy_chunk(reader, tcode::kLegacyCurveStuff, "legacy curve stuff");
    curve = read_legacy_curve(reader);
    reader.end_chunk();
  }
  reader.end_chunk();
  return curve;
}

void read_trim(ArchiveReader& reader, LegacyBrep& brep, LegacyLoop& loop) {
  open_legacy_chunk(reader, tcode::kLegacyTrim, "legacy trim");
  open_legacy_chunk(reader, tcode::kLegacyTrimStuff, "legacy trim stuff");
  LegacyTrim trim;
  const std::uint8_t flags = reader.u8();
  const bool owns_edge = (flags & 1) != 0, has_mate = (flags & 6) != 0, seam = (flags & 2) != 0;
  trim.kind = seam ? TrimKind::seam : has_mate ? TrimKind::mated : owns_edge ? TrimKind::boundary : TrimKind::singular;
  trim.against_edge = reader.i32() != 0;
  reader.skip(8);  // legacy continuity and monotonicity flags
  trim.tolerance_3d = reader.f64();
  trim.tolerance_2d = reader.f64();
  trim.curve = read_wrapped_curve(reader, true);
  if (owns_edge) {
    read_wrapped_curve(reader, false);  // the edge's 3D curve
    trim.edge = brep.edge_count++;
  }
  reader.end_chunk();
  reader.end_chunk();
  loop.trims.push_back(static_cast<int>(brep.trims.size()));
  brep.trims.push_back(std::move(trim));
}

LegacyLoop read_loop(ArchiveReader& reader, LegacyBrep& brep) {
  open_legacy_chunk(reader, tcode::kLegacyLoop, "legacy loop");
  open_legacy_chunk(reader, tcode::kLegacyLoopStuff, "legacy loop stuff");
  const std::int32_t trim_count = reader.i32();
  if (trim_count < 1) refuse(reader, kLoopRecord, "trim count " + std::to_string(trim_count) + " is below 1");
  LegacyLoop loop;
  loop.type = reader.i32();
  if (loop.type < -1 || loop.type > 1) refuse(reader, kLoopRecord, "type " + std::to_string(loop.type) + " unknown");
  reader.doubles(4);  // parameter box
  const std::size_t trims = record_count(reader, kLoopRecord, "trims", trim_count);
  for (std::size_t t = 0; t < trims; ++t) read_trim(reader, brep, loop);
  reader.end_chunk();
  reader.end_chunk();
  return loop;
}

// Face stuff (the reader inside it); appends the face and its trims to `brep`.
void read_face_stuff(ArchiveReader& reader, LegacyBrep& brep) {
  const std::size_t first_trim = brep.trims.size();
  LegacyFace face;
  const std::int32_t flipped = reader.i32();
  if (flipped != 0 && flipped != 1)
    refuse(reader, kFaceRecord, "normal-flipped flag " + std::to_string(flipped) + " is neither 0 nor 1");
  face.flipped = flipped == 1;
  reader.i32();  // face type
  const std::int32_t loop_field = reader.i32();
  if (loop_field < 0 || loop_field % 2 != 1)
    refuse(reader, kFaceRecord,
           "loop field " + std::to_string(loop_field) + " has no outer loop (Rhino 1 always writes one)");
  reader.doubles(6);  // bounding box
  const std::vector<int> glue = read_glue(reader);
  open_legacy_chunk(reader, tcode::kLegacySurface, "legacy surface");
  open_legacy_chunk(reader, tcode::kLegacySurfaceStuff, "legacy surface stuff");
  face.surface = read_legacy_surface(reader);
  reader.end_chunk();
  reader.end_chunk();
  const std::size_t loops = record_count(reader, kFaceRecord, "loops", loop_field / 2);
  for (std::size_t l = 0; l < loops; ++l) face.loops.push_back(read_loop(reader, brep));
  apply_glue(brep, first_trim, TrimKind::seam, glue);
  brep.faces.push_back(std::move(face));
}

// The trimmed surface of face `fi` (0-based); throws GeometryError when its loops do not close or its
// geometry is invalid.
TrimmedSurface build_face(const LegacyBrep& brep, std::size_t fi) {
  const LegacyFace& face = brep.faces[fi];
  const std::string entity = "face " + std::to_string(fi + 1);
  TrimmedSurface out;
  out.surface = face.surface;
  const double size =
      std::max(out.surface.u_end() - out.surface.u_start(), out.surface.v_end() - out.surface.v_start());
  for (std::size_t li = 0; li < face.loops.size(); ++li) {
    const LegacyLoop& loop = face.loops[li];
    const std::string loop_name = entity + " loop " + std::to_string(li + 1);
    TrimLoop built;
    double tolerance = 1e-9 * size;
    for (const int ti : loop.trims) {
      const LegacyTrim& trim = brep.trims[static_cast<std::size_t>(ti)];
      if (trim.curve.dimension != 2) throw GeometryError(loop_name, "trim " + std::to_string(ti) + "'s curve is 3D");
      built.segments.emplace_back(clamped(trim.curve));
      built.edges.push_back(trim.edge >= 0 ? TrimEdgeRef{trim.edge, trim.against_edge} : TrimEdgeRef{});
      tolerance = std::max(tolerance, trim.tolerance_2d);
    }
    std::vector<int> trim_numbers(built.segments.size());
    std::iota(trim_numbers.begin(), trim_numbers.end(), 1);
    // Rhino 1's loop types: 0 outer, 1 inner, -1 slit.
    const LoopRole role = loop.type == 0 ? LoopRole::outer : loop.type == 1 ? LoopRole::inner : LoopRole::other;
    out.loops.push_back(oriented_loop(std::move(built), role, tolerance, trim_numbers, loop_name));
  }
  if (face.flipped) out = flipped(out);
  validate(out, entity, 1e-9 * size);
  return out;
}

RhinoBrep built(const LegacyBrep& legacy) {
  RhinoBrep brep;
  brep.edge_count = legacy.edge_count;
  brep.edge_tolerances.assign(static_cast<std::size_t>(legacy.edge_count), 0.0);
  for (const auto& trim : legacy.trims)
    if (trim.edge >= 0) brep.edge_tolerances[trim.edge] = std::max(brep.edge_tolerances[trim.edge], trim.tolerance_3d);
  for (std::size_t fi = 0; fi < legacy.faces.size(); ++fi) {
    try {
      brep.faces.push_back(build_face(legacy, fi));
      brep.face_indices.push_back(static_cast<int>(fi));
    } catch (const GeometryError& e) {
      brep.skipped_faces.push_back(e.what());
      brep.skipped_face_indices.push_back(static_cast<int>(fi));
    }
  }
  return brep;
}

}  // namespace

RhinoBrep read_legacy_shell(ArchiveReader& reader) {
  LegacyBrep legacy;
  reader.i32();  // outer-shell flag
  const std::int32_t face_count = reader.i32();
  reader.point3();  // bounding box
  reader.point3();
  const std::vector<int> glue = read_glue(reader);
  const std::size_t faces = record_count(reader, kShellRecord, "faces", face_count);
  for (std::size_t f = 0; f < faces; ++f) {
    open_legacy_chunk(reader, tcode::kLegacyFace, "legacy face");
    open_legacy_chunk(reader, tcode::kLegacyFaceStuff, "legacy face stuff");
    read_face_stuff(reader, legacy);
    reader.end_chunk();
    reader.end_chunk();
  }
  apply_glue(legacy, 0, TrimKind::mated, glue);
  return built(legacy);
}

RhinoBrep read_legacy_face(ArchiveReader& reader) {
  LegacyBrep legacy;
  read_face_stuff(reader, legacy);
  return built(legacy);
}

}  // namespace cadnurbs::rhino
