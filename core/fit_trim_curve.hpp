#pragma once
// The trimming curve of an edge in a face's (u,v) domain, computed from the edge's 3D curve where the
// file gives none (STEP files without pcurves): the edge sampled, each sample located on the surface,
// the (u,v) samples interpolated (Piegl & Tiller 9.2.1), refined until the image follows the edge.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <functional>

#include "core/nurbs_curve.hpp"

namespace cadnurbs {

// The caller's inversion onto the surface: the (u,v) of a 3D point, given the (u,v) of the previous
// sample along the curve (so the result stays continuous across seams of periodic surfaces and at poles).
using LocateOnSurface = std::function<Eigen::Vector2d(const Eigen::Vector3d& point, const Eigen::Vector2d& previous)>;
// The face's surface, in the same (u,v) as LocateOnSurface's (values `locate` returns beyond the
// surface's domain, e.g. unwrapped across a seam, must be accepted).
using SurfaceAt = std::function<Eigen::Vector3d(const Eigen::Vector2d& uv)>;

struct TrimCurveFit {
  NurbsCurve curve;           // dimension 2, z = 0, polynomial, clamped, domain [0, 1]
  double max_distance = 0;    // largest |surface_at(curve(s)) - edge(t(s))| over the checked points
  int checked_points = 0;     // how many: the samples and the midpoints between consecutive samples
};

// Most samples fit_trim_curve locates before it refuses.
constexpr int kMaxTrimCurveSamples = 4096;

// The edge curve `edge` (dimension 3) between t0 and t1 (t0 != t1, both in its domain; t0 > t1: the
// result runs from edge(t0) to edge(t1), i.e. against the edge) as a 2D curve c on s in [0, 1] with
// s <-> t(s) = t0 + s (t1 - t0). c(0) is exactly `start_uv` (the caller's: it places the seam), c(1)
// exactly the located (u,v) of edge(t1).
//
// Checked, not bound: |surface_at(c(s)) - surface_at(locate(edge(t(s))))| <= tolerance (3D) at every
// checked point: the samples (per knot span of the edge max(2, degree + 1) intervals to start with, at
// least 4 in all, one a span past 256; more added by bisection where a check fails) and the midpoints
// between consecutive samples. Between them the image is not checked.
//
// The curve: degree 1 with 2 points when all located samples lie on a line to 1e-10 of their extent
// and the chord passes the checks; for a degree-1 edge, the polyline through the samples at its knots if
// it passes; else cubic (lower with fewer than 4 points) through a subset of the samples: once the
// interpolant of all samples passes, every other sample is dropped while the interpolant of the rest
// still passes every check, then single samples greedily (few control points: these curves are stored;
// the greedy pass costs a fit and a check per sample, O(n^2)).
//
// The image is measured against the edge's located points S(locate(edge(t))), its projection onto the
// surface, not the edge itself: files keep edges within a tolerance of their faces (linkrods.step's by up
// to 1e-4 mm), and a fit measured against the edge would use that slack to wander off the projection.
//
// Refuses (GeometryError): non-finite or out-of-domain input, tolerance <= 0, t0 == t1, an edge that is
// not a valid 3D curve; `start_uv` or a located point farther than `off_surface_limit` (at least
// `tolerance`; 0: `tolerance`) from its edge point ("the
// edge does not lie on the surface: D from it at parameter t"); a fit still outside the tolerance when
// kMaxTrimCurveSamples samples are reached, or where a failing interval is shorter than 2^-40 in s (the
// image jumps: a seam placed wrongly) ("trim curve does not follow its edge within T after N
// samples: D at parameter t").
//
// `domain`, when given: the surface's parameter domain, which every located point lies in; the curve's
// control points are moved into it (the curve lies in their hull, so it stays on the surface) if the
// curve's image then stays within 4 x tolerance at every checked point (the result's max_distance says
// how far). An interpolant near the domain's edge overshoots it by a little (KiCad's QFP fillets: by
// 6e-5 of the domain, across a boundary edge the loop then crosses); clamped, it touches that edge.
TrimCurveFit fit_trim_curve(const NurbsCurve& edge, double t0, double t1, const Eigen::Vector2d& start_uv,
                            const LocateOnSurface& locate, const SurfaceAt& surface_at, double tolerance,
                            double off_surface_limit = 0,
                            const std::optional<Eigen::AlignedBox2d>& domain = std::nullopt);

}  // namespace cadnurbs
