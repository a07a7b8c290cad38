#pragma once
// The mesh candidate of one body (scene_bodies.hpp): its trimmed surfaces tessellated within a world
// deviation with a certificate (tessellate_to_deviation, shared edges carrying bit-identical vertices),
// its planar polygons fanned (exact), each node's triangles merged per colour into one TriangleMesh,
// welded exactly and without corner normals (a viewer computes them; they would cost more than the
// positions). 3D curves and the triangle meshes the body already holds stay as they are.
#include <optional>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

struct CertifiedBodyMesh {
  // One list of shapes per child of the body scene, in the same order, in that node's own coordinates:
  // the curves and triangle meshes it held, then one mesh per colour (in order of first use; a shape
  // without its own colour inherits the node's, as before).
  std::vector<std::vector<Shape>> shapes;
  double world_deviation = 0;  // the certificate of its tessellation times the body's largest world scale
  int faces = 0;               // trimmed surfaces meshed
  long polygons = 0;           // planar polygons fanned
  long triangles = 0;          // in the merged, welded meshes
};

// `body` is a body scene (scene_bodies.hpp: the body's nodes as children of an empty root, at their world
// placement). Tessellated at max_world_deviation / (largest world scale of its nodes), so every point of
// a meshed face lies within max_world_deviation of the exact face in world coordinates, and the reverse
// (tessellate_to_deviation's certificate, stretched at most by that scale). nullopt when the body has
// nothing to mesh (no trimmed surface and no polygon mesh), when a face cannot be tessellated, or when a
// triangle is left uncertified; `refusal` (may be null) then says why ("" when there was nothing to
// mesh). Throws GeometryError for max_world_deviation <= 0.
std::optional<CertifiedBodyMesh> certified_body_mesh(const Scene& body, double max_world_deviation,
                                                     std::string* refusal = nullptr);

}  // namespace cadnurbs
