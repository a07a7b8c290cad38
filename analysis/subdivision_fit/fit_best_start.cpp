#include "analysis/subdivision_fit/fit_best_start.hpp"

#include <stdexcept>

#include "analysis/measure/mesh_distance.hpp"
#include "analysis/subdivision/limit_surface.hpp"
#include "analysis/subdivision_fit/crease_flat_corner_spans.hpp"
#include "analysis/subdivision_fit/decimate_within_distance.hpp"
#include "analysis/subdivision_fit/tag_sharp_edges.hpp"

namespace cadnurbs {

namespace {

double share(double figure, double decimations) { return decimations > 0 ? figure / decimations : figure; }

}  // namespace

SubdivisionControlMesh fit_and_measure(const TriangleMesh& welded, const SubdivisionControlMesh& start, const SubdivisionFitOptions& options,
                                     StartFit& out) {
  SubdivisionControlMesh fitted = fit_subdivision_surface(welded, start, options, &out.fit);
  const TriangleMesh limit = evaluate_limit_mesh(subdivision_limit_mesh(control_mesh_topology(fitted), options.levels), fitted.positions);
  out.distance = mesh_distance(limit, welded).overall;
  return fitted;
}

double start_score(const DeviationStats& fit, const DeviationStats& decimation) {
  return share(fit.rms, decimation.rms) + share(fit.max, decimation.max);
}

SubdivisionControlMesh fit_best_start(const TriangleMesh& welded, int target_vertices, double sharp_angle,
                                    const SubdivisionFitOptions& options, FitStartsReport* report,
                                    const std::vector<int>& keep) {
  if (!(sharp_angle >= 0)) throw std::invalid_argument("fit_best_start: the sharp angle must be 0 or more");
  FitStartsReport r;
  auto options_for = [&](FitStart start) {
    SubdivisionFitOptions o = options;
    o.balance_sides = start_balances_sides(start);
    return o;
  };
  const SubdivisionControlMesh feature_start = crease_flat_corner_spans(
      decimate_control_mesh(welded, target_vertices, sharp_angle, &r.decimation, keep), kFlatCornerSpanAngle);
  SubdivisionControlMesh best = fit_and_measure(welded, feature_start, options_for(FitStart::features), r.features);
  const StartFit* best_fit = &r.features;

  const int reached = static_cast<int>(feature_start.positions.size());
  const SubdivisionControlMesh plain = decimate_control_mesh(welded, reached, -1, nullptr, keep);
  r.plain_decimation = {plain.positions, plain.triangles, {}};
  r.plain_decimation_distance = mesh_distance(r.plain_decimation, welded).overall;
  auto beats = [&](const StartFit& a, const StartFit& b) {
    return start_score(a.distance, r.plain_decimation_distance) < start_score(b.distance, r.plain_decimation_distance);
  };
  SubdivisionControlMesh fitted = fit_and_measure(
      welded, crease_flat_corner_spans(tag_sharp_edges(r.plain_decimation, sharp_angle), kFlatCornerSpanAngle),
      options_for(FitStart::plain), r.plain);
  if (beats(r.plain, *best_fit)) {
    best = std::move(fitted);
    best_fit = &r.plain;
    r.kept = FitStart::plain;
  }

  const GuardedDecimation guarded = decimate_within_distance(welded, static_cast<int>(plain.positions.size()), keep);
  r.guard = guarded.guard;
  fitted = fit_and_measure(welded,
                           crease_flat_corner_spans(tag_sharp_edges(guarded.mesh, sharp_angle), kFlatCornerSpanAngle),
                           options_for(FitStart::guarded), r.guarded);
  if (beats(r.guarded, *best_fit)) {
    best = std::move(fitted);
    r.kept = FitStart::guarded;
  }
  if (report) *report = std::move(r);
  return best;
}

}  // namespace cadnurbs
