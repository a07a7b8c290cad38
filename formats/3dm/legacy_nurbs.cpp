#include "formats/3dm/legacy_nurbs.hpp"

#include <string>
#include <vector>

#include "core/geometry_error.hpp"
#include "formats/3dm/curve_objects.hpp"
#include "formats/3dm/object_checks.hpp"
#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {

namespace {

constexpr const char* kSpline = "legacy spline";
constexpr const char* kCurve = "legacy curve";
constexpr const char* kSurface = "legacy surface";

int signed_byte(ArchiveReader& reader) { return static_cast<std::int8_t>(reader.u8()); }

// How a legacy record stores rational control points.
enum class Weights { none, euclidean, homogeneous };

// `count` points of `dimension` coordinates, each followed by its weight unless `weights` is none.
void read_points(ArchiveReader& reader, const char* record, int dimension, Weights weights, std::size_t count,
                 std::vector<Eigen::Vector3d>& points, std::vector<double>& out_weights) {
  // Checked before anything is allocated: counts come from two-byte fields, up to 65535^2 points.
  const std::size_t per_point = static_cast<std::size_t>(dimension + (weights == Weights::none ? 0 : 1)) * 8;
  if (count * per_point > reader.bytes_left())
    refuse(reader, record,
           std::to_string(count) + " control points need more than the " + std::to_string(reader.bytes_left()) +
               " bytes left");
  if (weights != Weights::euclidean) {
    read_control_points(reader, record, dimension, weights == Weights::homogeneous, count, points, out_weights);
    return;
  }
  // Euclidean points with their weights: already what core keeps (read_control_points divides).
  points.assign(count, Eigen::Vector3d::Zero());
  out_weights.assign(count, 1.0);
  for (std::size_t i = 0; i < count; ++i) {
    for (int d = 0; d < dimension; ++d) points[i][d] = reader.f64();
    out_weights[i] = reader.f64();
  }
}

}  // namespace

void open_legacy_chunk(ArchiveReader& reader, std::uint32_t stuff, const char* name) {
  constexpr std::size_t kHeader = 8;  // typecode and 4-byte length of a V1 chunk
  while (reader.bytes_left() >= kHeader) {
    const ChunkHeader h = reader.begin_chunk();
    if (h.typecode == stuff) {
      if (h.is_short()) reader.fail(std::string(name) + " chunk is a short chunk");
      return;
    }
    if (!h.is_short()) reader.end_chunk();
  }
  reader.fail(std::string("no ") + name + " chunk");
}

NurbsCurve read_legacy_spline(ArchiveReader& reader) {
  NurbsCurve curve;
  curve.dimension = expect_dimension(reader, kSpline, signed_byte(reader));
  const int rational = signed_byte(reader);
  if (rational < 0 || rational > 2) refuse(reader, kSpline, "rational flag " + std::to_string(rational) + " unknown");
  curve.order = signed_byte(reader);
  const int count = reader.u16();
  expect_order_and_count(reader, kSpline, "", curve.order, count);
  reader.skip(2);                                                 // closed and form flags (not used by openNURBS)
  reader.doubles(static_cast<std::size_t>(2 * curve.dimension));  // bounding box
  const int clamped_ends = curve.order > 2 ? signed_byte(reader) : 0;
  // openNURBS's knots (order + count - 2 values): a clamped end's order - 1 equal knots are stored once.
  const int stored_count = curve.order + count - 2;
  std::vector<double> stored;
  stored.push_back(reader.f64());
  if (clamped_ends % 2 != 0) stored.resize(static_cast<std::size_t>(curve.order - 1), stored.front());
  while (static_cast<int>(stored.size()) < count) stored.push_back(reader.f64());
  if (clamped_ends >= 2)
    stored.resize(static_cast<std::size_t>(stored_count), stored.back());
  else
    while (static_cast<int>(stored.size()) < stored_count) stored.push_back(reader.f64());
  if (curve.order == 2 && count == 2 && stored[0] > stored[1]) stored = {-stored[0], -stored[1]};
  curve.knots = with_end_knots(stored);
  read_points(reader, kSpline, curve.dimension, rational != 0 ? Weights::euclidean : Weights::none,
              static_cast<std::size_t>(count), curve.points, curve.weights);
  return checked(reader, kSpline, std::move(curve));
}

