#pragma once
// The check that the compact writer changes no geometry beyond the written precision (issue 8): `source`
// is written twice as X3D, compact (compact_scene, then the writer's DEF/USE) and --exact-nurbs (every
// face the NURBS of its source), and both are read back:
//  - their areas agree within 1e-6 (relative);
//  - their meshes at D = 0.005 x the bounding-box diagonal are within 2 D of each other (two-sided);
//  - every triangle of a polygon set (a planar face written as exact polygons) has its three corners
//    within the written precision (1.5 τ: τ/2 per coordinate written, τ/4 welding) of one plane of a
//    planar face of the source.
// Reports failures through GoogleTest and prints one line of figures.
#include <string>

#include "core/scene.hpp"

namespace cadnurbs::test {

void check_compact_is_exact(const Scene& source, const std::string& name);

}  // namespace cadnurbs::test
