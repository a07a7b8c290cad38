#pragma once
// The one data model every reader produces and every writer consumes: a tree of named nodes with
// transforms, colours and geometry, plus the length unit of the source.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "core/nurbs_curve.hpp"
#include "core/polygon_mesh.hpp"
#include "core/trimmed_surface.hpp"
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

struct Colour {
  double r = 0.8, g = 0.8, b = 0.8;  // 0..1
  bool operator==(const Colour&) const = default;
};

struct LengthUnit {
  std::string name = "mm";
  double millimetres = 1.0;  // how many millimetres one unit is
};

// One piece of geometry: a (possibly untrimmed) NURBS surface, a 3D NURBS curve, a triangle mesh, or
// exact planar polygons.
using Geometry = std::variant<TrimmedSurface, NurbsCurve, TriangleMesh, PolygonMesh>;

struct Shape {
  std::string name;  // the source file's name for it; may be empty. Writers write it.
  Geometry geometry;
  std::optional<Colour> colour;  // inherits the node's colour when empty
  std::string source_type = {};  // what the source file called it (e.g. "Plane"), for reports; may be empty
  // How the reader refers to it where the file gives no name (e.g. "face 4"), for reports and messages;
  // never written to files. May be empty.
  std::string source_entity = {};
};

struct SceneNode {
  std::string name;  // the source file's name for it; may be empty. Writers write it.
  std::string source_entity = {};  // as Shape::source_entity (e.g. "solid 2")
  Eigen::Affine3d transform = Eigen::Affine3d::Identity();  // local to parent
  std::optional<Colour> colour;
  std::vector<Shape> shapes;
  std::vector<SceneNode> children;
};

struct Scene {
  SceneNode root;
  LengthUnit unit;         // unit of the coordinates stored in the scene
  LengthUnit source_unit;  // unit of the file the scene was read from
};

// Calls visit(shape, world_transform, colour) for every shape, depth first.
template <class Visit>
void for_each_shape(const SceneNode& node, const Eigen::Affine3d& parent, const Colour& inherited, Visit&& visit) {
  const Eigen::Affine3d world = parent * node.transform;
  const Colour colour = node.colour.value_or(inherited);
  for (const auto& shape : node.shapes) visit(shape, world, shape.colour.value_or(colour));
  for (const auto& child : node.children) for_each_shape(child, world, colour, visit);
}
template <class Visit>
void for_each_shape(const Scene& scene, Visit&& visit) {
  for_each_shape(scene.root, Eigen::Affine3d::Identity(), Colour{}, visit);
}

// Validates every shape; entity names are the node path and shape name or index.
void validate(const Scene& scene);

// Counts for reports.
struct SceneCounts {
  int surfaces = 0, trimmed_surfaces = 0, curves = 0, meshes = 0;
  long control_points = 0, knots = 0, trim_loops = 0, trim_control_points = 0, trim_knots = 0;
  long mesh_vertices = 0, mesh_triangles = 0;
  int polygon_meshes = 0;
  long polygon_vertices = 0, polygons = 0;
};

// The name to show for a shape or node in messages: its name, else its source entity, else "".
inline const std::string& display_name(const Shape& shape) {
  return shape.name.empty() ? shape.source_entity : shape.name;
}
inline const std::string& display_name(const SceneNode& node) {
  return node.name.empty() ? node.source_entity : node.name;
}
SceneCounts count_entities(const Scene& scene);

}  // namespace cadnurbs
