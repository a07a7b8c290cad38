#pragma once
// One step of Loop subdivision with sharp features (Loop 1987; crease, corner and dart rules of
// Hoppe et al. 1994, section 3.2; seed 001, Fig. 2.10), as a linear map from the coarse vertices to
// the fine ones. Refinement is topology plus stencils; positions are applied by the caller, so a
// fitting can differentiate through it (the map does not depend on positions).
#include <Eigen/SparseCore>

#include "analysis/subdivision/control_mesh_edges.hpp"

namespace cadnurbs {

// Rows: fine vertices; columns: coarse vertices; each row sums to 1.
using LimitStencils = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct SubdivisionRefinement {
  ControlMeshTopology fine;     // the coarse vertices keep their numbers; edge e's new vertex is vertex_count + e
  LimitStencils stencils;
};

// Takes one level's topology; returns the next level. Triangle t = (a, b, c) with new edge vertices
// m0 (a-b), m1 (b-c), m2 (c-a) becomes triangles 4t..4t+3 = (a, m0, m2), (m0, b, m1), (m2, m1, c),
// (m0, m1, m2), so triangle T of level k lies in control triangle T >> 2k. Tagged creases split in
// two tagged halves, tagged corners stay tagged; boundary and non-manifold edges stay sharp by
// themselves.
// Rules (n = edges at the vertex, beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n, Loop's):
// - smooth edge (two faces, untagged): 3/8 each end, 1/8 each opposite vertex; sharp edge: 1/2, 1/2;
// - smooth or dart vertex: 1 - n beta itself, beta each neighbour; crease vertex: 3/4 itself, 1/8 each
//   neighbour along a sharp edge (so a crease refines as a uniform cubic B-spline of its vertices,
//   independently of the faces beside it); corner: itself.
// Refuses what control_mesh_edges refuses.
SubdivisionRefinement refine_control_mesh(const ControlMeshTopology& coarse);

// Loop's beta for a vertex with n edges (n >= 1).
double valence_beta(int n);

// A vertex rule's weights, the shape refinement and limit masks share: a crease vertex keeps
// `crease_centre` and gives `crease_neighbour` to each neighbour along a sharp edge; a smooth or dart
// vertex with n edges gives `smooth_neighbour(n)` to each neighbour and keeps the rest; a corner
// keeps everything.
struct VertexWeights {
  double crease_centre, crease_neighbour;
  double (*smooth_neighbour)(int n);
};

// Appends vertex v's rule to `weights` as row v (the vertex keeps its number at the next level).
void append_vertex_rule(const ControlMeshEdges& edges, int v, const VertexWeights& rule,
                        std::vector<Eigen::Triplet<double>>& weights);

}  // namespace cadnurbs
