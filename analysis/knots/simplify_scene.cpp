#include "analysis/knots/simplify_scene.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <stdexcept>

#include "core/knot_removal.hpp"
#include "core/knot_vector.hpp"
#include "core/world_scale.hpp"

namespace cadnurbs {

namespace {

double placed_distance(const NurbsCurve& a, const NurbsCurve& b, const Eigen::Affine3d& world) {
  double worst = 0;
  const std::vector<double> breaks = domain_breaks(a.knots, a.order, a.count());
  for (size_t k = 0; k + 1 < breaks.size(); ++k)
    for (int q = 0; q <= 32; ++q) {
      const double t = breaks[k] + (breaks[k + 1] - breaks[k]) * q / 32;
      worst = std::max(worst, (world * curve_point(a, t) - world * curve_point(b, t)).norm());
    }
  return worst;
}

bool same_surface(const NurbsSurface& a, const NurbsSurface& b) {
  return a.u_order == b.u_order && a.v_order == b.v_order && a.u_count == b.u_count && a.v_count == b.v_count &&
         a.u_knots == b.u_knots && a.v_knots == b.v_knots && a.weights == b.weights && a.points == b.points;
}

// Copies of a repeated part hold equal nets under transforms whose stretches differ in the last bits;
// each kind is simplified once, so that the copies stay equal and are still written once.
class SimplifiedNets {
 public:
  NurbsSurface simplified(const NurbsSurface& net, double tolerance, int* removed) {
    const auto key = std::make_tuple(net.u_count, net.v_count, net.points.empty() ? 0.0 : net.points[0].x());
    for (auto [it, end] = done_.equal_range(key); it != end; ++it)
      if (same_surface(it->second.net, net) && std::abs(it->second.tolerance - tolerance) <= 1e-9 * tolerance) {
        *removed = it->second.removed;
        return it->second.result;
      }
    Entry entry{net, tolerance, remove_knots(net, tolerance, removed), *removed};
    return done_.emplace(key, std::move(entry))->second.result;
  }

 private:
  struct Entry {
    NurbsSurface net;
    double tolerance;
    NurbsSurface result;
    int removed;
  };
  std::multimap<std::tuple<int, int, double>, Entry> done_;
};

struct Simplifier {
  double max_move;
  SimplifyReport report;
  SimplifiedNets nets;

  void node(SceneNode& n, const Eigen::Affine3d& parent) {
    const Eigen::Affine3d world = parent * n.transform;
    // A placed point moves by at most the largest singular value times its local move.
    const double stretch = transform_scale(world);
    const double tolerance = stretch > 0 ? max_move / stretch : 0.0;
    for (auto& shape : n.shapes) {
      int removed = 0;
      if (auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
        report.control_points_before += t->surface.points.size();
        t->surface = nets.simplified(t->surface, tolerance, &removed);
        report.control_points_after += t->surface.points.size();
        report.surfaces_changed += removed > 0;
      } else if (auto* c = std::get_if<NurbsCurve>(&shape.geometry)) {
        report.control_points_before += c->count();
        const NurbsCurve before = *c;
        *c = remove_knots(*c, tolerance, &removed);
        if (removed > 0) report.curve_deviation = std::max(report.curve_deviation, placed_distance(before, *c, world));
        report.control_points_after += c->count();
        report.curves_changed += removed > 0;
      }
      report.knots_removed += removed;
    }
    for (auto& child : n.children) node(child, world);
  }
};

}  // namespace

Scene simplify_scene(const Scene& scene, double max_move, SimplifyReport* report) {
  if (!(max_move > 0) || !std::isfinite(max_move))
    throw std::invalid_argument("simplify_scene: the distance a shape may move must be a positive number");
  Scene out = scene;
  Simplifier s{max_move, {}};
  s.node(out.root, Eigen::Affine3d::Identity());
  if (report) *report = s.report;
  return out;
}

}  // namespace cadnurbs
