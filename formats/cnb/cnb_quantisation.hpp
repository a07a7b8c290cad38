#pragma once
// The .cnb quantisation steps, chosen as the coarsest whose bound keeps the decoded geometry within D.
//
// Control points: one grid of step q per scene, each coordinate rounded to the nearest multiple. A point
// moves by at most q·√3/2. Knots are kept exactly and weights exactly, so every surface and curve point
// is the same convex combination (same basis functions, same weights) of the moved control points as it
// was of the originals, and so moves by at most the largest control point move (the convex-hull
// property). Mesh vertices move by the same. In world coordinates the move is scaled by the largest
// singular value of the shape's world transform, so q = 2·(1 - trim_share)·D / (√3·largest scale).
// (A traversal-coded mesh's vertex may be written at another grid point within the same bound where that
// codes cheaper: CodingState::free_radius.)
// (D here and below is max_deviation·quantisation_scale: a writer asked to move boundaries less.)
//
// Trimming curves: per face a grid of step s = 2^e in (u,v). A trim point moves by at most s per
// coordinate (s/2 rounding, plus up to s/2 where a segment's start is snapped onto the previous end so
// that loops stay closed). With L = surface_derivative_bound (|∂S/∂u|, |∂S/∂v| <= L), the image of the
// trim on the (original) surface moves by at most L·(|Δu| + |Δv|) <= 2·L·s; e is the largest exponent
// with 2·L·s·scale <= trim_share·D. On the decoded surface the boundary moves by at most the sum of the
// two bounds, <= D.
#include <optional>

#include "core/scene.hpp"
#include "core/world_scale.hpp"
#include "formats/cnb/cnb_numbers.hpp"
#include "formats/cnb/cnb_options.hpp"

