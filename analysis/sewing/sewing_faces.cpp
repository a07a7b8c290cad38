#include "analysis/sewing/sewing_faces.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <optional>
#include <utility>
#include <variant>

#include "core/planar_polygon_surface.hpp"

namespace cadnurbs::sewing {

namespace {

// The polygons of a polygon set: a PolygonMesh's, or a TriangleMesh's triangles when it has no normals
// (how the readers return the compact writer's IndexedFaceSets of planar faces); empty for other shapes.
std::vector<std::vector<Eigen::Vector3d>> planar_polygons(const Shape& shape) {
  std::vector<std::vector<Eigen::Vector3d>> out;
  if (const auto* mesh = std::get_if<PolygonMesh>(&shape.geometry)) {
    for (const auto& polygon : mesh->polygons) {
      out.emplace_back();
      for (int i : polygon) out.back().push_back(mesh->positions[i]);
    }
  } else if (const auto* triangles = std::get_if<TriangleMesh>(&shape.geometry);
             triangles && triangles->corner_normals.empty()) {
    for (const auto& t : triangles->triangles)
      out.push_back({triangles->positions[t[0]], triangles->positions[t[1]], triangles->positions[t[2]]});
  }
  return out;
}

// Narrower than the tolerance everywhere (twice the area over the longest side): a sliver, such as a fan
// triangle over collinear corners of a polygon; it bounds nothing and its sides lie on its neighbours'.
bool is_sliver(const std::vector<Eigen::Vector3d>& corners, double tolerance) {
  Eigen::Vector3d twice_area = Eigen::Vector3d::Zero();
  double longest = 0;
  for (size_t i = 0; i < corners.size(); ++i) {
    const Eigen::Vector3d& a = corners[i];
    const Eigen::Vector3d& b = corners[(i + 1) % corners.size()];
    twice_area += (a - corners[0]).cross(b - corners[0]);
    longest = std::max(longest, (b - a).norm());
  }
  return twice_area.norm() <= tolerance * longest;
}

}  // namespace

void polygons_as_faces(SceneNode& node, double tolerance, SewingReport& report) {
  std::vector<Shape> shapes;
  for (auto& shape : node.shapes) {
    const auto polygons = planar_polygons(shape);
    if (polygons.empty()) {
      shapes.push_back(std::move(shape));
      continue;
    }
    for (const auto& corners : polygons) {
      auto face = is_sliver(corners, tolerance) ? std::nullopt : planar_polygon_surface(corners);
      if (!face) {
        ++report.dropped_polygons;
        continue;
      }
      Shape piece;
      piece.name = shape.name;
      piece.geometry = std::move(*face);
      piece.colour = shape.colour;
      piece.source_type = shape.source_type.empty() ? "polygon" : shape.source_type;
      piece.source_entity = shape.source_entity;
      shapes.push_back(std::move(piece));
      ++report.polygon_faces;
    }
  }
  node.shapes = std::move(shapes);
  for (auto& child : node.children) polygons_as_faces(child, tolerance, report);
}

void collect_faces(SceneNode& node, int group, int& groups, std::vector<SewFace>& faces) {
  if (!node.name.empty()) group = groups++;
  for (auto& shape : node.shapes)
    if (auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      if (t->loops.empty()) t->loops.push_back(domain_loop(t->surface));
      faces.push_back({t, std::make_unique<SurfaceEvaluator>(t->surface), group});
    }
  for (auto& child : node.children) collect_faces(child, group, groups, faces);
}

}  // namespace cadnurbs::sewing
