#include "formats/3dm/curve_objects.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/bezier_extraction.hpp"
#include "core/geometry_error.hpp"
#include "core/knot_insertion.hpp"
#include "core/number_format.hpp"
#include "formats/3dm/object_checks.hpp"
#include "formats/3dm/rhino_object.hpp"

namespace cadnurbs::rhino {

namespace {

// openNURBS's ON_SQRT_EPSILON and ON_ZERO_TOLERANCE: the slack of its arc span count and full-circle test.
constexpr double kSqrtEpsilon = 1.490116119384765625e-8;
constexpr double kZeroTolerance = 1.0e-12;

Eigen::Vector3d in_dimension(Eigen::Vector3d p, int dimension) {
  if (dimension == 2) p.z() = 0.0;
  return p;
}

// Order 2 through `points` with `params` as breaks.
NurbsCurve polyline_nurbs(std::vector<Eigen::Vector3d> points, const std::vector<double>& params, int dimension) {
  NurbsCurve c;
  c.dimension = dimension;
  c.order = 2;
  c.knots = with_end_knots(params);
  for (auto& p : points) p = in_dimension(p, dimension);
  c.points = std::move(points);
  return c;
}

// ON_Circle as written: plane (origin, x, y, z axes, equation), radius, then three points openNURBS
// no longer reads.
CircularArc read_circle(ArchiveReader& reader) {
  CircularArc arc;
  arc.center = reader.point3();
  arc.x_axis = reader.point3();
  arc.y_axis = reader.point3();
  reader.skip(3 * 8 + 4 * 8);  // z axis and plane equation: implied by the two others
  arc.radius = reader.f64();
  reader.skip(9 * 8);
  return arc;
}

// ON_ArcCurve's data (an ON_Arc: circle and angle interval), or the obsolete circle curve's (a circle, a
// full turn), then the domain and the dimension.
NurbsCurve read_arc_or_circle(ArchiveReader& reader, const char* class_name, bool has_angles) {
  expect_major_version(reader, class_name, 1);
  CircularArc arc = read_circle(reader);
  arc.angle0 = has_angles ? reader.f64() : 0.0;
  arc.angle1 = has_angles ? reader.f64() : 2.0 * std::numbers::pi;
  const auto [t0, t1] = read_increasing_interval(reader, class_name, "domain");
  // openNURBS's own rule for this field: anything but 2 means 3.
  const int dimension = reader.i32() == 2 ? 2 : 3;
  if (!(arc.radius > 0.0) || !std::isfinite(arc.radius))
    refuse(reader, class_name, "radius " + number_text(arc.radius, 17) + " is not positive");
  const double angle = arc.angle1 - arc.angle0;
  if (!(angle > 0.0) || angle > 2.0 * std::numbers::pi + kZeroTolerance)
    refuse(reader, class_name,
           "angle interval [" + number_text(arc.angle0, 17) + ", " + number_text(arc.angle1, 17) +
               "] is not in (0, 2 pi]");
  return checked(reader, class_name, arc_as_nurbs(arc, t0, t1, dimension));
}

// The affine map of the knots from the curve's domain onto [t0, t1]: each knot measured from the nearer
// domain end, so that both ends land exactly on t0 and t1 (the arithmetic of ON_NurbsCurve::SetDomain).
void set_domain(NurbsCurve& c, double t0, double t1) {
  const double k0 = c.domain_start(), k1 = c.domain_end();
  if (k0 == t0 && k1 == t1) return;
  const double scale = (t1 - t0) / (k1 - k0);
  const double middle = 0.5 * (k0 + k1);
  for (double& k : c.knots) k = k <= middle ? (k - k0) * scale + t0 : (k - k1) * scale + t1;
}

std::vector<Eigen::Vector4d> homogeneous(const NurbsCurve& c) {
  std::vector<Eigen::Vector4d> h(c.points.size());
  for (size_t i = 0; i < h.size(); ++i) {
    const double w = c.weight(static_cast<int>(i));
    h[i] << w * c.points[i], w;
  }
  return h;
}

// A Bezier piece (clamped, order CVs) raised by one degree: Q_i = i/(p+1) P_{i-1} + (1 - i/(p+1)) P_i.
NurbsCurve raised_bezier(const NurbsCurve& bezier) {
  const std::vector<Eigen::Vector4d> h = homogeneous(bezier);
  const int p = bezier.degree();
  NurbsCurve out = bezier;
  out.order = bezier.order + 1;
  out.knots.insert(out.knots.begin(), bezier.knots.front());
  out.knots.push_back(bezier.knots.back());
  out.points.resize(p + 2);
  if (bezier.is_rational()) out.weights.resize(p + 2);
  for (int i = 0; i <= p + 1; ++i) {
    const double a = static_cast<double>(i) / (p + 1);
    const Eigen::Vector4d q = i == 0 ? h[0] : i == p + 1 ? h[p] : Eigen::Vector4d(a * h[i - 1] + (1.0 - a) * h[i]);
    if (bezier.is_rational()) {
      out.weights[i] = q[3];
      out.points[i] = q.head<3>() * (1.0 / q[3]);
    } else {
      out.points[i] = q.head<3>();
    }
  }
  return out;
}

// Chains clamped curves of one order and one rationality whose domains follow each other: knots of
// multiplicity degree at the joints, the joint CV taken from the earlier curve, the later curve's weights
// scaled so that the joint weights agree.
NurbsCurve chain(const std::vector<NurbsCurve>& pieces) {
  NurbsCurve out = pieces.front();
  for (size_t s = 1; s < pieces.size(); ++s) {
    const NurbsCurve& next = pieces[s];
    out.dimension = std::max(out.dimension, next.dimension);
    out.knots.pop_back();
    out.knots.insert(out.knots.end(), next.knots.begin() + next.order, next.knots.end());
    out.points.insert(out.points.end(), next.points.begin() + 1, next.points.end());
    if (out.is_rational()) {
      const double scale = out.weights.back() / next.weights.front();
      for (size_t i = 1; i < next.weights.size(); ++i) out.weights.push_back(next.weights[i] * scale);
    }
  }
  return out;
}

}  // namespace

NurbsCurve read_nurbs_curve(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_NurbsCurve";
  expect_major_version(reader, kClass, 1);
  const int dimension = reader.i32();
  const bool rational = reader.i32() != 0;
  const int order = reader.i32();
  const int cv_count = reader.i32();
  reader.skip(2 * 4 + 6 * 8);  // two reserved ints, a bounding box written empty
  expect_dimension(reader, kClass, dimension);
  expect_order_and_count(reader, kClass, "", order, cv_count);
  std::vector<double> knots = read_knots(reader, kClass, "", order, cv_count);
  const int cv_size = dimension + (rational ? 1 : 0);
  const std::size_t stored_cvs = read_count(reader, kClass, 8 * static_cast<std::size_t>(cv_size), "control points");
  if (static_cast<std::int64_t>(stored_cvs) != cv_count)
    refuse(reader, kClass, std::to_string(stored_cvs) + " control points stored, the header says " + std::to_string(cv_count));

  NurbsCurve c;
  c.dimension = dimension;
  c.order = order;
  c.knots = std::move(knots);
  read_control_points(reader, kClass, dimension, rational, stored_cvs, c.points, c.weights);
  return checked(reader, kClass, std::move(c));
}

NurbsCurve read_line_curve(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_LineCurve";
  expect_major_version(reader, kClass, 1);
  const Eigen::Vector3d from = reader.point3();
  const Eigen::Vector3d to = reader.point3();
  const auto [t0, t1] = read_increasing_interval(reader, kClass, "domain");
  const int dimension = expect_dimension(reader, kClass, reader.i32());
  return checked(reader, kClass, polyline_nurbs({from, to}, {t0, t1}, dimension));
}

NurbsCurve read_arc_curve(ArchiveReader& reader) {
  return read_arc_or_circle(reader, "ON_ArcCurve", true);
}

NurbsCurve read_obsolete_circle_curve(ArchiveReader& reader) {
  return read_arc_or_circle(reader, "ON_CircleCurve", false);
}

NurbsCurve read_polyline_curve(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_PolylineCurve";
  expect_major_version(reader, kClass, 1);
  const std::size_t point_count = read_count(reader, kClass, 3 * 8, "points");
  std::vector<Eigen::Vector3d> points(point_count);
  for (auto& p : points) p = reader.point3();
  const std::size_t param_count = read_count(reader, kClass, 8, "parameters");
  const std::vector<double> params = reader.doubles(param_count);
  const int dimension = expect_dimension(reader, kClass, reader.i32());
  if (point_count < 2) refuse(reader, kClass, std::to_string(point_count) + " points; a polyline needs 2 at least");
  if (param_count != point_count)
    refuse(reader, kClass, std::to_string(param_count) + " parameters for " + std::to_string(point_count) + " points");
  for (std::size_t i = 1; i < params.size(); ++i)
    if (!(params[i - 1] < params[i]))
      refuse(reader, kClass, "parameter " + std::to_string(i) + " (" + number_text(params[i], 17) +
                                 ") does not exceed the one before (" + number_text(params[i - 1], 17) + ")");
  return checked(reader, kClass, polyline_nurbs(std::move(points), params, dimension));
}

NurbsCurve read_poly_curve(ArchiveReader& reader) {
  constexpr const char* kClass = "ON_PolyCurve";
  expect_major_version(reader, kClass, 1);
  const int segment_count = reader.i32();
  reader.skip(2 * 4 + 6 * 8);  // two reserved ints, a bounding box written empty
  const std::size_t break_count = read_count(reader, kClass, 8, "segment parameters");
  const std::vector<double> breaks = reader.doubles(break_count);
  if (segment_count < 1) refuse(reader, kClass, std::to_string(segment_count) + " segments");
  if (static_cast<std::int64_t>(break_count) != std::int64_t{segment_count} + 1)
    refuse(reader, kClass, std::to_string(break_count) + " segment parameters for " + std::to_string(segment_count) +
                               " segments (need one more than segments)");
  for (std::size_t i = 1; i < breaks.size(); ++i)
    if (!(breaks[i - 1] < breaks[i]))
      refuse(reader, kClass, "segment parameter " + std::to_string(i) + " (" + number_text(breaks[i], 17) +
                                 ") does not exceed the one before (" + number_text(breaks[i - 1], 17) + ")");
  std::vector<NurbsCurve> segments;
  segments.reserve(segment_count);
  for (int i = 0; i < segment_count; ++i)
    segments.push_back(nested_curve(reader, kClass, "segment " + std::to_string(i)));
  try {
    return checked(reader, kClass, join_segments(segments, breaks));
  } catch (const GeometryError& e) {
    refuse(reader, kClass, std::string("joining the segments: ") + e.what());
  }
}

NurbsCurve arc_as_nurbs(const CircularArc& arc, double t0, double t1, int dimension) {
  const double angle = arc.angle1 - arc.angle0;
  // Spans of at most a quarter turn (with openNURBS's slack, so that its span count and knots come out):
  // 1, 2 or 4 equal spans, a three-quarter arc getting 4 as in ON_ArcCurve::GetNurbForm.
  const double quarter = (0.5 + kSqrtEpsilon) * std::numbers::pi;
  const int spans = angle <= quarter ? 1 : angle <= 2.0 * quarter ? 2 : 4;
  const double span_angle = angle / spans;
  const double middle_weight = std::cos(0.5 * span_angle);
  const bool full_turn = std::abs(angle - 2.0 * std::numbers::pi) <= kZeroTolerance;
  auto on_circle = [&](double a) {
    return Eigen::Vector3d(arc.center + (std::cos(a) * arc.radius) * arc.x_axis + (std::sin(a) * arc.radius) * arc.y_axis);
  };

  NurbsCurve c;
  c.dimension = dimension;
  c.order = 3;
  const int count = 2 * spans + 1;
  c.points.resize(count);
  c.weights.assign(count, 1.0);
  // CV k sits at angle0 + k / (2 spans) of the way (fractions exact in binary: 1/2, 1/4, 1/8...).
  for (int k = 0; k < count - 1; ++k) {
    const Eigen::Vector3d on_arc = on_circle(arc.angle0 + (static_cast<double>(k) / (count - 1)) * angle);
    if (k % 2 == 0) {
      c.points[k] = on_arc;
    } else {
      // A span's middle CV: where the end tangents meet, radius / cos(half the span) from the centre along
      // the bisector; formed as openNURBS forms it, (bisector point + (w - 1) centre) * (1 / w).
      c.points[k] = (on_arc + (middle_weight - 1.0) * arc.center) * (1.0 / middle_weight);
      c.weights[k] = middle_weight;
    }
  }
  c.points[count - 1] = full_turn ? c.points[0] : on_circle(arc.angle1);
  // angle0 three times, each inner span start twice (accumulated as openNURBS does), angle1 three times.
  c.knots.assign(3, arc.angle0);
  double start = arc.angle0;
  for (int s = 1; s < spans; ++s) {
    start += span_angle;
    c.knots.push_back(start);
    c.knots.push_back(start);
  }
  c.knots.insert(c.knots.end(), 3, arc.angle1);
  for (auto& p : c.points) p = in_dimension(p, dimension);
  set_domain(c, t0, t1);
  return c;
}

double arc_nurbs_parameter(const CircularArc& arc, double t0, double t1, double s) {
  const NurbsCurve nurbs = arc_as_nurbs(arc, t0, t1, 3);
  const int spans = (nurbs.count() - 1) / 2;
  const double angle = arc.angle1 - arc.angle0;
  const double span_angle = angle / spans;
  const double from_start = std::clamp((s - t0) / (t1 - t0), 0.0, 1.0) * angle;
  const int k = std::min(static_cast<int>(from_start / span_angle), spans - 1);
  const double half = 0.5 * span_angle;
  const double phi = from_start - k * span_angle - half;
  const double v = 0.5 * (1.0 + std::tan(0.5 * phi) / std::tan(0.5 * half));
  const double u0 = nurbs.knots[2 * k + 1], u1 = nurbs.knots[2 * k + 3];
  return u0 + (u1 - u0) * v;
}

NurbsCurve clamped(const NurbsCurve& curve) {
  const int p = curve.degree();
  NurbsCurve c = curve;
  const double a = c.domain_start();
  if (c.knots.front() != a) {
    const int multiplicity = static_cast<int>(std::count(c.knots.begin(), c.knots.end(), a));
    if (multiplicity < p) c = insert_knot(c, a, p - multiplicity);
    // With a at least p times ending at index k, the curve starts at CV k - p: drop what is before it.
    const int k = static_cast<int>(std::upper_bound(c.knots.begin(), c.knots.end(), a) - c.knots.begin()) - 1;
    const int drop = k - p;
    c.knots.erase(c.knots.begin(), c.knots.begin() + drop);
    c.points.erase(c.points.begin(), c.points.begin() + drop);
    if (c.is_rational()) c.weights.erase(c.weights.begin(), c.weights.begin() + drop);
    c.knots.front() = a;
  }
  const double b = c.domain_end();
  if (c.knots.back() != b) {
    const int multiplicity = static_cast<int>(std::count(c.knots.begin(), c.knots.end(), b));
    if (multiplicity < p) c = insert_knot(c, b, p - multiplicity);
    // With b at least p times starting at index j, the curve ends at CV j - 1: keep CVs 0..j-1.
    const int j = static_cast<int>(std::lower_bound(c.knots.begin(), c.knots.end(), b) - c.knots.begin());
    c.points.resize(j);
    if (c.is_rational()) c.weights.resize(j);
    c.knots.resize(j + c.order);
    c.knots.back() = b;
  }
  return c;
}

NurbsCurve with_order(const NurbsCurve& curve, int order) {
  if (order <= curve.order) return curve;
  std::vector<NurbsCurve> pieces = bezier_segments(curve);
  for (auto& piece : pieces)
    while (piece.order < order) piece = raised_bezier(piece);
  return chain(pieces);
}

NurbsCurve join_segments(const std::vector<NurbsCurve>& segments, const std::vector<double>& breaks) {
  if (segments.empty() || breaks.size() != segments.size() + 1)
    throw GeometryError("joined segments", std::to_string(breaks.size()) + " breaks for " +
                                               std::to_string(segments.size()) + " segments");
  int order = 2;
  bool rational = false;
  for (const auto& s : segments) {
    order = std::max(order, s.order);
    rational = rational || s.is_rational();
  }
  std::vector<NurbsCurve> pieces;
  pieces.reserve(segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i) {
    NurbsCurve piece = segments[i];
    set_domain(piece, breaks[i], breaks[i + 1]);
    piece = with_order(clamped(piece), order);
    if (rational && !piece.is_rational()) piece.weights.assign(piece.points.size(), 1.0);
    pieces.push_back(std::move(piece));
  }
  return chain(pieces);
}

}  // namespace cadnurbs::rhino
