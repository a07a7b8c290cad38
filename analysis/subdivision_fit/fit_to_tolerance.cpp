#include "analysis/subdivision_fit/fit_to_tolerance.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "analysis/subdivision_fit/crease_flat_corner_spans.hpp"

namespace cadnurbs {

SubdivisionControlMesh fit_to_tolerance(const TriangleMesh& welded, int start_vertices, double sharp_angle,
                                      double tolerance, const SubdivisionFitOptions& options, ToleranceFitReport* report) {
  if (!(tolerance > 0 && std::isfinite(tolerance)))
    throw std::invalid_argument("fit_to_tolerance: the tolerance must be a positive number");
  ToleranceFitReport r;
  std::set<int> keep;
  int target = start_vertices;
  SubdivisionControlMesh fitted;
  const int input_vertices = static_cast<int>(welded.positions.size());
  for (r.rounds = 1;; ++r.rounds) {
    const SubdivisionControlMesh start = crease_flat_corner_spans(
        decimate_control_mesh(welded, target, sharp_angle, &r.decimation, {keep.begin(), keep.end()}),
        kFlatCornerSpanAngle);
    fitted = fit_subdivision_surface(welded, start, options, &r.fit);
    r.met = r.fit.max <= tolerance;
    if (r.met) break;
    int added = 0;
    for (int v = 0; v < input_vertices; ++v)
      if (r.fit.input_vertex_distance[v] > tolerance && keep.insert(v).second) ++added;
    const int count = static_cast<int>(fitted.positions.size());
    target = std::max(count + added, count + (count + 7) / 8);
    if (added == 0 || target >= input_vertices || r.rounds == kMaxToleranceRounds) break;
  }
  if (report) *report = r;
  return fitted;
}

}  // namespace cadnurbs
