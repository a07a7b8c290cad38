#include "analysis/nurss/nurss_storage.hpp"

namespace cadnurbs {

NurssStorage nurss_storage(const NurssMesh& mesh) {
  NurssStorage s;
  s.control_points = mesh.vertex_count();
  s.faces = mesh.face_count();
  s.edges = mesh.edge_count();
  s.knot_intervals = 2 * s.edges;
  s.floats = 4 * s.control_points + s.knot_intervals;
  for (int f = 0; f < mesh.face_count(); ++f)
    s.connectivity_integers += static_cast<long>(mesh.corners(NurssFaceId(f)).size()) + 1;
  return s;
}

}  // namespace cadnurbs
