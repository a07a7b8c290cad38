#pragma once
// Step 4 of tessellate_to_deviation (see its header): the certified deviation of one mesh triangle from
// the surface over its (u,v) triangle (internal).
//
// In: the surface (its points, through the face's cache, and second-derivative bounds), the triangle's three corners (counter-
// clockwise in (u,v)) and D. Out: a bound on the distance between the surface over the triangle and
// the triangle's plane, ok when it is <= D; when not ok, where the sampled error peaks, for refinement.
//
// Why the bound holds: n.(S - A) is a C2 function on a piece of the triangle between C0 knot lines
// whose second derivatives are bounded by the patch bounds M (surface_deviation_bound), so it differs
// from its linear interpolation on a lattice of k divisions by at most triangle_deviation_bound / k^2
// (one lattice sub-triangle), and that interpolation is bounded by its largest sampled value. The
// bound is therefore (largest sample) + (whole-triangle bound) / k^2, with k = 3, 6, 12, finer only
// while undecided; a piece whose whole-triangle bound alone (plus the corners' errors) is <= D skips the
// lattice. A triangle crossing a C0 knot line is cut there into pieces first (the bound needs C1).
// Distances are to the plane, not to the triangle: a surface point may lie over the neighbouring
// triangle, which is no deviation. A triangle collapsed in 3D (at a pole) has no plane: distances to
// the triangle itself then.
#include <Eigen/Core>
#include <optional>

#include "analysis/eval/surface_deviation_bound.hpp"
#include "analysis/tessellation/surface_point_cache.hpp"

namespace cadnurbs::tessellation {

// A corner of a mesh triangle: its (u,v), its 3D point in the mesh (a shared point from another face may
// lie off this surface), and S(uv) - point.
struct MeshCorner {
  Eigen::Vector2d uv;
  Eigen::Vector3d point;
  Eigen::Vector3d error;
};

struct TriangleVerdict {
  bool ok = true;
  double bound = 0;    // certified bound (when ok) or the bound so far (when not)
  double sampled = 0;  // largest sampled error (corners included)
  // The side (k: from corner k to corner k + 1) where the sampled error peaks; empty when it peaks
  // inside or at a corner.
  std::optional<int> peak_side;
  Eigen::Vector2d peak;  // (u,v) of the peak (the centroid when no lattice was sampled)
  bool crosses_c0 = false;
  Eigen::Vector2d c0_point;  // middle of the longest cut along a C0 knot line, when crosses_c0
};

TriangleVerdict certify_triangle(SurfacePointCache& surface, const SurfaceDeviationBound& bound, const MeshCorner& a,
                                 const MeshCorner& b, const MeshCorner& c, double max_deviation);

}  // namespace cadnurbs::tessellation
