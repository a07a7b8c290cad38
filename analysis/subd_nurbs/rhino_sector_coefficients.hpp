#pragma once
// Rhino's sector coefficients (openNURBS ON_SubDSectorType; read from its public source, not copied): the
// one place Rhino's SubD departs from textbook Catmull-Clark (internal to analysis/subd_nurbs).
//
// Rhino subdivides a smooth edge from a tagged point C (dart, crease or corner) to a smooth point P with the
// weights 3/4 (w C + (1 - w) P) in place of 3/8 (C + P), the face terms unchanged; w = 1/2 + cos(theta) / 3,
// cos snapped to 0, +-1/2 or +-1 within 1e-6, where, with F the faces of the edge's sector (the faces
// around C reached without crossing a crease): theta = pi / F at a crease, 2 pi / F at a dart, and A / F at
// a corner, A the angle between the sector's two crease edges at level 0 (in [0, pi], rounded to the nearest
// multiple of 5 degrees, at least 5). A smooth edge whose two ends are tagged is subdivided with 3/8, 3/8;
// its halves carry w at their tagged ends. w stays with the edge end through every level. w = 1/2 (a crease
// of two faces a side, a dart of 4 faces, a right-angled corner of one face) is the textbook rule; OpenSubdiv
// 3.5 has no other (Sdc's smooth edge mask weighs both ends alike), hence our own refinement.
//
// In: a net that validate() and check_manifold() accept, its edges and tags (rhino_point_tags). Out: w for
// every end (tagged point, other point) of a smooth edge at a tagged point where w != 1/2. Refuses nothing.
#include <array>
#include <map>

#include "analysis/subd_nurbs/rhino_point_tags.hpp"

namespace cadnurbs::subd_nurbs {

using SectorCoefficients = std::map<std::array<int, 2>, double>;  // (tagged point, other point) -> w

double rhino_sector_coefficient(double theta);

SectorCoefficients rhino_sector_coefficients(const SubdControlNet& net, const NetEdges& edges,
                                             const std::vector<PointTag>& tags);

}  // namespace cadnurbs::subd_nurbs
