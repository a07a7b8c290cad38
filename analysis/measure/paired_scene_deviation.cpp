#include "analysis/measure/paired_scene_deviation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "core/knot_vector.hpp"

namespace cadnurbs {

double PairedDeviation::max() const { return std::max({surfaces, boundaries, curves, meshes}); }

namespace {

// Parameters over [knots[order-1], knots[count]]: every distinct knot and `per_span` points inside each
// span, thinned to at most 256.
std::vector<double> sample_parameters(const std::vector<double>& knots, int order, int count, int per_span) {
  const std::vector<double> distinct = domain_breaks(knots, order, count);
  const int spans = std::max<int>(1, static_cast<int>(distinct.size()) - 1);
  const int per = std::max(1, std::min(per_span, 256 / spans));
  std::vector<double> t;
  for (size_t s = 0; s + 1 < distinct.size(); ++s)
    for (int k = 0; k < per; ++k) t.push_back(distinct[s] + (distinct[s + 1] - distinct[s]) * k / per);
  t.push_back(distinct.back());
  return t;
}

// Samples per span of a trimming curve's image against which the other curve's samples find their nearest
// point (thinned to 256 in all, as sample_parameters thins).
constexpr int kDenseSamples = 256;

[[noreturn]] void differ(const std::string& where, const std::string& what) {
  throw std::invalid_argument("paired_scene_deviation: " + where + ": " + what + " differ");
}

struct Comparison {
  int per_span;
  PairedDeviation result;

  void distance(double& field, const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    field = std::max(field, (a - b).norm());
    ++result.samples;
  }

  // The distance from p to the nearest point of the polyline through `line`.
  void nearest_on_polyline(double& field, const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& line) {
    double nearest = line.empty() ? 0.0 : (p - line.front()).norm();
    for (size_t i = 0; i + 1 < line.size(); ++i) {
      const Eigen::Vector3d d = line[i + 1] - line[i];
      const double length2 = d.squaredNorm();
      const double f = length2 > 0 ? std::clamp((p - line[i]).dot(d) / length2, 0.0, 1.0) : 0.0;
      nearest = std::min(nearest, (p - (line[i] + f * d)).norm());
    }
    field = std::max(field, nearest);
    ++result.samples;
  }

  void surface(const TrimmedSurface& a, const TrimmedSurface& b, const Eigen::Affine3d& wa, const Eigen::Affine3d& wb,
               const std::string& where) {
    const NurbsSurface &sa = a.surface, &sb = b.surface;
    if (sa.u_count != sb.u_count || sa.v_count != sb.v_count || sa.u_order != sb.u_order || sa.v_order != sb.v_order)
      differ(where, "net sizes or orders");
    if (a.loops.size() != b.loops.size()) differ(where, "loop counts");
    const auto us = sample_parameters(sa.u_knots, sa.u_order, sa.u_count, per_span);
    const auto vs = sample_parameters(sa.v_knots, sa.v_order, sa.v_count, per_span);
    for (double u : us)
      for (double v : vs) distance(result.surfaces, wa * surface_point(sa, u, v), wb * surface_point(sb, u, v));
    for (size_t l = 0; l < a.loops.size(); ++l) {
      const auto &la = a.loops[l], &lb = b.loops[l];
      if (la.segments.size() != lb.segments.size()) differ(where, "segment counts of loop " + std::to_string(l));
      for (size_t s = 0; s < la.segments.size(); ++s) {
        const auto* ca = std::get_if<NurbsCurve>(&la.segments[s]);
        const auto* cb = std::get_if<NurbsCurve>(&lb.segments[s]);
        if (!ca != !cb) differ(where, "kinds of segment " + std::to_string(s) + " of loop " + std::to_string(l));
        const auto on_a = [&](const Eigen::Vector2d& p) { return wa * surface_point(sa, p.x(), p.y()); };
        const auto on_b = [&](const Eigen::Vector2d& p) { return wb * surface_point(sb, p.x(), p.y()); };
        if (ca && (ca->order != cb->order || ca->knots.front() != cb->knots.front() ||
                   ca->knots.back() != cb->knots.back())) {
          // Another curve for the same boundary (the .cnb writer refits approximated pcurves): the images
          // compared both ways.
          const auto image = [&](const NurbsCurve& c, const auto& on, int per) {
            std::vector<Eigen::Vector3d> points;
            for (double t : sample_parameters(c.knots, c.order, c.count(), per)) points.push_back(on(curve_point(c, t).head<2>()));
            return points;
          };
          const std::vector<Eigen::Vector3d> image_a = image(*ca, on_a, per_span), image_b = image(*cb, on_b, per_span);
          const std::vector<Eigen::Vector3d> dense_a = image(*ca, on_a, kDenseSamples), dense_b = image(*cb, on_b, kDenseSamples);
          for (const auto& p : image_a) nearest_on_polyline(result.boundaries, p, dense_b);
          for (const auto& p : image_b) nearest_on_polyline(result.boundaries, p, dense_a);
        } else if (ca) {
          // Knots may differ (the .cnb writer removes spare ones), the parametrisation not.
          for (double t : sample_parameters(ca->knots, ca->order, ca->count(), per_span))
            distance(result.boundaries, on_a(curve_point(*ca, t).head<2>()), on_b(curve_point(*cb, t).head<2>()));
        } else {
          const auto &pa = std::get<Polyline2D>(la.segments[s]).points, &pb = std::get<Polyline2D>(lb.segments[s]).points;
          if (pa.size() != pb.size()) differ(where, "polyline sizes");
          for (size_t i = 0; i + 1 < pa.size(); ++i)
            for (int k = 0; k <= per_span; ++k) {
              const double f = static_cast<double>(k) / per_span;
              distance(result.boundaries, on_a((1 - f) * pa[i] + f * pa[i + 1]), on_b((1 - f) * pb[i] + f * pb[i + 1]));
            }
        }
      }
    }
  }