NurbsCurve read_legacy_curve(ArchiveReader& reader) {
  const int dimension = expect_dimension(reader, kCurve, signed_byte(reader));
  const int closed = signed_byte(reader);
  if (closed < -1 || closed > 2) refuse(reader, kCurve, "closed flag " + std::to_string(closed) + " unknown");
  const int segment_count = reader.i16();
  if (segment_count < 1) refuse(reader, kCurve, "segment count " + std::to_string(segment_count) + " is below 1");
  reader.doubles(static_cast<std::size_t>(2 * dimension));  // bounding box
  std::vector<NurbsCurve> segments;
  std::vector<double> breaks;
  for (int i = 0; i < segment_count; ++i) {
    const ChunkHeader h = reader.begin_chunk();
    if (h.typecode != tcode::kLegacySpline || h.is_short() || h.value == 0)
      refuse(reader, kCurve, "segment " + std::to_string(i) + " is not a legacy spline chunk");
    open_legacy_chunk(reader, tcode::kLegacySplineStuff, "legacy spline stuff");
    segments.push_back(read_legacy_spline(reader));
    reader.end_chunk();
    reader.end_chunk();
    const NurbsCurve& s = segments.back();
    if (breaks.empty()) breaks.push_back(s.domain_start());
    breaks.push_back(breaks.back() + (s.domain_end() - s.domain_start()));
  }
  if (segments.size() == 1) return std::move(segments.front());
  try {
    return checked(reader, kCurve, join_segments(segments, breaks));
  } catch (const GeometryError& e) {
    refuse(reader, kCurve, std::string("joining the segments: ") + e.what());
  }
}

NurbsSurface read_legacy_surface(ArchiveReader& reader) {
  NurbsSurface surface;
  const int dimension = expect_dimension(reader, kSurface, signed_byte(reader));
  reader.u8();  // form
  surface.u_order = signed_byte(reader) + 1;
  surface.v_order = signed_byte(reader) + 1;
  const int u_spans = reader.u16(), v_spans = reader.u16();
  if (u_spans < 1 || v_spans < 1) refuse(reader, kSurface, "a span count is 0");
  surface.u_count = surface.u_order - 1 + u_spans;
  surface.v_count = surface.v_order - 1 + v_spans;
  expect_order_and_count(reader, kSurface, "u", surface.u_order, surface.u_count);
  expect_order_and_count(reader, kSurface, "v", surface.v_order, surface.v_count);
  Weights weights = Weights::none;
  for (int direction = 0; direction < 2; ++direction) {
    const int flag = signed_byte(reader);
    if (flag == 1) weights = Weights::euclidean;
    if (flag == 2) weights = Weights::homogeneous;
  }
  reader.skip(4);  // closed and singular flags per direction (not used by openNURBS)
  reader.doubles(static_cast<std::size_t>(2 * dimension));  // bounding box
  surface.u_knots = with_end_knots(reader.doubles(static_cast<std::size_t>(surface.u_order + surface.u_count - 2)));
  surface.v_knots = with_end_knots(reader.doubles(static_cast<std::size_t>(surface.v_order + surface.v_count - 2)));
  std::vector<Eigen::Vector3d> points;  // v fastest, as stored
  std::vector<double> stored_weights;
  read_points(reader, kSurface, dimension, weights,
              static_cast<std::size_t>(surface.u_count) * static_cast<std::size_t>(surface.v_count), points,
              stored_weights);
  surface.points.resize(points.size());
  if (!stored_weights.empty()) surface.weights.resize(points.size());
  for (int i = 0; i < surface.u_count; ++i)
    for (int j = 0; j < surface.v_count; ++j) {
      const std::size_t from = static_cast<std::size_t>(i) * surface.v_count + j;
      surface.points[surface.index(i, j)] = points[from];
      if (!stored_weights.empty()) surface.weights[surface.index(i, j)] = stored_weights[from];
    }
  return checked(reader, kSurface, std::move(surface));
}

}  // namespace cadnurbs::rhino
