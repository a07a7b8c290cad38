#pragma once
// What the .cnb writer is asked for: the largest deviation of the decoded geometry, and how to spend it.
#include <algorithm>
#include <cstddef>

namespace cadnurbs {

struct CnbOptions {
  // D > 0, in scene units, in world coordinates: no decoded point of a surface, trimming boundary, curve
  // or mesh lies farther than D from the original (by the bound stated in docs/cnb.md).
  double max_deviation = 1.0;
  // The part of D that trimming curves may use (their quantisation in (u,v)); control points and mesh
  // vertices get the rest. In (0, 1).
  double trim_share = 0.4;
  // How far the scene's triangle and polygon meshes already lie from the exact part they stand for (a
  // certified tessellation's bound, world units; 0 for meshes that are the part). Meshes are quantised
  // like control points, so their share of the bound is this plus the vertices' move; the caller keeps
  // it within trim_share·D.
  double mesh_deviation = 0.0;
  // In (0, 1]: control points, trims and rounded weights are quantised as for quantisation_scale·D (the
  // meshes' certificate is unchanged). Two faces' boundaries may part by up to twice their move; a reader
  // that has to sew the file (one naming no edges, or holding polygon sets: converters/scene_preparation)
  // does so at D/4, so convert takes the largest scale that leaves its decoded scene as sewn as the scene
  // itself (converters/cnb_coding).
  double quantisation_scale = 1.0;
  // 0: control points and vertices take the coarsest grid whose worst rounding (q·√3/2) stays within their
  // share of D. Else this step (stored as a float32, as the writer's own is), which may be coarser: the
  // points' bound is then their largest move on it as decoded (cnb::largest_point_move), and the writer
  // refuses a step on which that exceeds (1 - trim_share)·quantisation_scale·D.
  double measured_point_step = 0.0;
  // Whether a traversal-coded mesh's vertex may be written at another grid point than its nearest, within
  // the points' bound, where that codes smaller (CodingState::free_radius); false: each at its nearest.
  bool free_mesh_points = true;
  // Whether a traversal-coded mesh's new vertices may each name the cheapest of the vertex predictors
  // (cnb_vertex_predictors.hpp); the writer also writes the file without and keeps the smaller. False: the
  // parallelogram (or the period) predicts every vertex.
  bool vertex_predictors = true;
  // Whether a traversal's symbols take the contexts of the border's shape at the gate and earlier vertices
  // are named by their place along the border (cnb_gate_shape.hpp; format version 9). False: a version 8
  // file.
  bool gate_shapes = true;
  // The entropy stage: the smallest of deflate, the adaptive arithmetic coder with every model starting at
  // ½, the same coder starting from the coder prior (cnb_coder_prior.hpp), and the coder whose models mix
  // two rates of adaptation, from the prior (adaptive_arithmetic_coder.hpp); or one of them.
  enum class Coder { smallest, deflate, arithmetic, arithmetic_prior, arithmetic_two_rates } coder = Coder::smallest;
};

// What the writer chose and what it guarantees.
struct CnbWriteReport {
  double point_step = 0;   // q: the grid of control points and mesh vertices (scene units)
  // Largest world move of a control point or vertex: q·√3/2·(largest world scale), or the move itself
  // where the caller chose the step (CnbOptions::measured_point_step).
  double point_bound = 0;
  // Largest world move, over faces, caused by the trims' own grid plus (faces with quantised weights)
  // the weights' rounding, plus (faces whose trims lost spare knots) the slack the knots took.
  double trim_bound = 0;
  long trim_knots_removed = 0;  // spare knots of trimming curves removed (cnb_quantisation.hpp)
  double mesh_bound = 0;  // options.mesh_deviation when the scene holds a mesh, else 0
  double deviation_bound() const { return point_bound + std::max(trim_bound, mesh_bound); }
  size_t payload_bytes = 0;     // decoded payload
  size_t deflate_bytes = 0;     // the payload deflated (0 when not tried)
  size_t arithmetic_bytes = 0;  // the payload arithmetic-coded from ½ (0 when not tried)
  size_t arithmetic_prior_bytes = 0;  // the payload arithmetic-coded from the coder prior (0 when not tried)
  size_t arithmetic_two_rates_bytes = 0;  // the same with models of two rates (0 when not tried)
  size_t file_bytes = 0;
  int parallelogram_nets = 0, row_nets = 0;  // which predictor each surface's net took
  int quantised_weight_nets = 0;              // surfaces whose weights were rounded (not kept exactly)
  int factored_weight_nets = 0;               // surfaces whose weights were written as two factors
  int mesh_groups = 0;                        // records holding several meshes of a node (kind 6)
  int piece_copies = 0;                       // pieces of a group's meshes coded as copies of others
  int periodic_meshes = 0;                    // traversal-coded meshes whose vertices a period predicts
  // Traversal-coded vertices written at a grid point other than their nearest, within the points' bound,
  // because it codes cheaper against their prediction (the writer tries this where the file holds a mesh).
  long vertices_off_nearest = 0;
  int traversal_meshes = 0;  // traversal-coded meshes (a group's union counts once)
  // Decoded payload bytes by what they hold: control point and vertex residuals, trim point residuals,
  // knots, weights (tables and indices), float64 values (transforms, header, raw knots, weight tables),
  // and the rest (structure, counts, names, indices, mesh symbols and ranks).
  size_t point_bytes = 0, trim_bytes = 0, knot_bytes = 0, weight_bytes = 0, float_bytes = 0, other_bytes = 0;
};

}  // namespace cadnurbs
