#pragma once
// What a NURSS control mesh costs, counted the thesis's way (seed 001 §6.1; report/storage_accounting.hpp
// for the NURBS and mesh figures): 4 floats per control point (x, y, z, w; w counted also when 1) and one
// knot interval per outgoing edge, i.e. two per edge (each end holds its own, nurss_mesh.hpp); the
// connectivity apart, as integers: every face's corner indices plus one end-of-face marker (the
// IndexedFaceSet coordIndex form). Intervals written in the faces' corner order need no further index.
#include "core/nurss_mesh.hpp"

namespace cadnurbs {

struct NurssStorage {
  long control_points = 0, faces = 0, edges = 0;
  long knot_intervals = 0;         // 2 * edges
  long floats = 0;                 // 4 * control_points + knot_intervals
  long connectivity_integers = 0;  // Σ (corners + 1) over the faces
};

NurssStorage nurss_storage(const NurssMesh& mesh);

}  // namespace cadnurbs
