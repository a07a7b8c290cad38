#pragma once
// The Catmull-Clark limit surface of a SubdControlNet, patch by patch, through OpenSubdiv 3.5 (Far): what
// subd_to_nurbs fits, copies and measures against (internal to analysis/subd_nurbs).
//
// Patches: one per quad of the net (all quads), OpenSubdiv's ptex faces, each over (u, v) in [0, 1]^2. A
// quad's (0, 0) is its first point, u runs toward its second and v toward its last, so Su x Sv points where
// the face does (outward).
// Sides k = 0..3 run counter-clockwise: v = 0, u = 1, v = 1, u = 0.
//
// Rules: textbook Catmull-Clark (OpenSubdiv's); crease edges and boundary edges are infinitely sharp (the limit there is the cubic B-spline of the
// crease points), corner points stay where they are; everything else is smooth. Away from extraordinary
// features the limit is OpenSubdiv's regular B-spline patches, exact; features are isolated adaptively to
// level 10, where the square of side 2^-10 touching them is a Gregory patch (OpenSubdiv's end cap, exact
// at its corners: the limit-position masks); everywhere else every point is exact.
//
// In: a net check_manifold() accepts, all quads. Refuses (GeometryError(entity, reason)) a topology
// OpenSubdiv refuses.
#include <Eigen/Core>
#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/subd_control_net.hpp"

namespace cadnurbs::subd_nurbs {

// The neighbour across one side of a patch: its patch and which of its sides; patch -1 on the boundary.
struct PatchSide {
  int patch = -1;
  int side = -1;
};

// A square [u0, u0 + size] x [v0, v0 + size] of a patch's domain where OpenSubdiv has one patch: a regular
// one (the limit there is the uniform bicubic B-spline of `bspline`, index i + 4 j, u fastest, the points
// beyond a boundary or crease already the phantoms 2 P1 - P2), or an end cap at an extraordinary feature
// (no `bspline`).
struct LimitPiece {
  double u0 = 0, v0 = 0, size = 1;
  std::optional<std::array<Eigen::Vector3d, 16>> bspline;
};

class SubdLimitSurface {
 public:
  SubdLimitSurface(const SubdControlNet& net, const std::string& entity);
  ~SubdLimitSurface();
  SubdLimitSurface(const SubdLimitSurface&) = delete;
  SubdLimitSurface& operator=(const SubdLimitSurface&) = delete;

  int patch_count() const;
  // The limit point of patch `patch` at (u, v) in [0, 1]^2.
  Eigen::Vector3d point(int patch, double u, double v) const;
  // The squares that tile the patch's domain: one regular piece of size 1 where the patch is regular.
  const std::vector<LimitPiece>& pieces(int patch) const;
  PatchSide neighbour(int patch, int side) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace cadnurbs::subd_nurbs
