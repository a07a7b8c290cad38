#include "analysis/mesh_distance.hpp"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <cmath>

#include "analysis/sample_triangles.hpp"
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

// Distances from the samples of `from` to the triangles of `to`, summed into `stats`; returns the
// sum of squares.
double one_side(const TriangleMesh& from, const std::vector<K::Triangle_3>& to, double spacing, DeviationStats& stats) {
  TriangleTree tree(to.begin(), to.end());
  tree.accelerate_distance_queries();
  double sum = 0;
  for (const Eigen::Vector3d& p : sample_triangles(from, spacing)) {
    const double d = std::sqrt(tree.squared_distance(cg(p)));
    stats.max = std::max(stats.max, d);
    sum += d * d;
    ++stats.samples;
  }
  stats.rms = stats.samples ? std::sqrt(sum / stats.samples) : 0.0;
  return sum;
}

}  // namespace

MeshDistance mesh_distance(const TriangleMesh& a, const TriangleMesh& b, double spacing) {
  const auto ta = cgal_triangles(a, "mesh a"), tb = cgal_triangles(b, "mesh b");
  if (!(spacing > 0)) spacing = std::min(default_sample_spacing(a), default_sample_spacing(b));
  MeshDistance out;
  const double sum = one_side(a, tb, spacing, out.a_to_b) + one_side(b, ta, spacing, out.b_to_a);
  out.overall.samples = out.a_to_b.samples + out.b_to_a.samples;
  out.overall.max = std::max(out.a_to_b.max, out.b_to_a.max);
  out.overall.rms = out.overall.samples ? std::sqrt(sum / out.overall.samples) : 0.0;
  return out;
}

}  // namespace cadnurbs
