#pragma once
// Compares a scene read back with the one written, within the tolerances the writer states
// (nurbs_tolerances.hpp, scene_to_nodes.hpp), reporting every difference through GoogleTest.
#include "core/scene.hpp"
#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs::vrml_test {

// Tree, names, colours, transforms (as maps of points), and for each geometry every control point,
// weight and knot, plus sampled evaluated points.
void expect_same_scene(const Scene& written, const Scene& read, const VrmlWriteOptions& options);

}  // namespace cadnurbs::vrml_test
