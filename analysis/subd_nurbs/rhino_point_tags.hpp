#pragma once
// The tag Rhino's SubD gives each point of a control net (openNURBS ON_SubDVertexTag), which picks the rule
// its subdivision point follows (internal to analysis/subd_nurbs).
//
// In: a net that validate() and check_manifold() accept. Out: its edges, and one tag per point from the
// crease edges around it (edges of one face are creases, as in Rhino): none smooth, one a dart, two a
// crease, three or more, or the net's corner tag, a corner. Refuses nothing.
#include <array>
#include <map>
#include <vector>

#include "core/subd_control_net.hpp"

namespace cadnurbs::subd_nurbs {

enum class PointTag { smooth, dart, crease, corner };

struct NetEdge {
  std::vector<int> faces;  // in face order
  bool crease = false;     // tagged a crease, or on the boundary
};
// Keyed by the edge's two points, smaller first.
using NetEdges = std::map<std::array<int, 2>, NetEdge>;

NetEdges net_edges(const SubdControlNet& net);

std::vector<PointTag> rhino_point_tags(const SubdControlNet& net, const NetEdges& edges);

}  // namespace cadnurbs::subd_nurbs
