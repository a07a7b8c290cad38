#pragma once
// Triangle soups as an STL file holds them (three own vertices per triangle, facet normals as corner
// normals), for the weld and crease-normal tests.
#include "core/triangle_mesh.hpp"

namespace cadnurbs::test {

// The cube [-size/2, size/2]^3: 12 triangles, 36 vertices, outward counter-clockwise.
TriangleMesh stl_cube(double size);

// A closed cylinder about Z, radius r, z from 0 to height: `segments` side quads (two triangles each)
// and two caps fanned from their centres; 4 * segments triangles, outward counter-clockwise.
TriangleMesh stl_cylinder(double r, double height, int segments);

}  // namespace cadnurbs::test
