#include "analysis/measure/mesh_distance.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>

#include "analysis/mesh/sample_triangles.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

using K = CGAL::Simple_cartesian<double>;
using TriangleIt = std::vector<K::Triangle_3>::const_iterator;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, TriangleIt>>>;

K::Point_3 cg(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }

std::vector<K::Triangle_3> cgal_triangles(const TriangleMesh& mesh, const char* name) {
  std::vector<K::Triangle_3> out;
  for (const auto& t : mesh.triangles) {
    const K::Triangle_3 tri(cg(mesh.positions[t[0]]), cg(mesh.positions[t[1]]), cg(mesh.positions[t[2]]));
    if (!tri.is_degenerate()) out.push_back(tri);
  }
  if (out.empty()) throw GeometryError(name, "the mesh has no non-degenerate triangle");
  return out;
}

// Distances from the samples of `from` to the triangles of `to`, into `stats`; returns the integral
// of the squared distance over `from` (area-weighted sum) and adds its area to `area`.
double one_side(const TriangleMesh& from, const std::vector<K::Triangle_3>& to, double spacing, DeviationStats& stats,
                double& area) {
  TriangleTree tree(to.begin(), to.end());
  tree.accelerate_distance_queries();
  std::vector<double> weights;
  const std::vector<Eigen::Vector3d> points = sample_triangles(from, spacing, &weights);
  double integral = 0, side_area = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double d2 = tree.squared_distance(cg(points[i]));
    stats.max = std::max(stats.max, std::sqrt(d2));
    integral += weights[i] * d2;
    side_area += weights[i];
  }
  stats.samples = static_cast<long>(points.size());
  stats.rms = side_area > 0 ? std::sqrt(integral / side_area) : 0.0;
  area += side_area;
  return integral;
}

}  // namespace

MeshDistance mesh_distance(const TriangleMesh& a, const TriangleMesh& b, double spacing) {
  const auto ta = cgal_triangles(a, "mesh a"), tb = cgal_triangles(b, "mesh b");
  if (!(spacing > 0)) spacing = std::min(default_sample_spacing(a), default_sample_spacing(b));
  MeshDistance out;
  double area = 0;
  const double integral = one_side(a, tb, spacing, out.a_to_b, area) + one_side(b, ta, spacing, out.b_to_a, area);
  out.overall.samples = out.a_to_b.samples + out.b_to_a.samples;
  out.overall.max = std::max(out.a_to_b.max, out.b_to_a.max);
  out.overall.rms = area > 0 ? std::sqrt(integral / area) : 0.0;
  return out;
}

}  // namespace cadnurbs
