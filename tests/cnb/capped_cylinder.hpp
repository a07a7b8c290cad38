#pragma once
// A pin as CAD tessellates it, for the .cnb mesh tests: a cylinder of `segments` about the z axis, from
// z = 0 to `height`, whose caps are fans from one rim point (vertex 0 below, `segments` above).
#include <cmath>
#include <numbers>

#include "core/triangle_mesh.hpp"

namespace cadnurbs {

inline TriangleMesh capped_cylinder(int segments, double radius, double height) {
  TriangleMesh mesh;
  for (int ring = 0; ring < 2; ++ring)
    for (int i = 0; i < segments; ++i) {
      const double a = 2 * std::numbers::pi * i / segments;
      mesh.positions.emplace_back(radius * std::cos(a), radius * std::sin(a), ring * height);
    }
  for (int i = 0; i < segments; ++i) {
    const int j = (i + 1) % segments;
    mesh.triangles.push_back({i, j, segments + j});
    mesh.triangles.push_back({i, segments + j, segments + i});
  }
  for (int i = 1; i + 1 < segments; ++i) {
    mesh.triangles.push_back({0, i + 1, i});                               // bottom, facing down
    mesh.triangles.push_back({segments, segments + i, segments + i + 1});  // top, facing up
  }
  return mesh;
}

}  // namespace cadnurbs
