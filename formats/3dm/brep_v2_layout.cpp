#include "formats/3dm/brep_v2_layout.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "core/geometry_error.hpp"
#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/flipped_face.hpp"
#include "formats/3dm/object_checks.hpp"
#include "formats/3dm/oriented_loop.hpp"
#include "formats/3dm/rhino_object.hpp"
#include "formats/3dm/surface_objects.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {

namespace {

constexpr const char* kRecord = "Brep (Rhino 2 layout)";
constexpr const char* kPolyCurve = "ON_PolyCurve";
constexpr const char* kNurbsSurface = "ON_NurbsSurface";

// The fewest bytes each element can take, so that a count is refused before anything is allocated: a polycurve header
// with no parameters (version, 3 ints, bounding box, parameter count); a NURBS surface header with empty arrays
// (version, 8 ints, bounding box, 3 array counts); the fixed part of a face, loop and trim record.
constexpr std::size_t kCurveBytes = 1 + 3 * 4 + 6 * 8 + 4;
constexpr std::size_t kSurfaceBytes = 1 + 8 * 4 + 6 * 8 + 3 * 4;
constexpr std::size_t kFaceBytes = 4 * 4 + 6 * 8 + 4;
constexpr std::size_t kLoopBytes = 2 * 4 + 4 * 8 + 4;
constexpr std::size_t kTrimBytes = 2 * 4 + 1 + 4 * 4 + 2 * 8;

// Rhino 2's loop types.
constexpr int kLoopOuter = 0;
constexpr int kLoopInner = 1;

struct Trim {
  int edge = -1;  // index into the 3D curves; -1: none (a singular trim)
  bool against_edge = false;
  double tolerance_2d = 0, tolerance_3d = 0;
};

struct Loop {
  int type = 0;            // 0 outer, 1 inner, -1 slit
  std::vector<int> trims;  // running trim numbers, also the indices of their 2D curves
};

struct Face {
  bool reversed = false;
  std::vector<Loop> loops;
};

// A curve or surface of the Brep, or why it could not be converted.
template <typename T>
struct Slot {
  std::optional<T> value;
  std::string missing;
};

// A count that must be at least 1, each element taking at least `element_bytes` of what is left.
std::size_t positive_count(ArchiveReader& reader, std::int32_t count, std::size_t element_bytes,
                           const std::string& what) {
  if (count < 1) refuse(reader, kRecord, what + " count " + std::to_string(count) + " is below 1");
  if (static_cast<std::uint64_t>(count) * element_bytes > reader.bytes_left())
    refuse(reader, kRecord,
           std::to_string(count) + " " + what + " cannot fit in the " + std::to_string(reader.bytes_left()) +
               " bytes left");
  return static_cast<std::size_t>(count);
}

// Steps over ON_PolyCurve class data by its structure alone (its segments are chunks).
void skip_poly_curve(ArchiveReader& reader) {
  reader.u8();  // chunk version
  const std::int32_t segments = reader.i32();
  if (segments < 0) refuse(reader, kPolyCurve, "segment count " + std::to_string(segments) + " is negative");
  reader.skip(2 * 4 + 6 * 8);  // reserved ints, bounding box
  reader.skip(8 * read_count(reader, kPolyCurve, 8, "segment parameters"));
  for (std::int32_t i = 0; i < segments; ++i) {
    reader.begin_chunk(tcode::kOpennurbsClass);
    reader.end_chunk();
  }
}

// Steps over ON_NurbsSurface class data by its structure alone.
void skip_nurbs_surface(ArchiveReader& reader) {
  reader.u8();  // chunk version
  const int dimension = expect_dimension(reader, kNurbsSurface, reader.i32());
  const bool rational = reader.i32() != 0;
  reader.skip(4 * 4 + 2 * 4 + 6 * 8);  // orders, counts, reserved ints, bounding box
  reader.skip(8 * read_count(reader, kNurbsSurface, 8, "u knots"));
  reader.skip(8 * read_count(reader, kNurbsSurface, 8, "v knots"));
  const std::size_t cv_bytes = 8 * static_cast<std::size_t>(dimension + (rational ? 1 : 0));
  reader.skip(cv_bytes * read_count(reader, kNurbsSurface, cv_bytes, "control points"));
}

// Converts one element with `read` on a copy of the reader; when that refuses it, keeps the reason and steps over the
// element with `skip`, so that only the faces using it are lost.
template <typename T, typename Read, typename Skip>
Slot<T> read_or_skip(ArchiveReader& reader, Read read, Skip skip) {
  ArchiveReader attempt = reader;
  try {
    Slot<T> slot{read(attempt), {}};
    reader = std::move(attempt);
    return slot;
  } catch (const ArchiveError& e) {
    std::string reason = e.what();
    const std::string file_prefix = reader.name() + ": ";
    if (reason.rfind(file_prefix, 0) == 0) reason.erase(0, file_prefix.size());
    skip(reader);
    return {std::nullopt, reason};
  }
}

void read_trim(ArchiveReader& reader, int edge_count, Trim& trim) {
  reader.i32();  // the trim's index as written (openNURBS only reports one out
                 // of step)
  reader.i32();  // its twin's index
  const bool owns_edge = reader.u8() != 0;
  trim.edge = reader.i32();
  if (trim.edge < 0 || trim.edge >= edge_count) {
    if (owns_edge)
      refuse(reader, kRecord,
             "a trim owning edge " + std::to_string(trim.edge) + " of " + std::to_string(edge_count) + " edges");
    trim.edge = -1;
  }
  trim.against_edge = reader.i32() != 0;
  reader.skip(2 * 4);  // continuity and monotonicity flags
  const double tolerance_3d = reader.f64(), tolerance_2d = reader.f64();
  trim.tolerance_3d = std::isfinite(tolerance_3d) ? std::max(tolerance_3d, 0.0) : 0.0;
  trim.tolerance_2d = std::isfinite(tolerance_2d) ? std::max(tolerance_2d, 0.0) : 0.0;
}

// The face records; appends every trim to `trims`, refusing more than `trim_count`.
std::vector<Face> read_faces(ArchiveReader& reader, std::size_t face_count, std::size_t trim_count, int edge_count,
                             std::vector<Trim>& trims) {
  std::vector<Face> faces(face_count);
  for (Face& face : faces) {
    reader.i32();  // legacy index
    reader.i32();  // obsolete material index
    face.reversed = reader.i32() != 0;
    reader.i32();       // face type
    reader.doubles(6);  // bounding box
    face.loops.resize(positive_count(reader, reader.i32(), kLoopBytes, "face loop"));
    for (Loop& loop : face.loops) {
      reader.i32();  // legacy index
      loop.type = reader.i32();
      reader.doubles(4);  // parameter box
      const std::size_t loop_trims = positive_count(reader, reader.i32(), kTrimBytes, "loop trim");
      for (std::size_t t = 0; t < loop_trims; ++t) {
        if (trims.size() == trim_count)
          refuse(reader, kRecord, "the loops hold more trims than the trim count " + std::to_string(trim_count));
        loop.trims.push_back(static_cast<int>(trims.size()));
        read_trim(reader, edge_count, trims.emplace_back());
      }
    }
  }
  return faces;
}

// Per face a flag and, when set, its render mesh object. openNURBS carries on without the meshes when they do not read,
// and so does this: none are kept then. Returns none when no face has one.
std::vector<std::optional<TriangleMesh>> read_render_meshes(const ArchiveReader& reader, std::size_t face_count) {
  ArchiveReader attempt = reader;  // the class data chunk's end is the caller's
  std::vector<std::optional<TriangleMesh>> meshes(face_count);
  bool any = false;
  try {
    for (auto& mesh : meshes) {
      if (attempt.u8() == 0) continue;
      RhinoGeometry g = read_object(attempt);
      if (auto* m = std::get_if<TriangleMesh>(&g)) {
        mesh = std::move(*m);
        any = true;
      }
    }
  } catch (const ArchiveError&) {
    any = false;
  }
  if (!any) meshes.clear();
  return meshes;
}

// Face `fi` (0-based) on its surface; throws GeometryError when a curve or the surface is missing, a loop does not
// close within its trims' 2D tolerance, or the result is invalid.
TrimmedSurface build_face(std::size_t fi, const Face& face, const Slot<NurbsSurface>& surface,
                          const std::vector<Slot<NurbsCurve>>& curves, const std::vector<Trim>& trims) {
  const std::string entity = "face " + std::to_string(fi + 1);
  if (!surface.value) throw GeometryError(entity, "surface " + std::to_string(fi) + ": " + surface.missing);
  TrimmedSurface out;
  out.surface = *surface.value;
  const double size =
      std::max(out.surface.u_end() - out.surface.u_start(), out.surface.v_end() - out.surface.v_start());
  for (std::size_t li = 0; li < face.loops.size(); ++li) {
    const Loop& loop = face.loops[li];
    const std::string loop_name = entity + " loop " + std::to_string(li + 1);
    TrimLoop built;
    double tolerance = 1e-9 * size;
    for (const int ti : loop.trims) {
      const Slot<NurbsCurve>& curve = curves[static_cast<std::size_t>(ti)];
      if (!curve.value) throw GeometryError(loop_name, "2D curve " + std::to_string(ti) + ": " + curve.missing);
      if (curve.value->dimension != 2) throw GeometryError(loop_name, "2D curve " + std::to_string(ti) + " is 3D");
      const Trim& trim = trims[static_cast<std::size_t>(ti)];
      built.segments.emplace_back(clamped(*curve.value));
      built.edges.push_back(trim.edge >= 0 ? TrimEdgeRef{trim.edge, trim.against_edge} : TrimEdgeRef{});
      tolerance = std::max(tolerance, trim.tolerance_2d);
    }
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

RhinoBrep read_brep_v2_layout(ArchiveReader& reader) {
  const std::int32_t counts[4] = {reader.i32(), reader.i32(), reader.i32(), reader.i32()};
  const std::size_t face_count = positive_count(reader, counts[0], kSurfaceBytes + kFaceBytes, "face");
  const std::size_t edge_count = positive_count(reader, counts[1], kCurveBytes, "edge");
  positive_count(reader, counts[2], kLoopBytes, "loop");
  const std::size_t trim_count = positive_count(reader, counts[3], kCurveBytes + kTrimBytes, "trim");
  reader.i32();     // outer flag: a closed solid with outward normals
  reader.point3();  // bounding box
  reader.point3();

  std::vector<Slot<NurbsCurve>> curves;
  curves.reserve(trim_count);
  for (std::size_t i = 0; i < trim_count; ++i)
    curves.push_back(read_or_skip<NurbsCurve>(reader, read_poly_curve, skip_poly_curve));
  for (std::size_t i = 0; i < edge_count; ++i) skip_poly_curve(reader);  // edges' 3D curves
  std::vector<Slot<NurbsSurface>> surfaces;
  surfaces.reserve(face_count);
  for (std::size_t i = 0; i < face_count; ++i)
    surfaces.push_back(read_or_skip<NurbsSurface>(reader, read_nurbs_surface, skip_nurbs_surface));

  std::vector<Trim> trims;
  const std::vector<Face> faces = read_faces(reader, face_count, trim_count, static_cast<int>(edge_count), trims);

  RhinoBrep brep;
  brep.edge_count = static_cast<int>(edge_count);
  brep.edge_tolerances.assign(edge_count, 0.0);
  for (const Trim& trim : trims)
    if (trim.edge >= 0) brep.edge_tolerances[trim.edge] = std::max(brep.edge_tolerances[trim.edge], trim.tolerance_3d);
  brep.render_meshes = read_render_meshes(reader, face_count);  // analysis meshes (minor 1) are not needed
  for (std::size_t fi = 0; fi < face_count; ++fi) {
    try {
      brep.faces.push_back(build_face(fi, faces[fi], surfaces[fi], curves, trims));
      brep.face_indices.push_back(static_cast<int>(fi));
    } catch (const GeometryError& e) {
      brep.skipped_faces.push_back(e.what());
      brep.skipped_face_indices.push_back(static_cast<int>(fi));
    }
  }
  return brep;
}

}  // namespace cadnurbs::rhino
