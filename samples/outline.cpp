#include "samples/outline.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace cadnurbs {

namespace {

Eigen::Vector2d left_of(const Eigen::Vector2d& v) { return {-v.y(), v.x()}; }

OutlineSegment make_arc(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double sweep) {
  OutlineSegment s;
  s.is_arc = true;
  s.start = a;
  s.end = b;
  s.sweep = sweep;
  const double chord = (b - a).norm();
  s.radius = chord / (2.0 * std::sin(std::abs(sweep) / 2.0));
  const Eigen::Vector2d mid = 0.5 * (a + b);
  s.centre = mid + (sweep > 0 ? 1.0 : -1.0) * left_of((b - a) / chord) * s.radius * std::cos(std::abs(sweep) / 2.0);
  return s;
}

// Left normal of a point on the segment: for arcs it points to the centre when turning left.
Eigen::Vector2d arc_left_normal(const OutlineSegment& s, const Eigen::Vector2d& p) {
  return (s.sweep > 0 ? -1.0 : 1.0) * (p - s.centre) / s.radius;
}

int arc_pieces(double sweep) { return static_cast<int>(std::ceil(std::abs(sweep) / (std::numbers::pi / 2) - 1e-9)); }

}  // namespace

Eigen::Vector2d OutlineSegment::start_tangent() const {
  if (!is_arc) return (end - start).normalized();
  return -left_of(arc_left_normal(*this, start));
}

Eigen::Vector2d OutlineSegment::end_tangent() const {
  if (!is_arc) return (end - start).normalized();
  return -left_of(arc_left_normal(*this, end));
}

