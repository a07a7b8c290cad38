#include "weld_test_meshes.hpp"

#include <cmath>
#include <numbers>

namespace cadnurbs::test {

namespace {

void add_triangle(TriangleMesh& m, const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const int first = static_cast<int>(m.positions.size());
  m.positions.insert(m.positions.end(), {a, b, c});
  m.triangles.push_back({first, first + 1, first + 2});
  const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
  m.corner_normals.insert(m.corner_normals.end(), {n, n, n});
}

}  // namespace

TriangleMesh stl_cube(double size) {
  TriangleMesh m;
  const double h = size / 2;
  // Each face as a quad (counter-clockwise seen from outside) split along its first diagonal.
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      auto corner = [&](double a, double b) {
        Eigen::Vector3d p;
        p[axis] = side * h;
        p[u] = a * h;
        p[v] = b * side * h;  // mirrored on the negative side keeps the quad outward
        return p;
      };
      const Eigen::Vector3d p00 = corner(-1, -1), p10 = corner(1, -1), p11 = corner(1, 1), p01 = corner(-1, 1);
      add_triangle(m, p00, p10, p11);
      add_triangle(m, p00, p11, p01);
    }
  return m;
}

TriangleMesh stl_cylinder(double r, double height, int segments) {
  TriangleMesh m;
  auto rim = [&](int i, double z) {
    const double a = 2 * std::numbers::pi * (i % segments) / segments;
    return Eigen::Vector3d(r * std::cos(a), r * std::sin(a), z);
  };
  const Eigen::Vector3d bottom(0, 0, 0), top(0, 0, height);
  for (int i = 0; i < segments; ++i) {
    add_triangle(m, rim(i, 0), rim(i + 1, 0), rim(i + 1, height));
    add_triangle(m, rim(i, 0), rim(i + 1, height), rim(i, height));
    add_triangle(m, top, rim(i, height), rim(i + 1, height));
    add_triangle(m, bottom, rim(i + 1, 0), rim(i, 0));
  }
  return m;
}

}  // namespace cadnurbs::test
