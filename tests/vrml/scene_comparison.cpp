#include "scene_comparison.hpp"

#include <gtest/gtest.h>

#include <Eigen/SVD>
#include <algorithm>

#include "core/bounding_box.hpp"
#include "formats/vrml/nurbs_tolerances.hpp"
#include "formats/vrml/scene_to_nodes.hpp"

namespace cadnurbs::vrml_test {

namespace {

// Double arithmetic on top of the written precision (w·P recomputed from P = (w·P)/w, and so on).
constexpr double slack = 1e-9;

double max_abs(const std::vector<Eigen::Vector3d>& points) {
  double m = 0.0;
  for (const auto& p : points) m = std::max(m, p.cwiseAbs().maxCoeff());
  return m;
}

void expect_knots(const std::vector<double>& a, const std::vector<double>& b, double tolerance, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], tolerance + slack) << what << " knot " << i;
}

// Control points in the written form (w·P or P) and weights, each within its stated tolerance.
void expect_net(const std::vector<Eigen::Vector3d>& a_points, const std::vector<double>& a_weights,
                const std::vector<Eigen::Vector3d>& b_points, const std::vector<double>& b_weights,
                const NurbsTolerances& t, bool homogeneous, const std::string& what, double extra = 0.0) {
  ASSERT_EQ(a_points.size(), b_points.size()) << what;
  const bool rational = std::any_of(a_weights.begin(), a_weights.end(), [](double w) { return w != 1.0; });
  for (size_t i = 0; i < a_points.size(); ++i) {
    const double wa = a_weights.empty() ? 1.0 : a_weights[i];
    const double wb = b_weights.empty() ? 1.0 : b_weights[i];
    const Eigen::Vector3d pa = (homogeneous && rational) ? Eigen::Vector3d(wa * a_points[i]) : a_points[i];
    const Eigen::Vector3d pb = (homogeneous && rational) ? Eigen::Vector3d(wb * b_points[i]) : b_points[i];
    EXPECT_LE((pa - pb).cwiseAbs().maxCoeff(), t.control_point + extra + slack)
        << what << " control point " << i << ": " << pa.transpose() << " vs " << pb.transpose();
    EXPECT_NEAR(wa, wb, t.weight + slack) << what << " weight " << i;
  }
}

void expect_surface(const NurbsSurface& a, const NurbsSurface& b, double tau, bool homogeneous, const std::string& what) {
  ASSERT_EQ(a.u_count, b.u_count) << what;
  ASSERT_EQ(a.v_count, b.v_count) << what;
  EXPECT_EQ(a.u_order, b.u_order) << what;
  EXPECT_EQ(a.v_order, b.v_order) << what;
  const NurbsTolerances t = surface_tolerances(a, tau, homogeneous);
  expect_knots(a.u_knots, b.u_knots, t.knot, what + " u");
  expect_knots(a.v_knots, b.v_knots, t.knot, what + " v");
  expect_net(a.points, a.weights, b.points, b.weights, t, homogeneous, what);
  // The promise behind all tolerances: the surface itself moves by at most tau per coordinate.
  for (int i = 0; i <= 8; ++i)
    for (int j = 0; j <= 8; ++j) {
      const double u = a.u_start() + (a.u_end() - a.u_start()) * i / 8.0;
      const double v = a.v_start() + (a.v_end() - a.v_start()) * j / 8.0;
      EXPECT_LE((surface_point(a, u, v) - surface_point(b, u, v)).cwiseAbs().maxCoeff(), tau + slack)
          << what << " at (" << u << ", " << v << ")";
    }
}

void expect_curve(const NurbsCurve& a, const NurbsCurve& b, double tau, bool homogeneous, const std::string& what,
                  double extra = 0.0) {
  ASSERT_EQ(a.count(), b.count()) << what;
  EXPECT_EQ(a.order, b.order) << what;
  EXPECT_EQ(a.dimension, b.dimension) << what;
  const NurbsTolerances t = curve_tolerances(a, tau, homogeneous);
  expect_knots(a.knots, b.knots, t.knot, what);
  expect_net(a.points, a.weights, b.points, b.weights, t, homogeneous, what, extra);
  for (int i = 0; i <= 16; ++i) {
    const double s = a.domain_start() + (a.domain_end() - a.domain_start()) * i / 16.0;
    EXPECT_LE((curve_point(a, s) - curve_point(b, s)).cwiseAbs().maxCoeff(), tau + extra + slack) << what << " at " << s;
  }
}

void expect_trimmed(const TrimmedSurface& a, const TrimmedSurface& b, double tau, bool homogeneous,
                    const std::string& what) {
  expect_surface(a.surface, b.surface, tau, homogeneous, what);
  ASSERT_EQ(a.loops.size(), b.loops.size()) << what;
  const double parameter_tol = trim_parameter_tolerance(a.surface, tau);
  for (size_t l = 0; l < a.loops.size(); ++l) {
    ASSERT_EQ(a.loops[l].segments.size(), b.loops[l].segments.size()) << what << " loop " << l;
    for (size_t s = 0; s < a.loops[l].segments.size(); ++s) {
      const std::string name = what + " loop " + std::to_string(l) + " segment " + std::to_string(s);
      const auto& sa = a.loops[l].segments[s];
      const auto& sb = b.loops[l].segments[s];
      ASSERT_EQ(sa.index(), sb.index()) << name;
      if (const auto* ca = std::get_if<NurbsCurve>(&sa)) {
        // The reader snaps a segment's first point onto its neighbour's last: that point then carries
        // the neighbour's rounding, at most one more written tolerance (in Euclidean terms).
        const NurbsTolerances t = curve_tolerances(*ca, parameter_tol, homogeneous);
        const double w_max = ca->weights.empty() ? 1.0 : *std::max_element(ca->weights.begin(), ca->weights.end());
        const double w_min = ca->weights.empty() ? 1.0 : *std::min_element(ca->weights.begin(), ca->weights.end());
        const double snap = 2.0 * w_max * (t.control_point + max_abs(ca->points) * t.weight) / w_min;
        expect_curve(*ca, std::get<NurbsCurve>(sb), parameter_tol, homogeneous, name, snap);
      } else {
        const auto& pa = std::get<Polyline2D>(sa).points;
        const auto& pb = std::get<Polyline2D>(sb).points;
        ASSERT_EQ(pa.size(), pb.size()) << name;
        for (size_t i = 0; i < pa.size(); ++i)
          EXPECT_LE((pa[i] - pb[i]).cwiseAbs().maxCoeff(), 2 * parameter_tol + slack) << name << " point " << i;
      }
    }
  }
}

