#pragma once
// Closest points on triangle meshes, as the Loop fit uses them: CGAL's AABB tree over a vector of
// triangles, conversions between Eigen and CGAL points, and where a foot point lies in its triangle.
// Private to analysis/subdivision_fit (it puts CGAL in the includer's view).
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "core/triangle_normal.hpp"

namespace cadnurbs::subdivision_fit {

using K = CGAL::Simple_cartesian<double>;
using TriangleIt = std::vector<K::Triangle_3>::const_iterator;
using TriangleTree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, TriangleIt>>>;

inline K::Point_3 cg(const Eigen::Vector3d& p) { return {p.x(), p.y(), p.z()}; }
inline Eigen::Vector3d eig(const K::Point_3& p) { return {p.x(), p.y(), p.z()}; }

// Barycentric coordinates of p (on or near triangle abc), clamped to the triangle; a triangle without
// area gives its centroid's.
inline Eigen::Vector3d barycentric(const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                                   const Eigen::Vector3d& c) {
  const Eigen::Vector3d e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = d.dot(e0), d21 = d.dot(e1);
  const double det = d00 * d11 - d01 * d01;
  if (!(det > 0)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
  v = std::clamp(v, 0.0, 1.0);
  w = std::clamp(w, 0.0, 1.0 - v);
  return {1 - v - w, v, w};
}

}  // namespace cadnurbs::subdivision_fit
