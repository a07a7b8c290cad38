#pragma once
// One more fit of a fitted control mesh, with every limit point fitted, those whose nearest input
// point faces away too (SubdivisionFitOptions::fit_limit_points_facing_away), kept only when the user's
// measure says it is closer. The fit leaves such points out because on a thin wall the nearest point
// can be on the other sheet; but where the control mesh spans a gap the walls' points face the span
// at about right angles, and the span sags unwatched. On the corpus's motor at 268 control vertices,
// after three connectivity rounds, the surface sagged 15.8 mm into the half-bore against the quadric
// decimation's 14.9; refitted so, 0.481 / 0.758 of the decimation's RMS / max, from 0.498 / 1.061.
// Fitted so from the start instead, the rounds went astray (stop 33), hence once, at the end.
#include "analysis/subdivision_fit/fit_best_start.hpp"

namespace cadnurbs {

struct SpanRefitReport {
  StartFit refit;   // the refit's report and its limit surface's two-sided distance to the input
  bool kept = false;    // its start_score against the decimation was lower than the given fit's
};

// Takes a welded input mesh, a fitted control mesh, its limit surface's two-sided distance to the
// input, the plain quadric decimation's at as many vertices, and the options it was fitted with;
// refits with limit points facing away fitted, measures the refit's limit surface (options.levels
// refinements), and returns it when its start_score is lower, else the given mesh. Costs one fit and
// one measure. Refuses what fit_subdivision_surface refuses.
SubdivisionControlMesh refit_watching_spans(const TriangleMesh& input, const SubdivisionControlMesh& fitted,
                                     const DeviationStats& fitted_distance, const DeviationStats& decimation_distance,
                                     const SubdivisionFitOptions& options, SpanRefitReport* report = nullptr);

}  // namespace cadnurbs
