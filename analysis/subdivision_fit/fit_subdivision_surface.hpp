#pragma once
// Fitting a Loop subdivision surface to a triangle mesh: the control points are solved so that the
// limit surface passes close to the mesh (Hoppe et al. 1994, "Piecewise smooth surface
// reconstruction", phase 3; Ma et al. 2004 for the limit-point least squares). The control mesh's
// connectivity and sharp tags are given (decimate_control_mesh); fit_to_tolerance adds vertices.
#include "core/subdivision_control_mesh.hpp"

namespace cadnurbs {

struct SubdivisionFitOptions {
  int levels = 3;            // refinements of the limit mesh that stands for the limit surface
  double fairness = 1e-5;    // spring term weight, relative to the data terms (Hoppe's E_spring)
  // Point-to-point share next to the point-to-tangent-plane distance: small, so points slide along
  // the surface (the squared distance minimisation of Ma et al. 2004), yet above 0, so the solve
  // stays definite. 0.05 (until stop 31) took 2 to 4 times the rounds and fitted no closer: at 200
  // control vertices capping-90 60 rounds -> 14, RMS 0.257 -> 0.227 of the quadric decimation's;
  // only plate_holes got worse (0.239 -> 0.293).
  double tangent_weight = 0.001;
  int max_iterations = 60;   // project-and-solve rounds
  // Weight every sample by the area it stands for, as the two-sided measure does: a data point by its
  // share of its triangles' area (a triangle's area split evenly over its lattice points and its
  // corners), a limit point by its share of the limit mesh's. Unweighted, the some 15 times more data
  // points let the surface fold to pass near every one of them (corpus: simple_mesh_binary's noisy
  // sheet got a limit area 1.34 times its own). Weighting each side as a whole (until stop 33) still
  // let the dense regions of a CAD tessellation pull the fit: on motor, half the data points lie on
  // 15 % of the area (the tray: 4 %); weighting each point took motor's plain start from 0.651 to
  // 0.591 of the quadric decimation's RMS. The RMS reported (and the best round chosen by) is
  // weighted the same way.
  bool balance_sides = false;
  // Fit the limit points whose nearest input point faces away too. Where the surface spans a gap
  // (motor's half-bore) its nearest input points lie on the gap's walls, at about right angles, and
  // about half of them count as facing away: left out, the span sags unwatched. Off by default: in
  // every fit it took motor's plain start from 0.607 / 0.914 of the quadric decimation's RMS / max to
  // 0.625 / 0.980, and made its connectivity rounds diverge (stop 33); refit_watching_spans uses it
  // once, on a fitted mesh.
  bool fit_limit_points_facing_away = false;
  // A residual is measured along the surface normal at its foot point, unless the offset from foot to
  // target makes an angle with it whose cosine is below this (some 46 degrees): then along the offset.
  // The tangent-plane distance is the distance only where the target lies above the surface; where the
  // foot is on a rim or a crease and the target beside the surface (a hole's outline that the limit's
  // B-spline crease draws inside the input's, a limit point past a face's edge), the offset lies in the
  // tangent plane and only the 0.001 point-to-point share saw it. On dm1-id-214.stp meshed by
  // OpenCASCADE (issue 38 item 6) the input-to-limit max went from 1.51 to 0.46 mm. 0: always the normal.
  double off_normal_cosine = 0.7;
  // ... and only where the distance is over this many times the best round's RMS so far (none in the
  // first round): the far residuals, which make the max.
  double off_normal_rms_share = 3;
};

struct SubdivisionFitReport {
  int iterations = 0;         // project-and-solve rounds
  long data_samples = 0;      // input points fitted
  double rms = 0, max = 0;    // two-sided distances at the fit's samples, in the best round
  // Per input vertex, the largest distance of the samples nearest it (input points on its triangles,
  // limit points whose nearest input point is by it): where the fit stays far.
  std::vector<double> input_vertex_distance;
};

// Takes a welded input mesh and a starting control mesh; returns the control mesh with fitted
// positions (connectivity and tags unchanged). The data: every input vertex, and on every triangle a
// lattice at most half the mean edge length apart; and the other way, every limit-mesh vertex is
// pulled to its nearest input point, so the distance is fitted both ways. Each round projects the
// data onto the current limit mesh (CGAL AABB tree), then solves the sparse least squares for all
// control points at once (Eigen LDLT of the normal equations), each residual measured to the tangent
// plane at its foot point (along the offset where that turns far from the normal) plus a small point-to-point share
// (squared distance minimisation, as Ma et al. 2004), pairs whose normals face opposite ways left out (thin walls; the
// limit side's are kept with fit_limit_points_facing_away); it stops when three rounds in a row improve the RMS by less
// than 0.1 % and keeps the best round.
// Refuses (std::invalid_argument) an input or control mesh without triangles, levels outside 1..5.
SubdivisionControlMesh fit_subdivision_surface(const TriangleMesh& input, const SubdivisionControlMesh& start, const SubdivisionFitOptions& options,
                                 SubdivisionFitReport* report = nullptr);

}  // namespace cadnurbs