  void geometry(const Geometry& a, const Geometry& b, const Eigen::Affine3d& wa, const Eigen::Affine3d& wb,
                const std::string& where) {
    if (a.index() != b.index()) differ(where, "geometry kinds");
    if (const auto* t = std::get_if<TrimmedSurface>(&a)) {
      surface(*t, std::get<TrimmedSurface>(b), wa, wb, where);
    } else if (const auto* c = std::get_if<NurbsCurve>(&a)) {
      const auto& d = std::get<NurbsCurve>(b);
      if (c->count() != d.count() || c->order != d.order) differ(where, "curve sizes");
      for (double t : sample_parameters(c->knots, c->order, c->count(), per_span))
        distance(result.curves, wa * curve_point(*c, t), wb * curve_point(d, t));
    } else {
      const auto positions = [](const Geometry& g) -> const std::vector<Eigen::Vector3d>& {
        return std::holds_alternative<TriangleMesh>(g) ? std::get<TriangleMesh>(g).positions : std::get<PolygonMesh>(g).positions;
      };
      const auto &pa = positions(a), &pb = positions(b);
      if (pa.size() != pb.size()) differ(where, "vertex counts");
      for (size_t i = 0; i < pa.size(); ++i) distance(result.meshes, wa * pa[i], wb * pb[i]);
    }
  }

  void node(const SceneNode& a, const SceneNode& b, const Eigen::Affine3d& pa, const Eigen::Affine3d& pb,
            const std::string& where) {
    if (a.shapes.size() != b.shapes.size() || a.children.size() != b.children.size()) differ(where, "shape or child counts");
    const Eigen::Affine3d wa = pa * a.transform, wb = pb * b.transform;
    for (size_t i = 0; i < a.shapes.size(); ++i)
      geometry(a.shapes[i].geometry, b.shapes[i].geometry, wa, wb, where + "/shape " + std::to_string(i));
    for (size_t i = 0; i < a.children.size(); ++i)
      node(a.children[i], b.children[i], wa, wb, where + "/node " + std::to_string(i));
  }
};

}  // namespace

PairedDeviation paired_scene_deviation(const Scene& original, const Scene& decoded, int samples_per_span) {
  Comparison c{std::max(1, samples_per_span), {}};
  c.node(original.root, decoded.root, Eigen::Affine3d::Identity(), Eigen::Affine3d::Identity(), "scene");
  return c.result;
}

}  // namespace cadnurbs
