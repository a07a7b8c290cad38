#include "analysis/knots/whole_number_knots.hpp"

#include <algorithm>
#include <cmath>

#include "core/knot_vector.hpp"
#include "core/number_format.hpp"

namespace cadnurbs {

namespace {

// Knots that are this close (relative to the vector's length) count as the whole number: far below any
// written precision, and what CAD kernels' own arithmetic leaves on "uniform" knots.
constexpr double relative_tolerance = 1e-9;

bool all_whole_from_zero(const std::vector<double>& knots) {
  if (knots.front() != 0.0) return false;
  for (double k : knots)
    if (k != std::floor(k)) return false;
  return true;
}

}  // namespace

std::optional<KnotMap> whole_number_knot_map(const std::vector<double>& knots, int max_whole) {
  if (knots.size() < 2 || all_whole_from_zero(knots)) return std::nullopt;
  const std::vector<double> distinct = distinct_knots(knots);
  if (distinct.size() < 2) return std::nullopt;
  const double first = distinct.front(), length = distinct.back() - first;
  double shortest = length;
  for (size_t i = 1; i < distinct.size(); ++i) shortest = std::min(shortest, distinct[i] - distinct[i - 1]);
  const double tolerance = relative_tolerance * length;
  for (int divisions = 1; divisions <= 12; ++divisions) {
    const double last_whole = std::round(length / (shortest / divisions));
    if (last_whole > max_whole) break;
    const double unit = length / last_whole;  // refitted so the last knot is whole exactly
    bool fits = true;
    for (double k : distinct)
      if (std::abs((k - first) - std::round((k - first) / unit) * unit) > tolerance) fits = false;
    if (fits) return KnotMap{first, unit};
  }
  return std::nullopt;
}

std::vector<double> mapped_knots(const std::vector<double>& knots, const KnotMap& map) {
  std::vector<double> out;
  out.reserve(knots.size());
  for (double k : knots) out.push_back(std::round(map(k)));
  return out;
}

int use_whole_number_knots(NurbsCurve& curve) {
  const auto map = whole_number_knot_map(curve.knots);
  if (!map) return 0;
  curve.knots = mapped_knots(curve.knots, *map);
  return 1;
}

size_t written_length(const TrimmedSurface& face, double tolerance) {
  const NurbsSurface& s = face.surface;
  auto knots_length = [](const std::vector<double>& knots) {
    double shortest = knots.back() - knots.front();
    for (size_t i = 1; i < knots.size(); ++i)
      if (knots[i] > knots[i - 1]) shortest = std::min(shortest, knots[i] - knots[i - 1]);
    size_t length = 0;
    for (double k : knots) length += format_number(k, {1e-3 * shortest}).size() + 1;
    return length;
  };
  const NumberPrecision uv{0.5 * trim_parameter_tolerance(s, tolerance)};
  size_t length = knots_length(s.u_knots) + knots_length(s.v_knots);
  for (const auto& loop : face.loops)
    for (const auto& segment : loop.segments) {
      if (const auto* polyline = std::get_if<Polyline2D>(&segment)) {
        for (const auto& p : polyline->points) length += format_number(p.x(), uv).size() + format_number(p.y(), uv).size() + 2;
      } else {
        const auto& c = std::get<NurbsCurve>(segment);
        for (const auto& p : c.points) length += format_number(p.x(), uv).size() + format_number(p.y(), uv).size() + 2;
        length += knots_length(c.knots);
      }
    }
  return length;
}

namespace {

// The face with its u and/or v knots mapped, trims mapped along.
TrimmedSurface mapped_face(const TrimmedSurface& face, const std::optional<KnotMap>& u_map,
                           const std::optional<KnotMap>& v_map) {
  TrimmedSurface out = face;
  NurbsSurface& s = out.surface;
  if (u_map) s.u_knots = mapped_knots(s.u_knots, *u_map);
  if (v_map) s.v_knots = mapped_knots(s.v_knots, *v_map);
  const KnotMap u = u_map.value_or(KnotMap{}), v = v_map.value_or(KnotMap{});
  auto to_new_domain = [&](const Eigen::Vector2d& p) { return Eigen::Vector2d(u(p.x()), v(p.y())); };
  for (auto& loop : out.loops)
    for (auto& segment : loop.segments) {
      if (auto* polyline = std::get_if<Polyline2D>(&segment)) {
        for (auto& p : polyline->points) p = to_new_domain(p);
      } else {
        for (auto& p : std::get<NurbsCurve>(segment).points) p.head<2>() = to_new_domain(p.head<2>());
      }
    }
  return out;
}

}  // namespace

int use_whole_number_knots(TrimmedSurface& face, double tolerance) {
  int changed = 0;
  const auto u_map = whole_number_knot_map(face.surface.u_knots);
  const auto v_map = whole_number_knot_map(face.surface.v_knots);
  if (u_map || v_map) {
    // The shortest of the four choices (each map taken or not).
    TrimmedSurface best = face;
    size_t best_length = written_length(face, tolerance);
    int best_count = 0;
    for (int choice = 1; choice < 4; ++choice) {
      const bool use_u = choice & 1, use_v = choice & 2;
      if ((use_u && !u_map) || (use_v && !v_map)) continue;
      TrimmedSurface candidate = mapped_face(face, use_u ? u_map : std::nullopt, use_v ? v_map : std::nullopt);
      const size_t length = written_length(candidate, tolerance);
      if (length < best_length) {
        best = std::move(candidate);
        best_length = length;
        best_count = int(use_u) + int(use_v);
      }
    }
    face = std::move(best);
    changed += best_count;
  }
  for (auto& loop : face.loops)
    for (auto& segment : loop.segments)
      if (auto* curve = std::get_if<NurbsCurve>(&segment)) changed += use_whole_number_knots(*curve);
  return changed;
}

}  // namespace cadnurbs
