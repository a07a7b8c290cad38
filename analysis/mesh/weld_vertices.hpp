#pragma once
// Welding by distance: the vertices of a triangle soup (an STL file's three corners per triangle)
// that lie within a tolerance of each other become one vertex, so that the mesh gets connectivity.
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

// What weld_vertices did.
struct WeldReport {
  int input_vertices = 0;
  int vertex_classes = 0;           // groups of merged vertices (counting those only dropped triangles used)
  int output_vertices = 0;          // classes used by a kept triangle
  int collapsed_triangles = 0;      // dropped: two or three corners in one class
  int zero_area_triangles = 0;      // dropped: three distinct corners, but exactly collinear
  double largest_merge_distance = 0;  // farthest a vertex was moved (chains make this exceed the tolerance)
};

// 1e-6 of the diagonal of the mesh's bounding box (0 for an empty mesh or one point): small enough to
// keep apart any two vertices a modeller meant to be distinct, large enough to join corners that an
// exporter wrote with float32 round-off (about 6e-8 of the coordinates' magnitude).
double default_weld_tolerance(const TriangleMesh& mesh);

// Takes a mesh and a tolerance >= 0; returns the mesh with every pair of vertices at distance
// <= tolerance in one vertex. Exact: every such pair is found, none is missed at a cell border
// (the points are sorted into cubes at least `tolerance` wide by a radix sort and each cube is compared
// with the 26 around it, in one sweep). A soup (more vertices than triangles, as an STL file read without
// merge_equal_points) has its bitwise-equal vertices numbered first, so that the sweep sees each point
// once; the result is the same either way. O(n) expected for the n vertices, unless very many crowd
// within one tolerance.
// - The merge is transitive: a chain a-b-c with a, b and b, c within the tolerance is one vertex even
//   when a, c are not. This is the usual choice because any other leaves the result depending on the
//   vertex order (which of b's neighbours wins), and a chain in a real part means the tolerance is
//   larger than its features anyway; WeldReport::largest_merge_distance shows when it happened.
// - A merged vertex sits at the position of its first vertex in input order (not an average, so
//   exact duplicates keep their exact coordinates); output vertices are in order of first use.
// - Triangles with two corners in one class, or with exactly zero area afterwards, are dropped and
//   counted; the others keep their order and corner order. Corner normals follow their triangles.
// - Vertices that no kept triangle uses are dropped.
// Refuses (std::invalid_argument) a negative or non-finite tolerance; validate()s the mesh.
TriangleMesh weld_vertices(const TriangleMesh& mesh, double tolerance, WeldReport* report = nullptr);
// The same result, made in the buffers of a mesh the caller is done with (no second copy of the
// triangles, nor of the positions when they need no reordering): less memory and fewer fresh pages.
TriangleMesh weld_vertices(TriangleMesh&& mesh, double tolerance, WeldReport* report = nullptr);

}  // namespace cadnurbs
