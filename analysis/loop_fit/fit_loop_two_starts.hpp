#pragma once
// A Loop fit at a vertex budget from the better of two starting control meshes. The feature-keeping
// decimation keeps every crease, so on a part with many (a CAD tessellation) it spends nearly all of
// its vertices on them and leaves the smooth body a few large triangles; a plain quadric decimation
// spends them where the error is, and its own sharp edges are tagged instead. Neither wins everywhere
// (corpus: motor.stl at 268 vertices, two-sided RMS 2.71 mm from the first start, 1.03 from the second).
#include "analysis/loop_fit/decimate_control_mesh.hpp"
#include "analysis/loop_fit/fit_loop_surface.hpp"

namespace cadnurbs {

struct LoopTwoStartsReport {
  DecimationReport decimation;     // the feature-keeping decimation's
  LoopFitReport feature_start;     // the fit from it
  LoopFitReport plain_start;       // the fit from the plain decimation, tagged by tag_sharp_edges
  bool plain_start_kept = false;   // its RMS at the fit's samples was lower and its max no higher
  TriangleMesh plain_decimation;   // the plain start before tagging: what a user would publish instead
};

// Takes a welded mesh, the vertex target, the sharp angle (radians, >= 0), fit options, and input
// vertices every decimation must keep. Decimates with features kept (decimate_control_mesh), then
// plainly to the vertex count that reached (so both have as many, unless the plain one is stopped
// earlier by the kept vertices), tags the second by its own angles, fits both, and returns the second
// fit only when it is better at the fit's samples both ways: a lower RMS and a max no higher
// (LoopFitReport::rms, max); else the first. A lower RMS alone is not enough: on the corpus's tray the
// plain start's fit had 0.82 of the decimation's RMS against 0.88, but a max of 1.00 against 0.65.
// Costs two fits. Refuses what decimate_control_mesh and fit_loop_surface refuse, and a negative
// sharp angle (std::invalid_argument: there would be no features to choose between).
LoopControlMesh fit_loop_two_starts(const TriangleMesh& welded, int target_vertices, double sharp_angle_radians,
                                    const LoopFitOptions& options, LoopTwoStartsReport* report,
                                    const std::vector<int>& keep = {});

// The report of the kept fit.
inline const LoopFitReport& kept_fit(const LoopTwoStartsReport& r) { return r.plain_start_kept ? r.plain_start : r.feature_start; }

}  // namespace cadnurbs
