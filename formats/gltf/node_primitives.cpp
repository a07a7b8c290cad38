#include "formats/gltf/node_primitives.hpp"

#include <array>
#include <bit>
#include <unordered_map>

#include "core/geometry_error.hpp"

namespace cadnurbs {
namespace {

using PositionBits = std::array<std::uint64_t, 3>;

struct PositionBitsHash {
  std::size_t operator()(const PositionBits& p) const {
    std::size_t h = 0;
    for (const auto v : p) h = h * 0x9e3779b97f4a7c15ULL + (v ^ (v >> 29));
    return h;
  }
};

// Collects the triangles of one colour, welding bit-identical positions.
struct PrimitiveBuilder {
  PrimitiveMesh mesh;
  std::unordered_map<PositionBits, std::uint32_t, PositionBitsHash> index_of;

  void add(const TriangleMesh& shape, const Eigen::Matrix3d& frame) {
    std::vector<std::uint32_t> vertex_of(shape.positions.size());
    for (std::size_t i = 0; i < shape.positions.size(); ++i) {
      const Eigen::Vector3d p = frame * shape.positions[i];
      const PositionBits key{std::bit_cast<std::uint64_t>(p.x()), std::bit_cast<std::uint64_t>(p.y()),
                             std::bit_cast<std::uint64_t>(p.z())};
      const auto [it, inserted] = index_of.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (inserted) mesh.positions.push_back(p);
      vertex_of[i] = it->second;
    }
    for (const auto& triangle : shape.triangles)
      for (const int corner : triangle) mesh.indices.push_back(vertex_of[corner]);
  }
};

}  // namespace

NodePrimitives node_primitives(const SceneNode& node, const Colour& node_colour, const Eigen::Matrix3d& frame,
                               const std::string& entity) {
  NodePrimitives result;
  std::vector<PrimitiveBuilder> builders;
  for (std::size_t s = 0; s < node.shapes.size(); ++s) {
    const Shape& shape = node.shapes[s];
    const std::string name = entity + "/" + (display_name(shape).empty() ? "shape " + std::to_string(s) : display_name(shape));
    TriangleMesh triangles;
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) {
      validate(*mesh, name);
      triangles = *mesh;
    } else if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) {
      validate(*polygons, name);
      triangles = triangulated(*polygons);
    } else if (std::holds_alternative<NurbsCurve>(shape.geometry)) {
      ++result.skipped_curves;
      continue;
    } else {
      throw GeometryError(name, "glTF holds triangle meshes only: tessellate NURBS surfaces first");
    }
    const Colour colour = shape.colour.value_or(node_colour);
    auto builder = builders.begin();
    while (builder != builders.end() && !(builder->mesh.colour == colour)) ++builder;
    if (builder == builders.end()) {
      builders.emplace_back();
      builders.back().mesh.colour = colour;
      builder = builders.end() - 1;
    }
    builder->add(triangles, frame);
  }
  for (auto& builder : builders)
    if (!builder.mesh.indices.empty()) result.primitives.push_back(std::move(builder.mesh));
  return result;
}

}  // namespace cadnurbs
