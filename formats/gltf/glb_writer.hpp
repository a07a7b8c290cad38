#pragma once
// A tessellated scene as glTF 2.0 binary (.glb), uncompressed or compressed with Draco
// (KHR_draco_mesh_compression) or meshoptimizer (EXT_meshopt_compression + KHR_mesh_quantization).
//
// What the file holds:
// - One glTF node per SceneNode, same tree, same names; the node transforms re-expressed in glTF's frame.
// - Positions in metres with +Y up: the data itself is transformed (gltf_frame.hpp), not wrapped in a
//   root node with a scale and a rotation, so every accessor min / max and node matrix is in metres.
// - Per node one mesh; its TriangleMesh and PolygonMesh shapes merged into one primitive per colour,
//   bit-identical positions welded (face names are not kept: glTF primitives have no names).
// - One material per distinct colour: pbrMetallicRoughness baseColorFactor = the colour converted
//   from sRGB (how VRML viewers show diffuseColor) to linear (what glTF's factor is), so a glTF viewer
//   shows the same colour; metallic 0, roughness 1, double-sided (as our VRML writer writes solid FALSE).
// - No normals: viewers compute flat ones (three.js's GLTFLoader then shades the material flat). Smooth
//   normals would cost at least as much again as the positions in every encoding.
// - Draco: every primitive a Draco stream (edgebreaker), positions quantised to `position_bits` on one
//   grid for the whole file (position_grid.hpp) so shared edges of different primitives stay closed.
// - meshopt: positions as unsigned 16-bit grid coordinates (KHR_mesh_quantization); each mesh hangs on
//   an unnamed child node whose translation and uniform scale map grid coordinates back to metres;
//   vertex and index streams compressed with meshoptimizer's codecs into buffer 0 (the BIN chunk); the
//   bufferViews point into a second, data-less fallback buffer ("fallback": true), so a viewer without
//   the extension cannot show the file (the extension is listed as required).
// Not written: curves (counted in GlbReport::skipped_curves), textures, normals, cameras.
#include <optional>
#include <string>
#include <string_view>

#include "core/scene.hpp"

namespace cadnurbs {

enum class GlbCompression { none, draco, meshopt };

struct GlbOptions {
  GlbCompression compression = GlbCompression::none;
  // Grid resolution of the quantised positions (draco, meshopt; ignored by none): the grid's step is
  // the scene's largest extent / (2^bits - 1). 1..30 for draco, 1..16 for meshopt.
  int position_bits = 14;
  int draco_speed = 0;  // Draco's encoding and decoding speed, 0 (smallest file) .. 10
};

struct GlbReport {
  long nodes = 0, meshes = 0, primitives = 0, materials = 0;
  long vertices = 0, triangles = 0;  // as written (after welding; Draco: what its decoder yields)
  long skipped_curves = 0;
  // Grid step of the quantised positions, in the scene's unit (0 for none).
  double position_step = 0;
  // Bound on the distance between a written position, as a viewer decodes it, and the scene's position,
  // in the scene's unit and each node's own coordinates (the world distance where transforms are rigid):
  // sqrt(3) x (step / 2 + float32 rounding) per vertex.
  double max_position_error = 0;
};

// The .glb bytes of `meshes_scene` (a tessellated scene: TriangleMesh / PolygonMesh shapes; curves are
// skipped and counted). Refuses (GeometryError naming the node path and shape) NURBS surfaces and
// invalid meshes; (std::invalid_argument) position_bits outside the compression's range or a scene
// unit that is not a positive length; (std::runtime_error "Draco: ...") what Draco refuses.
std::string write_glb(const Scene& meshes_scene, const GlbOptions& options, GlbReport* report = nullptr);

// "none", "draco", "meshopt" (the --compress values); nullopt for any other name.
std::optional<GlbCompression> glb_compression_named(std::string_view name);

}  // namespace cadnurbs
