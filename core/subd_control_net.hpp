#pragma once
// A Catmull-Clark subdivision surface's control net as Rhino's SubD stores it (level 0): polygons of any
// size over points, and the edges and points its rules keep sharp. formats/3dm reads it; analysis turns
// it into NURBS patches. Smooth, crease and dart points follow from the crease edges around them; only a
// corner (a point kept where it is) is said explicitly.
#include <Eigen/Core>
#include <array>
#include <string>
#include <vector>

namespace cadnurbs {

struct SubdControlNet {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> faces;          // point indices, counter-clockwise seen from outside
  std::vector<std::array<int, 2>> crease_edges;  // point pairs, either order; an edge of one face is a crease anyway
  std::vector<int> corner_points;                // Rhino's corner tag: the limit surface passes through the point
};

// Throws GeometryError(entity, reason) unless every point is finite, every face has 3 or more distinct
// points, every index is in range, and every crease edge is an edge of some face.
void validate(const SubdControlNet& net, const std::string& entity);

}  // namespace cadnurbs
