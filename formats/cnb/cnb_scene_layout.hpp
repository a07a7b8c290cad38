#pragma once
// Flag bits of the scene tree records (docs/cnb.md, "Scene tree"), shared by the writer and the reader.
#include <cstdint>

namespace cadnurbs::cnb {

// Node flags.
constexpr uint8_t node_colour_flag = 1, node_linear_flag = 2, node_translation_flag = 4;
// Shape kind byte: the geometry's kind (0 trimmed surface, 1 3D curve, 2 triangle mesh, 3 polygon mesh,
// the order of core::Geometry) in the low bits, this bit when the shape has its own colour.
constexpr uint8_t has_colour_flag = 0x10;
// Deeper node trees are refused (a crafted file must not exhaust the reader's stack).
constexpr int deepest_node = 1000;

}  // namespace cadnurbs::cnb
