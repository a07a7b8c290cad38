#pragma once
// Polygon meshes of one colour joined into one, vertices shared. Neighbouring planar faces compute their
// common corners from different surfaces, so the same corner differs in the last bits; welding within a
// tolerance far below the written precision makes it one vertex, written once and indexed by both.
#include <vector>

#include "core/polygon_mesh.hpp"

namespace cadnurbs {

// All `meshes` as one: positions closer than `tolerance` merged into the first of them (found through a
// hash grid of cell `tolerance`, the 27 cells around a point searched, so no pair within `tolerance` is
// missed at a cell border; greedy, so chains longer than `tolerance` are not merged transitively),
// unused positions dropped, repeated corners within a polygon removed and polygons left with fewer
// than three corners dropped. Positions keep their first-seen order.
PolygonMesh weld_polygon_meshes(const std::vector<PolygonMesh>& meshes, double tolerance);

}  // namespace cadnurbs
