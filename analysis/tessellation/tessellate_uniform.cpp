#include "analysis/tessellation/tessellate_uniform.hpp"

#include "analysis/mesh/triangulate_polygon.hpp"

namespace cadnurbs {

std::vector<double> uniform_parameters(const std::vector<double>& knots, int order, int count, int steps) {
  std::vector<double> out;
  for (int i = order - 1; i < count; ++i) {
    const double a = knots[i], b = knots[i + 1];
    if (!(a < b)) continue;
    for (int s = out.empty() ? 0 : 1; s <= steps; ++s) out.push_back(s == steps ? b : a + (b - a) * s / steps);
  }
  return out;
}

namespace {

// Maps (u, v) points to the surface with normals; triangles stay as given.
TriangleMesh map_to_surface(const NurbsSurface& s, const std::vector<Eigen::Vector2d>& uv,
                            const std::vector<std::array<int, 3>>& triangles) {
  TriangleMesh mesh;
  std::vector<Eigen::Vector3d> normals(uv.size());
  for (size_t i = 0; i < uv.size(); ++i) {
    mesh.positions.push_back(surface_point(s, uv[i].x(), uv[i].y()));
    normals[i] = surface_normal(s, uv[i].x(), uv[i].y());
  }
  mesh.triangles = triangles;
  for (const auto& t : triangles)
    for (int k : t) mesh.corner_normals.push_back(normals[k]);
  return mesh;
}

}  // namespace

TriangleMesh tessellate_uniform(const TrimmedSurface& trimmed, int steps_per_span) {
  const NurbsSurface& s = trimmed.surface;
  const auto us = uniform_parameters(s.u_knots, s.u_order, s.u_count, steps_per_span);
  const auto vs = uniform_parameters(s.v_knots, s.v_order, s.v_count, steps_per_span);
  std::vector<Eigen::Vector2d> grid;
  for (double v : vs)
    for (double u : us) grid.emplace_back(u, v);

  if (trimmed.loops.empty()) {
    const int nu = static_cast<int>(us.size());
    std::vector<std::array<int, 3>> triangles;
    for (int j = 0; j + 1 < static_cast<int>(vs.size()); ++j)
      for (int i = 0; i + 1 < nu; ++i) {
        const int a = i + j * nu, b = a + 1, c = a + 1 + nu, d = a + nu;
        triangles.push_back({a, b, c});
        triangles.push_back({a, c, d});
      }
    return map_to_surface(s, grid, triangles);
  }

  std::vector<std::vector<Eigen::Vector2d>> loops;
  for (const auto& loop : trimmed.loops) loops.push_back(loop_polygon(loop, 2 * steps_per_span));
  const PlanarTriangulation cdt = triangulate_polygon(loops, grid);
  return map_to_surface(s, cdt.points, cdt.triangles);
}

namespace {

void tessellate_node(SceneNode& node, int steps_per_span) {
  for (auto& shape : node.shapes)
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) shape.geometry = tessellate_uniform(*t, steps_per_span);
  for (auto& child : node.children) tessellate_node(child, steps_per_span);
}

}  // namespace

Scene tessellate_uniform(const Scene& scene, int steps_per_span) {
  Scene out = scene;
  tessellate_node(out.root, steps_per_span);
  return out;
}

}  // namespace cadnurbs
