#pragma once
// The limit surface of a SubD under Rhino's own rules, patch by patch: what subd_to_nurbs fits, copies and
// measures against (internal to analysis/subd_nurbs).
//
// Patches: one per quad of the net, or, when the net has faces other than quads, one per quad after one step
// of Rhino's rules (rhino_subdivision_step: face f's children in order, child k from its point k), each over
// (u, v) in [0, 1]^2 as SubdLimitSurface's.
//
// Where Rhino's rules are the textbook ones (no sector coefficient other than 1/2 on an edge at a patch
// corner) the patch is OpenSubdiv's limit of that net (SubdLimitSurface), exact. Elsewhere ("Rhino
// patches") Rhino's rules matter at every level near the tagged point: the patch is OpenSubdiv's limit of
// the net after `levels` more steps of Rhino's rules, which is Rhino's limit exactly on every square of side
// 2^-levels whose corners meet no such edge (every limit point at a net point is exact: a smooth point's
// ring is textbook after one step, a crease point's limit lies on its crease's B-spline, a corner's is
// itself). On the squares of side 2^-levels at the tagged points it is not Rhino's: their pieces carry no
// B-spline (patch_deviation samples them), and the two surfaces differ there by a few 2^-levels of the
// net's local size (docs/3dm.md gives the measured figures).
//
// In: a net check_manifold() accepts, levels >= 1. Refuses (GeometryError(entity, reason)) what
// check_manifold and SubdLimitSurface refuse.
#include <memory>
#include <string>
#include <vector>

#include "analysis/subd_nurbs/rhino_subdivision_step.hpp"
#include "analysis/subd_nurbs/subd_limit_surface.hpp"

namespace cadnurbs::subd_nurbs {

constexpr int kRhinoReferenceLevels = 4;

class RhinoLimitSurface {
 public:
  RhinoLimitSurface(const SubdControlNet& net, const std::string& entity, int levels = kRhinoReferenceLevels);

  int patch_count() const { return base_.patch_count(); }
  Eigen::Vector3d point(int patch, double u, double v) const;
  const std::vector<LimitPiece>& pieces(int patch) const;
  PatchSide neighbour(int patch, int side) const { return base_.neighbour(patch, side); }
  // Whether a sector coefficient other than 1/2 shapes the patch (Rhino's limit differs from the textbook one).
  bool follows_sector_coefficients(int patch) const { return rhino_patch_[patch]; }

 private:
  RhinoNet base_net_;
  SubdLimitSurface base_;
  std::vector<bool> rhino_patch_;
  int levels_;
  std::unique_ptr<SubdLimitSurface> refined_;  // only when some patch is a Rhino patch
  std::vector<std::vector<int>> children_;     // per Rhino patch: refined faces, i + 2^levels j
  std::vector<std::vector<LimitPiece>> rhino_pieces_;
};

}  // namespace cadnurbs::subd_nurbs
