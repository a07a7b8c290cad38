#pragma once
// The scene with its triangle meshes merged into one per colour, in world coordinates: for coders that
// code a mesh's shared edges once and its repeated coordinates cheaply (.cnb's traversal coding), one
// mesh of a whole part costs less than a mesh per body with the nodes that place them (measured on
// KiCad parts: bench/cnb_library_sizes.cpp).
//
// In: any scene. Out: every TriangleMesh shape placed by its node's world transform and appended to the
// mesh of the colour it is drawn with (its own, else its nearest node's, else the default), each merged
// mesh welded by exact position, without corner normals, and put at the root (named "meshes", in the
// order their colours are first met) with its colour. Every other shape stays in its node; nodes left
// with neither shapes nor children are removed (the root stays). A mesh placed N times becomes N copies.
#include "core/scene.hpp"

namespace cadnurbs {

Scene merge_world_meshes(const Scene& scene);

}  // namespace cadnurbs
