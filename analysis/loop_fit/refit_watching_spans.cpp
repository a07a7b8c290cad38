#include "analysis/loop_fit/refit_watching_spans.hpp"

namespace cadnurbs {

LoopControlMesh refit_watching_spans(const TriangleMesh& input, const LoopControlMesh& fitted,
                                     const DeviationStats& fitted_distance, const DeviationStats& decimation_distance,
                                     const LoopFitOptions& options, SpanRefitReport* report) {
  LoopFitOptions watching = options;
  watching.fit_limit_points_facing_away = true;
  SpanRefitReport r;
  LoopControlMesh refit = fit_loop_and_measure(input, fitted, watching, r.refit);
  r.kept = start_score(r.refit.distance, decimation_distance) < start_score(fitted_distance, decimation_distance);
  if (report) *report = r;
  return r.kept ? refit : fitted;
}

}  // namespace cadnurbs
