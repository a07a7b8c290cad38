#include "analysis/subdivision_fit/decimate_within_distance.hpp"

#include <cmath>

#include "core/bounding_box.hpp"

namespace cadnurbs {

GuardedDecimation decimate_within_distance(const TriangleMesh& welded, int target_vertices, const std::vector<int>& keep) {
  const double diagonal = welded.positions.empty() ? 0.0 : mesh_bounding_box(welded).diagonal().norm();

  GuardedDecimation out;
  auto run = [&](double guard) {
    ++out.decimations;
    const SubdivisionControlMesh m = decimate_control_mesh(welded, target_vertices, -1, nullptr, keep, guard);
    return TriangleMesh{m.positions, m.triangles, {}};
  };
  auto reached = [&](const TriangleMesh& m) { return static_cast<int>(m.positions.size()) <= target_vertices; };

  double guard = 1e-3 * diagonal;
  TriangleMesh mesh = run(guard);  // refuses a target below 4 or a mesh without triangles
  while (!reached(mesh) && guard < diagonal / 4) mesh = run(guard *= 2);
  if (!reached(mesh)) {
    out.mesh = run(0);
    return out;
  }
  if (out.decimations > 1) {
    double failed = guard / 2;  // the last guard that stopped short
    for (int i = 0; i < 3; ++i) {
      const double middle = std::sqrt(failed * guard);
      TriangleMesh m = run(middle);
      if (reached(m)) {
        guard = middle;
        mesh = std::move(m);
      } else {
        failed = middle;
      }
    }
  }
  out.mesh = std::move(mesh);
  out.guard = guard;
  return out;
}

}  // namespace cadnurbs
