#include "analysis/subdivision_fit/refit_watching_spans.hpp"

namespace cadnurbs {

SubdivisionControlMesh refit_watching_spans(const TriangleMesh& input, const SubdivisionControlMesh& fitted,
                                     const DeviationStats& fitted_distance, const DeviationStats& decimation_distance,
                                     const SubdivisionFitOptions& options, SpanRefitReport* report) {
  SubdivisionFitOptions watching = options;
  watching.fit_limit_points_facing_away = true;
  SpanRefitReport r;
  SubdivisionControlMesh refit = fit_and_measure(input, fitted, watching, r.refit);
  r.kept = start_score(r.refit.distance, decimation_distance) < start_score(fitted_distance, decimation_distance);
  if (report) *report = r;
  return r.kept ? refit : fitted;
}

}  // namespace cadnurbs
