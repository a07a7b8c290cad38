#pragma once
// The mesh candidate of one body (scene_bodies.hpp): its trimmed surfaces tessellated within a world
// deviation with a certificate (tessellate_to_deviation, shared edges carrying bit-identical vertices),
// its planar polygons fanned (exact), each node's triangles merged per colour into one TriangleMesh,
// welded within 1e-6 of its size (default_weld_tolerance: the compact form's polygons, welded within its
// own tolerance, meet the tessellated faces at corners equal only up to rounding; on DIP-8 at 0.01 mm this
// closed 185 of 808 boundary edges and made the .cnb 1,309 -> 1,206 bytes) and without corner normals (a
// viewer computes them; they would cost more than the positions). 3D curves and the triangle meshes the
// body already holds stay as they are.
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
  double world_deviation = 0;  // (certificate of its tessellation + weld_move) x the body's largest world scale
  double weld_move = 0;        // farthest the welding moved a vertex, own coordinates
  int faces = 0;               // trimmed surfaces meshed
  long polygons = 0;           // planar polygons fanned
  long triangles = 0;          // in the merged, welded meshes
  int unshared_edge_uses = 0;  // shared edges its faces could not match within the deviation: cracks
};

// `body` is a body scene (scene_bodies.hpp: the body's nodes as children of an empty root, at their world
// placement). Tessellated at max_world_deviation / (largest world scale of its nodes), so every point of
// a meshed face lies within max_world_deviation of the exact face in world coordinates, and the reverse
// (tessellate_to_deviation's certificate plus the welding's move, stretched at most by that scale; a body
// whose sum exceeds max_world_deviation is refused). nullopt when the body has
// nothing to mesh (no trimmed surface and no polygon mesh), when a face cannot be tessellated, or when a
// triangle is left uncertified; `refusal` (may be null) then says why ("" when there was nothing to
// mesh). Throws GeometryError for max_world_deviation <= 0.
std::optional<CertifiedBodyMesh> certified_body_mesh(const Scene& body, double max_world_deviation,
                                                     std::string* refusal = nullptr);

}  // namespace cadnurbs
