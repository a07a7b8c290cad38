#include "analysis/loop_fit/refit_watching_spans.hpp"

#include "analysis/loop_fit/fit_loop_best_start.hpp"
#include "analysis/mesh_distance.hpp"
#include "analysis/subdivision/loop_limit_surface.hpp"

namespace cadnurbs {

LoopControlMesh refit_watching_spans(const TriangleMesh& input, const LoopControlMesh& fitted,
                                     const DeviationStats& fitted_distance, const DeviationStats& decimation_distance,
                                     const LoopFitOptions& options, SpanRefitReport* report) {
  LoopFitOptions watching = options;
  watching.fit_limit_points_facing_away = true;
  SpanRefitReport r;
  LoopControlMesh refit = fit_loop_surface(input, fitted, watching, &r.fit);
  const TriangleMesh limit = evaluate_limit_mesh(loop_limit_mesh(loop_topology(refit), options.levels), refit.positions);
  r.distance = mesh_distance(limit, input).overall;
  r.kept = start_score(r.distance, decimation_distance) < start_score(fitted_distance, decimation_distance);
  if (report) *report = r;
  return r.kept ? refit : fitted;
}

}  // namespace cadnurbs
