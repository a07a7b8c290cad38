#include "analysis/loop_fit/fit_loop_two_starts.hpp"

#include <stdexcept>

#include "analysis/loop_fit/tag_sharp_edges.hpp"

namespace cadnurbs {

LoopControlMesh fit_loop_two_starts(const TriangleMesh& welded, int target_vertices, double sharp_angle,
                                    const LoopFitOptions& options, LoopTwoStartsReport* report,
                                    const std::vector<int>& keep) {
  if (!(sharp_angle >= 0)) throw std::invalid_argument("fit_loop_two_starts: the sharp angle must be 0 or more");
  LoopTwoStartsReport r;
  const LoopControlMesh feature_start = decimate_control_mesh(welded, target_vertices, sharp_angle, &r.decimation, keep);
  const LoopControlMesh feature_fit = fit_loop_surface(welded, feature_start, options, &r.feature_start);

  const int reached = static_cast<int>(feature_start.positions.size());
  const LoopControlMesh plain = decimate_control_mesh(welded, reached, -1, nullptr, keep);
  r.plain_decimation = {plain.positions, plain.triangles, {}};
  const LoopControlMesh plain_start = tag_sharp_edges(r.plain_decimation, sharp_angle);
  const LoopControlMesh plain_fit = fit_loop_surface(welded, plain_start, options, &r.plain_start);

  r.plain_start_kept = r.plain_start.rms < r.feature_start.rms && r.plain_start.max <= r.feature_start.max;
  const bool plain_kept = r.plain_start_kept;
  if (report) *report = std::move(r);
  return plain_kept ? plain_fit : feature_fit;
}

}  // namespace cadnurbs
