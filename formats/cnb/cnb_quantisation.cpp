#include "formats/cnb/cnb_quantisation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/knot_removal.hpp"
#include "core/refit_cubic_within.hpp"
#include "core/world_scale.hpp"
#include "formats/cnb/cnb_numbers.hpp"

namespace cadnurbs::cnb {

namespace {
void check(const CnbOptions& o) {
  if (!(o.max_deviation > 0) || !std::isfinite(o.max_deviation))
    throw std::invalid_argument("cnb: the maximum deviation must be positive and finite");
  if (!(o.trim_share > 0 && o.trim_share < 1)) throw std::invalid_argument("cnb: trim_share must lie in (0, 1)");
  if (!(o.mesh_deviation >= 0 && o.mesh_deviation <= o.trim_share * o.max_deviation))
    throw std::invalid_argument("cnb: mesh_deviation must lie in [0, trim_share * max_deviation]");
  if (!(o.quantisation_scale > 0 && o.quantisation_scale <= 1))
    throw std::invalid_argument("cnb: quantisation_scale must lie in (0, 1]");
}
}  // namespace

double point_share(const CnbOptions& options) {
  return (1.0 - options.trim_share) * options.quantisation_scale * options.max_deviation;
}

double point_step(const Scene& scene, const CnbOptions& options) {
  check(options);
  return 2.0 * point_share(options) / (std::sqrt(3.0) * largest_world_scale(scene));
}

double decimal_step(double largest) {
  constexpr double hundredth = 0.01;
  if (!(largest > 0) || !std::isfinite(largest)) return largest;
  if (largest >= hundredth) return hundredth * std::floor(largest / hundredth + 1e-9);
  const double n = std::ceil(hundredth / largest - 1e-9);
  return hundredth / n <= largest ? hundredth / n : hundredth / (n + 1);
}

namespace {
// Every control point and vertex of the scene's shapes with the linear part of its world transform.
template <typename Visit>
void visit_points(const SceneNode& node, const Eigen::Affine3d& parent, const Visit& visit) {
  const Eigen::Affine3d world = parent * node.transform;
  const Eigen::Matrix3d linear = world.linear();
  for (const auto& shape : node.shapes) {
    const auto each = [&](const std::vector<Eigen::Vector3d>& points) {
      for (const auto& p : points) visit(p, linear);
    };
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry))
      each(t->surface.points);
    else if (const auto* c = std::get_if<NurbsCurve>(&shape.geometry))
      each(c->points);
    else if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry))
      each(m->positions);
    else
      each(std::get<PolygonMesh>(shape.geometry).positions);
  }
  for (const auto& child : node.children) visit_points(child, world, visit);
}

Eigen::Vector3d decoded(const Eigen::Vector3d& p, double q) {
  return {static_cast<double>(on_grid(p.x(), q)) * q, static_cast<double>(on_grid(p.y(), q)) * q,
          static_cast<double>(on_grid(p.z(), q)) * q};
}

template <typename Visit>
void visit_meshes(const SceneNode& node, const Visit& visit) {
  for (const auto& shape : node.shapes) {
    if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry)) {
      for (const auto& t : m->triangles) visit(m->positions, t.data(), t.size());
    } else if (const auto* p = std::get_if<PolygonMesh>(&shape.geometry)) {
      for (const auto& polygon : p->polygons) visit(p->positions, polygon.data(), polygon.size());
    }
  }
  for (const auto& child : node.children) visit_meshes(child, visit);
}
}  // namespace

double largest_point_move(const Scene& scene, double q) {
  double largest = 0.0;
  visit_points(scene.root, Eigen::Affine3d::Identity(), [&](const Eigen::Vector3d& p, const Eigen::Matrix3d& linear) {
    largest = std::max(largest, (linear * (decoded(p, q) - p)).norm());
  });
  return largest;
}

std::vector<std::array<int64_t, 3>> shared_grid_points(const Scene& scene, double q) {
  std::vector<std::array<int64_t, 3>> all;
  visit_points(scene.root, Eigen::Affine3d::Identity(), [&](const Eigen::Vector3d& p, const Eigen::Matrix3d&) {
    all.push_back({on_grid(p.x(), q), on_grid(p.y(), q), on_grid(p.z(), q)});
  });
  std::sort(all.begin(), all.end());
  std::vector<std::array<int64_t, 3>> shared;
  for (size_t i = 1; i < all.size(); ++i)
    if (all[i] == all[i - 1] && (shared.empty() || shared.back() != all[i])) shared.push_back(all[i]);
  return shared;
}

long collapsed_faces(const Scene& scene, double q) {
  long collapsed = 0;
  visit_meshes(scene.root, [&](const std::vector<Eigen::Vector3d>& positions, const int* corners, size_t n) {
    std::vector<Eigen::Vector3d> on_grid_corners;
    for (size_t k = 0; k < n; ++k) on_grid_corners.push_back(decoded(positions[corners[k]], q));
    for (size_t a = 0; a < n; ++a)
      for (size_t b = a + 1; b < n; ++b)
        if (on_grid_corners[a] == on_grid_corners[b]) {
          ++collapsed;
          return;
        }
  });
  return collapsed;
}

