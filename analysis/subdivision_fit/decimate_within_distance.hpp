#pragma once
// A quadric decimation to a vertex count that stays as close to its input as that count allows.
// Quadric errors measure the distance of the kept vertices to planes of the input, not of the surface
// made, so a plain quadric decimation closes a cup or a blind bore with a lid in its rim's plane at no
// cost: on the corpus's TR12J_OCC housing at 531 vertices, a lid over the bell's mouth 84 mm from the
// nearest input. A guard on the removed vertices' distance (OpenMesh's ModHausdorffT) forbids that,
// and the smallest guard that still reaches the count is searched for.
#include "analysis/subdivision_fit/decimate_control_mesh.hpp"

namespace cadnurbs {

struct GuardedDecimation {
  TriangleMesh mesh;        // untagged; positions are a subset of the input's
  double guard = 0;         // the distance guard used: no removed input vertex is farther from `mesh`
  int decimations = 0;      // runs of the search
};

// Takes a welded mesh, a target vertex count >= 4 and input vertices to keep. Doubles the guard from
// 1e-3 of the bounding-box diagonal until the decimation (no features kept) reaches the target, then
// halves the last interval three times (geometric means), and returns the mesh at the smallest guard
// that reached it: within 2^(1/8) = 1.09 of the smallest such guard of that form, in about
// log2(guard / 1e-3 diagonal) + 4 decimations. When no guard up to a quarter of the diagonal reaches
// the target (kept vertices stop it, or the guard's own refusals: on the corpus's tray at 50 vertices
// even a guard of twice the diagonal stopped at 69), returns the decimation without a guard (guard 0).
// Refuses what decimate_control_mesh refuses.
GuardedDecimation decimate_within_distance(const TriangleMesh& welded, int target_vertices, const std::vector<int>& keep = {});

}  // namespace cadnurbs
