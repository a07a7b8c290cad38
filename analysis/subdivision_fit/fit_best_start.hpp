#pragma once
// A Loop fit at a vertex budget from the best of three starting control meshes, judged by the measure
// a user sees: the limit surface's two-sided distance to the input (mesh_distance).
// - features: the decimation that keeps every crease (decimate_control_mesh). On a part with many (a
//   CAD tessellation) it spends nearly all of its vertices on them and leaves the body a few large
//   triangles (TR12J_OCC: 596 crease edges among 531 vertices).
// - plain: a plain quadric decimation to as many vertices, tagged where it is sharp itself
//   (tag_sharp_edges); it spends the vertices where the error is. Fitted with every sample weighted
//   by its area (SubdivisionFitOptions::balance_sides), as the guarded start is: on motor 0.61 of the
//   decimation's RMS and 0.91 of its max (stop 33; 0.65 and 0.96 with each side weighted as a whole,
//   0.80 and 1.00 unweighted).
// - guarded: the same under the smallest distance guard that reaches the count
//   (decimate_within_distance), which keeps it from closing cavities with lids, fitted weighted too,
//   which keeps it from folding to pass through noise.
// None wins everywhere (corpus, RMS ratio to the plain quadric decimation, pooled by count in stop 30:
// TR12J_OCC features 1.38, guarded 0.51; motor plain 0.70, guarded 0.84; the tray features 0.88,
// guarded 1.11).
#include "analysis/subdivision_fit/decimate_control_mesh.hpp"
#include "analysis/subdivision_fit/fit_subdivision_surface.hpp"
#include "analysis/measure/measure_deviation.hpp"

namespace cadnurbs {

enum class FitStart { features, plain, guarded };

struct StartFit {
  SubdivisionFitReport fit;          // at the fit's own samples
  DeviationStats distance;    // the limit surface to the input, two-sided (mesh_distance's overall)
};

struct FitStartsReport {
  DecimationReport decimation;          // the feature-keeping decimation's
  StartFit features, plain, guarded;
  FitStart kept = FitStart::features;
  double guard = 0;                     // the guarded start's distance guard (0: none reached the count)
  TriangleMesh plain_decimation;        // the plain start untagged: what a user would publish instead
  DeviationStats plain_decimation_distance;  // it to the input, two-sided (mesh_distance's overall)
};

// Takes a welded mesh, a start and fit options; returns fit_subdivision_surface's control mesh, its report
// and its limit surface's (options.levels refinements) two-sided distance to the mesh in `out`.
SubdivisionControlMesh fit_and_measure(const TriangleMesh& welded, const SubdivisionControlMesh& start, const SubdivisionFitOptions& options,
                                     StartFit& out);

// How far a start's fit stands from the plain quadric decimation at as many vertices: its limit
// surface's RMS and max, each as a share of the decimation's, summed (a figure the decimation has
// as 0 counts as it is). Lower is better. Both terms count, so neither a slightly lower max nor a
// slightly lower RMS buys the other at any price: on the corpus's motor at 536 control vertices the
// start that keeps the input's creases fits to 0.876 / 14.2 mm (RMS / max) and the plain one to
// 0.524 / 14.3 against the decimation's 0.809 / 14.9 (scores 2.03 and 1.61: the plain one is kept);
// on fan at 200 the plain one fits to 0.00698 / 0.104 mm and the creases' one to 0.00773 / 0.0918
// against 0.0276 / 0.246 (scores 0.68 and 0.65: the creases' one is kept).
double start_score(const DeviationStats& fit, const DeviationStats& decimation);

// Takes a welded mesh, the vertex target, the sharp angle (radians, >= 0), fit options (their
// balance_sides is set for the plain and guarded starts), and input vertices every decimation must keep.
// Decimates with features kept, then plainly and guarded to the vertex count that reached (so all
// have as many, unless kept vertices stop the plain ones earlier), creases each one's flat spans between
// corners (crease_flat_corner_spans, at kFlatCornerSpanAngle), fits all three, measures each
// limit surface (options.levels refinements) and the plain decimation against the input, and returns
// the fit with the lowest start_score (the first in the order features, plain, guarded on a tie).
// Until stop 32 a later start had to have a lower RMS and a max no higher: on motor at 400 and 536
// control vertices that kept fits with 1.24 and 1.08 of the decimation's RMS, for a max 1.8 and 0.1 mm
// lower than the plain start's fits, at 0.60 and 0.65 of it. Costs three fits and four measures.
// Refuses what decimate_control_mesh and fit_subdivision_surface refuse, and a negative sharp angle
// (std::invalid_argument: there would be no features to keep).
SubdivisionControlMesh fit_best_start(const TriangleMesh& welded, int target_vertices, double sharp_angle_radians,
                                    const SubdivisionFitOptions& options, FitStartsReport* report,
                                    const std::vector<int>& keep = {});

// Whether a start is fitted with SubdivisionFitOptions::balance_sides: the plain and guarded ones are, the
// feature-keeping one is not (a refit of the kept start weights alike, so the RMS compare).
inline bool start_balances_sides(FitStart start) { return start != FitStart::features; }

// The kept start's fit and measure.
inline const StartFit& kept_start(const FitStartsReport& r) {
  return r.kept == FitStart::plain ? r.plain : r.kept == FitStart::guarded ? r.guarded : r.features;
}

}  // namespace cadnurbs
