#include "analysis/subdivision/limit_surface.hpp"

#include <stdexcept>

namespace cadnurbs {

LimitStencils limit_stencils(const ControlMeshTopology& level) {
  const ControlMeshEdges edges = control_mesh_edges(level);
  const int nv = level.vertex_count;
  std::vector<Eigen::Triplet<double>> weights;
  weights.reserve(static_cast<size_t>(nv) * 7);
  // Loop's limit weight w = 1 / (3 / (8 beta) + n); on creases the cubic B-spline's 2/3, 1/6.
  const VertexWeights rule{2.0 / 3.0, 1.0 / 6.0, [](int n) { return 1.0 / (3.0 / (8.0 * valence_beta(n)) + n); }};
  for (int v = 0; v < nv; ++v) append_vertex_rule(edges, v, rule, weights);
  LimitStencils out(nv, nv);
  out.setFromTriplets(weights.begin(), weights.end());
  return out;
}

SubdivisionLimitMesh subdivision_limit_mesh(const ControlMeshTopology& control, int levels) {
  if (levels < 0 || levels > 8) throw std::invalid_argument("subdivision_limit_mesh: levels must be 0 to 8");
  SubdivisionLimitMesh out;
  out.level = control;
  LimitStencils to_level(control.vertex_count, control.vertex_count);
  to_level.setIdentity();
  for (int k = 0; k < levels; ++k) {
    out.coarser_vertex_count = out.level.vertex_count;
    SubdivisionRefinement step = refine_control_mesh(out.level);
    to_level = (step.stencils * to_level).pruned();
    out.level = std::move(step.fine);
  }
  out.limit_from_control = (limit_stencils(out.level) * to_level).pruned();
  return out;
}

TriangleMesh evaluate_limit_mesh(const SubdivisionLimitMesh& limit, const std::vector<Eigen::Vector3d>& control_points) {
  if (static_cast<long>(control_points.size()) != limit.limit_from_control.cols())
    throw std::invalid_argument("evaluate_limit_mesh: control point count does not match the mesh");
  Eigen::MatrixX3d x(control_points.size(), 3);
  for (size_t i = 0; i < control_points.size(); ++i) x.row(i) = control_points[i].transpose();
  const Eigen::MatrixX3d p = limit.limit_from_control * x;
  TriangleMesh out;
  out.positions.resize(p.rows());
  for (long i = 0; i < p.rows(); ++i) out.positions[i] = p.row(i).transpose();
  out.triangles = limit.level.triangles;
  return out;
}

}  // namespace cadnurbs
