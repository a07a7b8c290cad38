#pragma once
// A Loop surface within a given distance of a mesh, with few control vertices: decimate, fit, and
// where the fit stays too far keep more of the input's vertices and do it again.
#include "analysis/subdivision_fit/decimate_control_mesh.hpp"
#include "analysis/subdivision_fit/fit_subdivision_surface.hpp"

namespace cadnurbs {

// Rounds are bounded: each costs a decimation and a fit, and a round that adds a handful of vertices
// would otherwise be followed by as many more as the input has vertices.
constexpr int kMaxToleranceRounds = 8;

struct ToleranceFitReport {
  int rounds = 0;          // decimate-and-fit rounds
  bool met = false;        // the last fit is within the tolerance at its samples
  DecimationReport decimation;  // the last round's
  SubdivisionFitReport fit;            // the last round's
};

// Takes a welded mesh, the first round's vertex count, the sharp angle (as decimate_control_mesh) and
// a tolerance > 0. Each round decimates the input with every vertex kept that an earlier round found
// farther than the tolerance (fit_subdivision_surface's input_vertex_distance) and the count raised by as many
// (by an eighth at least), and fits; it stops when the fit is within the tolerance, when no new vertex
// is far, when the count would reach the input's, or after kMaxToleranceRounds rounds. Adding whole input vertices where the error is, and re-decimating
// around them, keeps the control mesh as well shaped as the first (splitting control edges in place
// made slivers that the fit could not use).
// Refuses (std::invalid_argument) a tolerance that is not positive, and what the two steps refuse.
SubdivisionControlMesh fit_to_tolerance(const TriangleMesh& welded, int start_vertices, double sharp_angle_radians,
                                      double tolerance, const SubdivisionFitOptions& options, ToleranceFitReport* report);

}  // namespace cadnurbs
