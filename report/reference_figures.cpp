#include "report/reference_figures.hpp"

namespace cadnurbs {

const std::vector<ReferenceFigure>& reference_figures() {
  static const std::vector<ReferenceFigure> figures = {
      {"seed 001 (thesis), §6.1", "90° handrail capping", "NURBS: 591 control points (x, y, z, w) + 104 knots", "2,468 floats"},
      {"seed 001 (thesis), §6.1", "90° handrail capping", "NURSS: same net + one value per outgoing edge", "4,728 floats + connectivity"},
      {"seed 001 (thesis), §6.1", "90° handrail capping", "triangle mesh within 1 mm", "9,216 floats"},
      {"seed 000, Table 2", "tool-made sphere (general NURBS)", "IndexedFaceSet (6.8K polygons) / NURBS file", "66 KB / 7 KB"},
      {"seed 000, Table 2", "Knight NURBS avatar", "IndexedFaceSet (40K polygons) / NURBS file", "2 MB / 200 KB"},
  };
  return figures;
}

}  // namespace cadnurbs