void expect_mesh(const TriangleMesh& a, const TriangleMesh& b, double tau, const std::string& what) {
  ASSERT_EQ(a.positions.size(), b.positions.size()) << what;
  for (size_t i = 0; i < a.positions.size(); ++i)
    EXPECT_LE((a.positions[i] - b.positions[i]).cwiseAbs().maxCoeff(), tau + slack) << what << " vertex " << i;
  EXPECT_EQ(a.triangles, b.triangles) << what;
  ASSERT_EQ(a.corner_normals.size(), b.corner_normals.size()) << what;
  for (size_t i = 0; i < a.corner_normals.size(); ++i)
    EXPECT_LE((a.corner_normals[i] - b.corner_normals[i]).cwiseAbs().maxCoeff(), 1e-3 + slack) << what << " normal " << i;
}

void expect_colour(const std::optional<Colour>& a, const std::optional<Colour>& b, const std::string& what) {
  ASSERT_EQ(a.has_value(), b.has_value()) << what << " colour";
  if (!a) return;
  EXPECT_NEAR(a->r, b->r, 1.0 / 512) << what;
  EXPECT_NEAR(a->g, b->g, 1.0 / 512) << what;
  EXPECT_NEAR(a->b, b->b, 1.0 / 512) << what;
}

struct Comparison {
  const VrmlWriteOptions& options;
  double tau;
  Eigen::AlignedBox3d box;

  void nodes(const SceneNode& a, const SceneNode& b, const Eigen::Affine3d& world_a, const Eigen::Affine3d& world_b,
             const std::string& path) {
    EXPECT_EQ(a.name, b.name) << path;
    expect_colour(a.colour, b.colour, path);
    const Eigen::Affine3d wa = world_a * a.transform, wb = world_b * b.transform;
    // Transforms: the scene box's corners mapped by both must agree within tau (first-order precision
    // of the written Transform fields, nested).
    for (int c = 0; c < 8; ++c) {
      const Eigen::Vector3d p = wa.inverse() * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(c));
      EXPECT_LE((wa * p - wb * p).cwiseAbs().maxCoeff(), 2 * tau + slack) << path << " transform";
    }
    const double stretch = wa.linear().jacobiSvd().singularValues()(0);
    const double local_tau = tau / stretch;
    ASSERT_EQ(a.shapes.size(), b.shapes.size()) << path;
    for (size_t i = 0; i < a.shapes.size(); ++i) {
      const auto& sa = a.shapes[i];
      const auto& sb = b.shapes[i];
      const std::string what = path + "/" + sa.name;
      EXPECT_EQ(sa.name, sb.name) << path;
      expect_colour(sa.colour, sb.colour, what);
      const bool homogeneous = options.homogeneous_control_points;
      // Polygons are read back as the triangles of their fans.
      if (const auto* polygons = std::get_if<PolygonMesh>(&sa.geometry)) {
        ASSERT_TRUE(std::holds_alternative<TriangleMesh>(sb.geometry)) << what;
        expect_mesh(triangulated(*polygons), std::get<TriangleMesh>(sb.geometry), local_tau, what);
        continue;
      }
      ASSERT_EQ(sa.geometry.index(), sb.geometry.index()) << what;
      if (const auto* t = std::get_if<TrimmedSurface>(&sa.geometry))
        expect_trimmed(*t, std::get<TrimmedSurface>(sb.geometry), local_tau, homogeneous, what);
      else if (const auto* c = std::get_if<NurbsCurve>(&sa.geometry))
        expect_curve(*c, std::get<NurbsCurve>(sb.geometry), local_tau, homogeneous, what);
      else
        expect_mesh(std::get<TriangleMesh>(sa.geometry), std::get<TriangleMesh>(sb.geometry), local_tau, what);
    }
    ASSERT_EQ(a.children.size(), b.children.size()) << path;
    for (size_t i = 0; i < a.children.size(); ++i)
      nodes(a.children[i], b.children[i], wa, wb, path + "/" + a.children[i].name);
  }
};

}  // namespace

void expect_same_scene(const Scene& written, const Scene& read, const VrmlWriteOptions& options) {
  EXPECT_EQ(written.unit.name, read.unit.name);
  EXPECT_EQ(written.unit.millimetres, read.unit.millimetres);
  Comparison comparison{options, effective_coordinate_tolerance(written, options), scene_bounding_box(written)};
  comparison.nodes(written.root, read.root, Eigen::Affine3d::Identity(), Eigen::Affine3d::Identity(), written.root.name);
}

}  // namespace cadnurbs::vrml_test