namespace cadnurbs::cnb {

// q as above. Throws std::invalid_argument for D, trim_share or quantisation_scale out of range.
double point_step(const Scene& scene, const CnbOptions& options);
// The points' share of D, (1 - trim_share)·quantisation_scale·D: the world move no point may exceed.
double point_share(const CnbOptions& options);

// The largest world move of a control point or vertex of `scene` on the grid of step q: each coordinate
// decodes as round(x/q)·q (the writer's on_grid), and each move is taken through its shape's world
// transform, as decoded. It bounds the points' move as q·√3/2·scale does, with no worst case: where a step
// coarser than point_step leaves every point this close, the convex-hull argument above holds with this
// figure (on KiCad parts drawn on decimal dimensions, a box's corners may not move at all).
double largest_point_move(const Scene& scene, double q);

// The grid points of step q (in each point's own node's coordinates) that two or more of the scene's
// control points and vertices round to, sorted. A writer that may move a vertex to another grid point
// within the bound (CodingState::free_radius) keeps these where rounding puts them: shared positions
// (a vertex of two meshes, a mesh's repeated vertex) must decode alike, or the part cracks there.
std::vector<std::array<int64_t, 3>> shared_grid_points(const Scene& scene, double q);

// How many triangles and polygons of the scene's meshes have two corners on one grid point of step q
// (their decoded face collapses). A caller choosing a coarser step takes none that collapses more than
// point_step does.
long collapsed_faces(const Scene& scene, double q);

// The largest step not above `largest` that divides 1/100 of the scene's unit or is a whole multiple of
// it: 0.01·m or 0.01/n. Parts drawn on decimal dimensions (a pitch of 0.5 or 2.54 mm) then place repeated
// pins whole steps apart, so that pins rounded to the grid stay copies of each other (cnb_mesh_copies.hpp);
// on an arbitrary step, rounding moves one pin's vertices differently from another's. The step is at
// most 2x finer than `largest` (for `largest` in [0.005, 0.01)), and closer the further it is from there.
double decimal_step(double largest);

// e as above, for a face whose world transform scales by at most `world_scale`; clamped to [-100, 100].
// A surface with L = 0 (a point) gets 1/1024 of its domain.
int trim_step_exponent(const NurbsSurface& surface, const CnbOptions& options, double world_scale);

// e, lowered where needed so that every loop spans at least loop_steps steps in each direction (the
// smallest extent of its control points' box, loops of no extent aside): a loop much smaller than the
// step the bound allows would otherwise decode collapsed (no area, the face lost on reading). A finer
// grid only tightens the bound.
constexpr double loop_steps = 64;
int trim_step_exponent_keeping_loops(const std::vector<TrimLoop>& loops, int exponent);

// The world bound 2·L·2^e·scale of that choice.
double trim_bound(const NurbsSurface& surface, int exponent, double world_scale);

// Trimming curves' spare knots. The grid 2^e, a power of two, leaves part of the trims' world budget
// unused: slack = budget - 2·L·2^e·scale. In it the NURBS trimming curves lose the knots their shape does
// not need (core/knot_removal): each curve moves by at most t in (u,v), so its image on the surface by at
// most L·(|Δu| + |Δv|) <= √2·L·t, and t = slack / (√2·L·scale) keeps that within the slack. Pcurves that a
// kernel approximated carry many knots, none a short decimal (a Fastron 77A inductor's windings: 670
// knots written as float64s at D = 0.01 mm). Ends stay where they were (interior knots only), so loops stay
// closed; the writer then takes the grid again for the new loops, never coarser than before.
// A polynomial curve is also refit as a cubic within t (core/refit_cubic_within: its image within t of
// the old one both ways, its ends kept bit for bit, its parametrisation not), and each curve keeps
// whichever of the two has fewer control points: the DTMB bow's degree-8 boundary, 313 control points in
// 40 float64-knotted spans, takes 54 on whole-number knots at 1e-3 of the part's diagonal.
// has_spare_knot_candidates: the curve has interior knots.
// `removed` (may be null) receives the number of knots fewer. Returns the loops as they are for t <= 0.
bool has_spare_knot_candidates(const NurbsCurve& curve);
double spare_trim_tolerance(const NurbsSurface& surface, double slack, double world_scale);
std::vector<TrimLoop> trims_with_fewer_knots(const std::vector<TrimLoop>& loops, double uv_tolerance,
                                             long* removed = nullptr);

// Weights: kept exactly, except on a rational surface with more than `exact_weight_limit` distinct
// weights (a table would cost 8 bytes each). There each weight is rounded to 2^(n·h), a relative error
// of at most ε = 2^(h/2) - 1. With the control points fixed, S' - S = Σ N_i (w'_i - w_i)(P_i - S) /
// Σ N_i w'_i, so |S' - S| <= ε/(1 - ε) · max |P_i - S| <= ε/(1 - ε) · (diagonal of the net's box); the
// moved points add their own bound on top (convex hull, as above). Such a face gives half its trim share
// to the weights and half to its trims.
// A surface whose weights are an outer product (weight_factors) writes the two factors instead (format
// version 6 on), whatever their number of distinct values; their products are off by a relative ε of
// 1e-12 to 1e-6 (rounded cos(θ/2) values), and the same bound, with that ε, is added to the face's.
constexpr size_t exact_weight_limit = 4;
bool quantises_weights(const NurbsSurface& surface);
// h for a world budget `budget`, and the world bound ε/(1 - ε)·diagonal·scale that h gives.
double weight_log_step(const NurbsSurface& surface, double budget, double world_scale);
double weight_bound(const NurbsSurface& surface, double log_step, double world_scale);

// How a trimmed surface's weights are written, and what they take of its trims' world budget
// `trim_budget` (trim_share·D·quantisation_scale): factors where they are off by at most 1e-4 (weights
// written to 7 digits, as our .x3dv) and their bound is at most 1/64 of the budget (the trims' grid, a power
// of two below their share, seldom changes), else rounded (quantises_weights: half the budget), else exact.
struct WeightCoding {
  std::optional<WeightFactors> factors;  // mode 3
  double log_step = 0;                   // > 0: mode 2
  double bound = 0;                      // world move of the surface that the weights' coding causes
  double trim_fraction = 1;              // of the budget left to the trims
};
WeightCoding weight_coding(const NurbsSurface& surface, double trim_budget, double world_scale);

}  // namespace cadnurbs::cnb
