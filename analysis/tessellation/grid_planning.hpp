#pragma once
// Step 1 of tessellate_to_deviation (see its header): the tensor grid of one face.
//
// In: the surface (evaluator and its per-patch second-derivative bounds), the face's trimming loops as
// (u,v) polygons (empty: untrimmed), and the deviation D. Out: sorted u and v grid lines from the
// domain's start to its end, every C0 knot among them.
//
// Each Bezier patch that the trimmed region reaches (a loop passes through it, or its centre is inside)
// wants n_u x n_v cells, n chosen from second derivatives sampled on a 4 x 4 lattice of the patch (their
// normal components: tangential acceleration costs no deviation) so that the Filip-Magedson-Markot
// estimate (1/8)(h_u^2 M_uu + 2 h_u h_v M_uv + h_v^2 M_vv) is 0.85 D. This is an estimate, not a bound:
// step 4 certifies every triangle and refines where it was too optimistic; a good grid only saves that
// work. n may be a fraction (a patch already within the target shares a cell with its neighbours). The
// budget is split evenly between the two directions unless one needs a single step (a cylinder's
// straight direction: long thin triangles, which a deviation bound allows); a direction that is
// straight and untwisted gets no line of its own. The wanted cells per span (the most any patch of that
// column or row wants, at most 4096) are spread evenly between C0 knot lines, so smooth knots need no
// grid line of their own.
#include <Eigen/Core>
#include <vector>

#include "analysis/eval/surface_deviation_bound.hpp"
#include "analysis/eval/surface_evaluator.hpp"

namespace cadnurbs::tessellation {

struct TessellationGrid {
  std::vector<double> us, vs;  // grid lines, domain ends and C0 knots included
};

TessellationGrid plan_tessellation_grid(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound,
                                        const std::vector<std::vector<Eigen::Vector2d>>& loops, double max_deviation);

// Grid lines over the knot breaks `breaks` (span i wants `steps[i]` cells, a fraction allowed): the
// wanted density steps[i] / length is integrated between hard lines (the ends and the values of `hard`
// inside), and lines go at equal shares of it, at least one cell between hard lines. A run of thin knot
// spans (linkrods.step: nine within 1e-4 of each other) then shares cells with its neighbours instead
// of adding a row of slivers each.
std::vector<double> graded_grid_lines(const std::vector<double>& breaks, const std::vector<double>& steps,
                                      const std::vector<double>& hard);

}  // namespace cadnurbs::tessellation
