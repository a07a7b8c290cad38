#pragma once
// What a face tells viewers that tessellate NURBS on a uniform grid (X3D/VRML uTessellation,
// vTessellation, NurbsCurve2D tessellation): counts, 0 where the viewer's default will do.
// analysis/tessellation/plan_tessellation_hints computes them for a deviation; the VRML/X3D writers
// write them.
#include <vector>

namespace cadnurbs {

struct TessellationHints {
  int u = 0, v = 0;
  std::vector<std::vector<int>> trim_segments;  // per loop, per segment; 0 for polylines
};

}  // namespace cadnurbs
