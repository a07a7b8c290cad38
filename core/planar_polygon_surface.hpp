#pragma once
// A planar polygon as a trimmed NURBS surface, so that the polygons a compact file holds can take part
// in what works on trimmed surfaces (sewing, shared-edge tessellation).
//
// In:  the corners of one planar polygon (3 or more, in order; counter-clockwise seen from the side its
//      normal should face).
// Out: a bilinear patch over the polygon's bounding rectangle in its own plane (axes: its longest side
//      and the Newell normal crossed with it), trimmed by one loop of straight segments, one per polygon
//      side, counter-clockwise in (u,v), so that Su x Sv is the Newell normal. The surface at the loop's
//      points gives back the corners up to round-off. Empty when the polygon has no area (Newell normal
//      zero) or fewer than 3 corners.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "core/trimmed_surface.hpp"

namespace cadnurbs {

std::optional<TrimmedSurface> planar_polygon_surface(const std::vector<Eigen::Vector3d>& corners);

}  // namespace cadnurbs
