#pragma once
// One Catmull-Clark step under Rhino's SubD rules (openNURBS ON_SubDVertex/Edge/Face subdivision points,
// read from its public source, not copied) (internal to analysis/subd_nurbs).
//
// Rules: a face point is the face's centroid. A crease edge's point is its midpoint; a smooth edge's is
// 3/4 (wa A + wb B) - (A + B) / 8 + (F0 + F1) / 4, F the centroids of its two faces, wa = wb = 1/2 but at a
// tagged end with a sector coefficient (rhino_sector_coefficients.hpp): the textbook rule for every face
// size (Rhino's weights for triangles and other faces come to the same). A corner stays; a crease point
// goes to (6 V + E0 + E1) / 8, E its crease neighbours; a smooth or dart point of n faces to
// (1 - 2 / n) V + (sum of its edge neighbours + sum of its faces' centroids) / n^2 (textbook).
// Rhino builds before 2019-11-11 weighed edges beside faces other than quads differently (the corpus logo's
// cached limit points were computed so; see docs/3dm.md).
//
// In: a net that validate() and check_manifold() accept, and its sector coefficients. Out: the net after one
// step, all quads: the old points first (same numbers), then one per edge, then one per face; crease edges
// halved, corners kept, coefficients carried to the halves at their tagged ends. Face f's children are in
// order, child k at its point k: a quad's child k covers the quarter of the quad's (u, v) at its point k and
// runs as the quad does (its corner k is point k), another face's child k starts at point k, u toward point
// k + 1 (OpenSubdiv's order, so patches keep their numbers).
#include <vector>

#include "analysis/subd_nurbs/rhino_sector_coefficients.hpp"

namespace cadnurbs::subd_nurbs {

struct RhinoNet {
  SubdControlNet net;
  SectorCoefficients coefficients;
};

RhinoNet rhino_subdivision_step(const RhinoNet& in);

// The sector coefficients of a level-0 net (its tags and edges worked out here).
RhinoNet rhino_net(const SubdControlNet& net);

}  // namespace cadnurbs::subd_nurbs