int trim_step_exponent(const NurbsSurface& surface, const CnbOptions& options, double world_scale) {
  check(options);
  const double bound = surface_derivative_bound(surface) * std::max(world_scale, 1e-300);
  double step;
  if (bound > 0.0 && std::isfinite(bound)) {
    step = options.trim_share * options.max_deviation * options.quantisation_scale / (2.0 * bound);
  } else {
    const double domain = std::max(surface.u_end() - surface.u_start(), surface.v_end() - surface.v_start());
    step = domain > 0 ? domain / 1024.0 : 1.0;
  }
  // floor(log2(step)), then one lower if rounding made 2^e larger than step.
  int e = static_cast<int>(std::floor(std::log2(step)));
  e = std::clamp(e, -100, 100);
  while (e > -100 && std::ldexp(1.0, e) > step) --e;
  return e;
}

int trim_step_exponent_keeping_loops(const std::vector<TrimLoop>& loops, int exponent) {
  for (const auto& loop : loops) {
    Eigen::AlignedBox2d box;
    for (const auto& segment : loop.segments) {
      if (const auto* curve = std::get_if<NurbsCurve>(&segment))
        for (const auto& p : curve->points) box.extend(p.head<2>());
      else
        for (const auto& p : std::get<Polyline2D>(segment).points) box.extend(p);
    }
    if (box.isEmpty()) continue;
    const double extent = box.sizes().minCoeff();
    if (!(extent > 0)) continue;
    while (exponent > -100 && std::ldexp(1.0, exponent) * loop_steps > extent) --exponent;
  }
  return exponent;
}

double trim_bound(const NurbsSurface& surface, int exponent, double world_scale) {
  return 2.0 * surface_derivative_bound(surface) * std::ldexp(1.0, exponent) * world_scale;
}

bool has_spare_knot_candidates(const NurbsCurve& curve) {
  return curve.knots.size() > 2 * static_cast<size_t>(curve.order);
}

double spare_trim_tolerance(const NurbsSurface& surface, double slack, double world_scale) {
  const double per_uv = std::sqrt(2.0) * surface_derivative_bound(surface) * world_scale;  // √2·L·scale
  if (!(slack > 0) || !(per_uv > 0) || !std::isfinite(per_uv)) return 0.0;
  return slack / per_uv;
}

std::vector<TrimLoop> trims_with_fewer_knots(const std::vector<TrimLoop>& loops, double uv_tolerance,
                                             long* removed) {
  std::vector<TrimLoop> result = loops;
  if (!(uv_tolerance > 0)) return result;
  for (auto& loop : result)
    for (auto& segment : loop.segments)
      if (auto* curve = std::get_if<NurbsCurve>(&segment); curve && has_spare_knot_candidates(*curve)) {
        const size_t knots_before = curve->knots.size();
        NurbsCurve fewer = remove_knots(*curve, uv_tolerance);
        if (std::optional<NurbsCurve> cubic = refit_cubic_within(*curve, uv_tolerance);
            cubic && cubic->points.size() < fewer.points.size())
          fewer = std::move(*cubic);
        if (fewer.knots.size() < knots_before) {
          if (removed) *removed += static_cast<long>(knots_before - fewer.knots.size());
          *curve = std::move(fewer);
        }
      }
  return result;
}

namespace {
double net_diagonal(const NurbsSurface& s) {
  Eigen::AlignedBox3d box;
  for (const auto& p : s.points) box.extend(p);
  return box.diagonal().norm();
}
}  // namespace

bool quantises_weights(const NurbsSurface& surface) {
  return surface.is_rational() && distinct_count(surface.weights) > exact_weight_limit;
}

double weight_log_step(const NurbsSurface& surface, double budget, double world_scale) {
  const double reach = net_diagonal(surface) * world_scale;
  if (!(reach > 0)) return 0.5;  // all control points equal: the weights cannot move the surface
  // ε/(1-ε)·reach = budget  <=>  ε = budget / (reach + budget); h = 2·log2(1 + ε), a little less for rounding.
  const double epsilon = budget / (reach + budget);
  return std::min(0.5, 0.999 * 2.0 * std::log2(1.0 + epsilon));
}

namespace {
// The world move of a surface whose weights are each off by a relative error of at most `epsilon`.
double relative_weight_error_bound(const NurbsSurface& surface, double epsilon, double world_scale) {
  return epsilon / (1.0 - epsilon) * net_diagonal(surface) * world_scale;
}
}  // namespace

double weight_bound(const NurbsSurface& surface, double log_step, double world_scale) {
  return relative_weight_error_bound(surface, std::exp2(log_step / 2.0) - 1.0, world_scale);
}

WeightCoding weight_coding(const NurbsSurface& surface, double trim_budget, double world_scale) {
  WeightCoding coding;
  if (!surface.is_rational()) return coding;
  constexpr double largest_factor_error = 1e-4, largest_factor_share = 1.0 / 64;
  if (auto factors = weight_factors(surface.weights, surface.u_count, surface.v_count, largest_factor_error)) {
    const double bound = relative_weight_error_bound(surface, factors->relative_error, world_scale);
    if (bound <= largest_factor_share * trim_budget) {
      coding.factors = std::move(factors);
      coding.bound = bound;
      coding.trim_fraction = trim_budget > 0 ? 1.0 - bound / trim_budget : 1.0;
      return coding;
    }
  }
  if (quantises_weights(surface)) {
    coding.log_step = weight_log_step(surface, trim_budget / 2, world_scale);
    coding.bound = weight_bound(surface, coding.log_step, world_scale);
    coding.trim_fraction = 0.5;
  }
  return coding;
}

}  // namespace cadnurbs::cnb
