#include "analysis/subdivision/refinement.hpp"

#include <cmath>

namespace cadnurbs {

double valence_beta(int n) {
  const double c = 3.0 / 8.0 + std::cos(2.0 * M_PI / n) / 4.0;
  return (5.0 / 8.0 - c * c) / n;
}

void append_vertex_rule(const ControlMeshEdges& edges, int v, const VertexWeights& rule,
                        std::vector<Eigen::Triplet<double>>& weights) {
  const auto& at = edges.vertex_edges[v];
  switch (edges.vertex_kind[v]) {
    case ControlVertexKind::corner:
      weights.emplace_back(v, v, 1.0);
      break;
    case ControlVertexKind::crease:
      weights.emplace_back(v, v, rule.crease_centre);
      for (const int e : at)
        if (edges.sharp[e]) weights.emplace_back(v, other_end(edges, e, v), rule.crease_neighbour);
      break;
    case ControlVertexKind::smooth:
    case ControlVertexKind::dart: {
      const int n = static_cast<int>(at.size());
      const double w = rule.smooth_neighbour(n);
      weights.emplace_back(v, v, 1.0 - n * w);
      for (const int e : at) weights.emplace_back(v, other_end(edges, e, v), w);
      break;
    }
  }
}

SubdivisionRefinement refine_control_mesh(const ControlMeshTopology& coarse) {
  const ControlMeshEdges edges = control_mesh_edges(coarse);
  const int nv = coarse.vertex_count, ne = static_cast<int>(edges.ends.size());
  SubdivisionRefinement out;
  out.fine.vertex_count = nv + ne;

  using Triplet = Eigen::Triplet<double>;
  std::vector<Triplet> weights;
  weights.reserve(static_cast<size_t>(nv) * 7 + static_cast<size_t>(ne) * 4);
  const VertexWeights rule{0.75, 0.125, valence_beta};
  for (int v = 0; v < nv; ++v) append_vertex_rule(edges, v, rule, weights);
  for (int e = 0; e < ne; ++e) {
    const int row = nv + e;
    const auto [a, b] = edges.ends[e];
    if (edges.sharp[e]) {
      weights.emplace_back(row, a, 0.5);
      weights.emplace_back(row, b, 0.5);
    } else {
      weights.emplace_back(row, a, 0.375);
      weights.emplace_back(row, b, 0.375);
      weights.emplace_back(row, edges.opposite[e][0], 0.125);
      weights.emplace_back(row, edges.opposite[e][1], 0.125);
    }
  }
  out.stencils.resize(out.fine.vertex_count, nv);
  out.stencils.setFromTriplets(weights.begin(), weights.end());

  out.fine.triangles.reserve(coarse.triangles.size() * 4);
  for (size_t t = 0; t < coarse.triangles.size(); ++t) {
    const auto [a, b, c] = coarse.triangles[t];
    const auto& te = edges.triangle_edges[t];
    const int m0 = nv + te[0], m1 = nv + te[1], m2 = nv + te[2];
    out.fine.triangles.push_back({a, m0, m2});
    out.fine.triangles.push_back({m0, b, m1});
    out.fine.triangles.push_back({m2, m1, c});
    out.fine.triangles.push_back({m0, m1, m2});
  }
  // Tagged creases: each edge tagged at this level (found by its ends) passes its tag to both halves.
  for (int e = 0; e < ne; ++e) {
    if (!edges.sharp[e] || edges.face_count[e] != 2) continue;  // boundary/non-manifold stay sharp anyway
    const int m = nv + e;
    const auto [a, b] = edges.ends[e];
    out.fine.crease_edges.push_back({a, m});
    out.fine.crease_edges.push_back({b, m});
  }
  out.fine.corner_vertices = coarse.corner_vertices;
  return out;
}

}  // namespace cadnurbs