Outline parse_outline(const std::string& text, const std::string& name) {
  Outline outline;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  bool started = false;
  Eigen::Vector2d at(0, 0);
  auto fail = [&](const std::string& reason) {
    throw std::runtime_error(name + ": line " + std::to_string(number) + ": " + reason);
  };
  while (std::getline(lines, line)) {
    ++number;
    if (auto hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::string keyword;
    if (!(words >> keyword)) continue;
    auto read_numbers = [&](int n) {
      std::vector<double> v(n);
      for (auto& x : v)
        if (!(words >> x) || !std::isfinite(x)) fail("'" + keyword + "' needs " + std::to_string(n) + " numbers");
      std::string extra;
      if (words >> extra) fail("unexpected '" + extra + "' after '" + keyword + "'");
      return v;
    };
    if (keyword == "plane") {
      if (!(words >> outline.plane) || (outline.plane != "xy" && outline.plane != "xz"))
        fail("plane must be 'xy' or 'xz'");
    } else if (keyword == "start") {
      if (started) fail("'start' given twice");
      const auto v = read_numbers(2);
      at = {v[0], v[1]};
      started = true;
    } else if (keyword == "line" || keyword == "arc") {
      if (!started) fail("'" + keyword + "' before 'start'");
      const auto v = read_numbers(keyword == "line" ? 2 : 3);
      const Eigen::Vector2d to(v[0], v[1]);
      if ((to - at).norm() < 1e-9) fail("segment of zero length");
      if (keyword == "line") {
        outline.segments.push_back({false, at, to});
      } else {
        const double sweep = v[2] * std::numbers::pi / 180.0;
        if (!(std::abs(v[2]) > 1e-9 && std::abs(v[2]) < 360.0)) fail("arc sweep must be within (-360, 360) degrees and not 0");
        outline.segments.push_back(make_arc(at, to, sweep));
      }
      at = to;
    } else {
      fail("unknown statement '" + keyword + "'");
    }
  }
  if (outline.segments.empty()) throw std::runtime_error(name + ": no segments");
  return outline;
}

void require_smooth(const Outline& outline, const std::string& name) {
  for (size_t i = 1; i < outline.segments.size(); ++i) {
    const Eigen::Vector2d a = outline.segments[i - 1].end_tangent(), b = outline.segments[i].start_tangent();
    const double turn = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
    if (std::abs(turn) > 1e-9) {
      std::ostringstream out;
      out << name << ": segment " << i + 1 << " turns " << turn * 180.0 / std::numbers::pi
          << " degrees from segment " << i << "; a swept path must be smooth";
      throw std::runtime_error(out.str());
    }
  }
}

NurbsCurve outline_to_nurbs(const Outline& outline) {
  NurbsCurve curve;
  curve.dimension = 2;
  curve.order = 3;
  auto add_piece = [&](const Eigen::Vector2d& b0, const Eigen::Vector2d& b1, const Eigen::Vector2d& b2, double w1) {
    if (curve.points.empty()) {
      curve.points.emplace_back(b0.x(), b0.y(), 0.0);
      curve.weights.push_back(1.0);
    }
    curve.points.emplace_back(b1.x(), b1.y(), 0.0);
    curve.weights.push_back(w1);
    curve.points.emplace_back(b2.x(), b2.y(), 0.0);
    curve.weights.push_back(1.0);
  };
  for (const auto& s : outline.segments) {
    if (!s.is_arc) {
      add_piece(s.start, 0.5 * (s.start + s.end), s.end, 1.0);
      continue;
    }
    const int n = arc_pieces(s.sweep);
    const double step = s.sweep / n;
    const double a0 = std::atan2(s.start.y() - s.centre.y(), s.start.x() - s.centre.x());
    for (int k = 0; k < n; ++k) {
      const double a = a0 + k * step, b = a0 + (k + 1) * step, m = 0.5 * (a + b);
      const Eigen::Vector2d p0 = k == 0 ? s.start : s.centre + s.radius * Eigen::Vector2d(std::cos(a), std::sin(a));
      const Eigen::Vector2d p2 = k == n - 1 ? s.end : s.centre + s.radius * Eigen::Vector2d(std::cos(b), std::sin(b));
      const double w = std::cos(std::abs(step) / 2.0);
      add_piece(p0, s.centre + (s.radius / w) * Eigen::Vector2d(std::cos(m), std::sin(m)), p2, w);
    }
  }
  const int pieces = (curve.count() - 1) / 2;
  curve.knots = {0, 0, 0};
  for (int k = 1; k < pieces; ++k) curve.knots.insert(curve.knots.end(), {double(k), double(k)});
  curve.knots.insert(curve.knots.end(), 3, double(pieces));
  return curve;
}

std::vector<Eigen::Vector2d> outline_offset_normals(const Outline& outline) {
  const NurbsCurve curve = outline_to_nurbs(outline);
  std::vector<Eigen::Vector2d> normals;
  size_t next = 0;  // index of the next control point to give a normal
  for (const auto& s : outline.segments) {
    const int pieces = s.is_arc ? arc_pieces(s.sweep) : 1;
    const size_t last = next == 0 ? 2 * pieces : next + 2 * pieces - 1;
    for (; next <= last; ++next) {
      const Eigen::Vector2d p = curve.points[next].head<2>();
      normals.push_back(s.is_arc ? arc_left_normal(s, p) : left_of((s.end - s.start).normalized()));
    }
  }
  return normals;
}

double angle_along_arc(const OutlineSegment& arc, const Eigen::Vector2d& q) {
  const double a0 = std::atan2(arc.start.y() - arc.centre.y(), arc.start.x() - arc.centre.x());
  const double a = std::atan2(q.y() - arc.centre.y(), q.x() - arc.centre.x()) - a0;
  return std::fmod((arc.sweep > 0 ? a : -a) + 4 * std::numbers::pi, 2 * std::numbers::pi);
}

double distance_to_segment(const OutlineSegment& s, const Eigen::Vector2d& q) {
  if (s.is_arc && angle_along_arc(s, q) <= std::abs(s.sweep)) return std::abs((q - s.centre).norm() - s.radius);
  if (s.is_arc) return std::min((q - s.start).norm(), (q - s.end).norm());
  const Eigen::Vector2d e = s.end - s.start;
  const double t = std::clamp((q - s.start).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (s.start + t * e - q).norm();
}

std::vector<OutlineSample> sample_outline(const Outline& outline, double max_chord_deviation, double radius_margin) {
  std::vector<OutlineSample> out;
  for (size_t i = 0; i < outline.segments.size(); ++i) {
    const auto& s = outline.segments[i];
    if (!s.is_arc) {
      const Eigen::Vector2d n = left_of((s.end - s.start).normalized());
      if (i == 0) out.push_back({s.start, n});
      out.push_back({s.end, n});
      continue;
    }
    // Sagitta of a chord over angle a: R (1 - cos(a/2)) <= d.
    const double max_angle = 2.0 * std::acos(std::max(-1.0, 1.0 - max_chord_deviation / (s.radius + radius_margin)));
    const int n = std::max(1, static_cast<int>(std::ceil(std::abs(s.sweep) / max_angle - 1e-12)));
    const double a0 = std::atan2(s.start.y() - s.centre.y(), s.start.x() - s.centre.x());
    for (int k = i == 0 ? 0 : 1; k <= n; ++k) {
      const double a = a0 + s.sweep * k / n;
      const Eigen::Vector2d p = k == 0 ? s.start : k == n ? s.end : s.centre + s.radius * Eigen::Vector2d(std::cos(a), std::sin(a));
      out.push_back({p, arc_left_normal(s, p)});
    }
  }
  return out;
}

}  // namespace cadnurbs
