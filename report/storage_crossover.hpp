#pragma once
// "When do NURBS pay?": the maximum deviation D below which a mesh costs more bytes than the NURBS.
// A mesh within D needs about C/D triangles on curved faces (the chord error falls with the square of the
// triangle size, in two directions), so bytes against D are close to a straight line in log-log; between
// two measured points the crossing is interpolated on that line.
#include <optional>
#include <vector>

namespace cadnurbs {

struct BytesAtDeviation {
  double deviation = 0;  // D > 0
  double bytes = 0;      // > 0
};

struct Crossover {
  // The D where the mesh's bytes equal `nurbs_bytes`; empty when the measured points do not cross.
  std::optional<double> deviation;
  // When they do not cross: true if the mesh was larger at every measured D (NURBS pay everywhere),
  // false if smaller at every measured D.
  bool mesh_larger_everywhere = false;
};

// `mesh` in any order (sorted here by decreasing D). Refuses nothing: an empty `mesh` gives no crossing
// and mesh_larger_everywhere false.
Crossover storage_crossover(std::vector<BytesAtDeviation> mesh, double nurbs_bytes);

}  // namespace cadnurbs
