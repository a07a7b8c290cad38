#pragma once
// One node's own meshes grouped the way glTF stores them compactly: one primitive per colour.
#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

// A glTF primitive before encoding: triangles of one colour, positions already in glTF's frame.
struct PrimitiveMesh {
  Colour colour;
  std::vector<Eigen::Vector3d> positions;
  std::vector<std::uint32_t> indices;  // three per triangle, counter-clockwise seen from outside
};

struct NodePrimitives {
  std::vector<PrimitiveMesh> primitives;  // in the order their colours first appear among the shapes
  long skipped_curves = 0;                // NurbsCurve shapes: glTF triangles cannot hold them
};

// The TriangleMesh and PolygonMesh (fanned) shapes of `node` itself, not of its children, grouped by
// their colour (the shape's, else `node_colour`); positions mapped by `frame`; within a primitive,
// bit-identical positions (the shared edges tessellate_to_deviation makes identical on purpose) become
// one vertex. Corner normals are not kept. Refuses (GeometryError, entity = `entity` and the shape's
// name) a TrimmedSurface (tessellate the scene first) and a mesh that fails validate().
NodePrimitives node_primitives(const SceneNode& node, const Colour& node_colour, const Eigen::Matrix3d& frame,
                               const std::string& entity);

}  // namespace cadnurbs
