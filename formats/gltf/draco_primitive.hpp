#pragma once
// One glTF primitive compressed by Draco, as KHR_draco_mesh_compression stores it: a Draco mesh
// stream in a bufferView, and the id by which the primitive's extension names its POSITION attribute.
#include <string>

#include "formats/gltf/node_primitives.hpp"
#include "formats/gltf/position_grid.hpp"

namespace cadnurbs {

struct DracoPrimitive {
  std::string bytes;          // the Draco stream
  int position_id = -1;       // the POSITION attribute's unique id in the stream
  long points = 0, faces = 0;  // what the decoder will produce (the glTF accessors' counts)
};

// Encodes `mesh` (positions as float32) with Draco's edgebreaker, positions quantised on `grid`
// (explicit quantisation: the same grid for every primitive), at Draco speed `speed` (0 smallest ..
// 10 fastest) for both encoding and decoding. Refuses (std::runtime_error "Draco: <reason>") what
// Draco refuses.
DracoPrimitive draco_primitive(const PrimitiveMesh& mesh, const PositionGrid& grid, int speed);

}  // namespace cadnurbs
