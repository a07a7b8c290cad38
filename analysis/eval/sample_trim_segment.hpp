#pragma once
// Sampling one trimming segment (a 2D NURBS curve or a polyline in a surface's (u,v) domain) by the
// deviation of its 3D image, so the mesh boundary lies within D of the exact trimmed surface.
//
// A chord [t_a, t_b] is kept when, at m evenly spaced interior parameters,
//  (1) the 3D curve S(c(t)) lies within 0.9 D of the 3D chord (what a viewer sees at the border), and
//  (2) the surface over the straight (u,v) chord lies within D of the 3D chord, certified like the
//      triangles: max over the m samples + (1/8) (h/m)^2 Q(chord) with the rigorous second-derivative
//      bound Q of surface_deviation_bound (this is exactly the mesh edge's own deviation), and
//  (3) that sampled distance stays below 0.3 of the chord's length: however coarse D, no chord stands
//      for an arc turning by more than about 100 degrees (a half-circle is two chords, so the two halves
//      of a cylinder thinner than D never mesh to the same flat quad); a sagitta under 1e-9 D is
//      rounding and passes (where the image stands still, chords are ulps long).
// (1) has no rigorous remainder (it would need bounds on the pcurve's derivatives): with m = 8 the
// unsampled part of a chord's sagitta is about 1/64 of it when the curvature varies less than a few
// times over one chord; the 0.9 factor covers that (0.9 (1 + 1/64) < 0.92). A chord may span C0
// knots of the pcurve (polyline vertices, the knots of a degree-1 pcurve) and the points where a
// polyline crosses a C0 knot line of the surface: these kinks are sampled as well, so the smooth pieces
// between samples are never longer than an eighth of the chord. A failed chord is split into pieces by
// its sampled sagitta (halved when it failed criterion (2) or the grid; splits move onto nearby kinks),
// then chords are merged greedily, each kept sample reaching the farthest later sample whose chord
// passes; last, between samples on kinks, one chord fewer evenly spaced in t replaces the run while
// every chord of it passes.
#include <Eigen/Core>
#include <vector>

#include "analysis/eval/surface_deviation_bound.hpp"
#include "analysis/eval/surface_evaluator.hpp"
#include "core/trim_segment_parameters.hpp"  // segment_t0, segment_uv, ...: the parametrisation sampled here
#include "core/trimmed_surface.hpp"

namespace cadnurbs {

struct TrimSample {
  double t;
  Eigen::Vector2d uv;
  Eigen::Vector3d point;
};

// True when S(c(t)) moves less than `tolerance` over the whole segment (a pole or a collapsed edge).
bool is_degenerate_segment(const SurfaceEvaluator& surface, const TrimSegment& segment, double tolerance);

// How many of the sorted grid `lines` lie strictly between a and b.
int lines_between(const std::vector<double>& lines, double a, double b);

// Criterion (2) alone, for the straight (u,v) chord from a_uv to b_uv whose 3D ends are a and b.
bool surface_chord_within(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound, const Eigen::Vector2d& a_uv,
                          const Eigen::Vector3d& a, const Eigen::Vector2d& b_uv, const Eigen::Vector3d& b, double d);

// Samples of the segment from its start to its end, first and last given as `start_point` and
// `end_point` (shared model vertices: used as they are, bit for bit). With a tessellation grid
// (grid_u, grid_v: sorted parameter lines), no chord crosses more than one line of it in u or in v,
// so that the triangles between the loop and the grid stay small. Refuses nothing: a chord shorter
// than 1e-12 of the parameter range is kept whatever its deviation.
std::vector<TrimSample> sample_trim_segment(const SurfaceEvaluator& surface, const SurfaceDeviationBound& bound,
                                            const TrimSegment& segment, double max_deviation,
                                            const Eigen::Vector3d& start_point, const Eigen::Vector3d& end_point,
                                            const std::vector<double>* grid_u = nullptr,
                                            const std::vector<double>* grid_v = nullptr);

}  // namespace cadnurbs
