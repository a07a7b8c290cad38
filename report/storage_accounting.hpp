#pragma once
// Storage as the thesis counts it (seed 001, §6.1), so that our figures and its figures are the same
// kind of number:
//  - NURBS: 4 floats per control point (x, y, z, w; a polynomial net counts its w too) + 1 per knot;
//    trimming curves apart: 3 floats per 2D control point (u, v, w) + 1 per knot, 2 per polyline point.
//    Exact planar polygons (the compact writer's form of flat faces) apart again: 3 floats per vertex
//    and one integer per polygon corner.
//  - Triangle mesh at a deviation D: indexed = 3 floats per (welded) vertex + 3 integers per triangle,
//    with normals 3 floats more per vertex; STL's triangle soup = 9 floats per triangle, 12 with the
//    facet normal. (The thesis's 9,216 floats for its 1 mm mesh are 3 per vertex.)
//  - NURSS (analysis/nurss): the control net's 4 floats per point + one knot interval per outgoing
//    edge; connectivity as integers, counted apart.
// Shapes are counted as they stand in the scene: a part placed twice by USE counts twice, since a
// Scene holds no sharing (the written file's bytes show what sharing saves).
#include "core/scene.hpp"

namespace cadnurbs {

struct NurbsStorage {
  long surfaces = 0, control_points = 0, knots = 0;
  long floats = 0;  // 4 * control_points + knots (surfaces and 3D curves)
  long trim_curves = 0, trim_control_points = 0, trim_knots = 0, trim_polyline_points = 0;
  long trim_floats = 0;  // 3 * trim_control_points + trim_knots + 2 * trim_polyline_points
  long polygon_vertices = 0, polygon_corners = 0;
  long polygon_floats = 0;  // 3 * polygon_vertices (integers: polygon_corners)
  long total_floats() const { return floats + trim_floats + polygon_floats; }
};

struct MeshStorage {
  long vertices = 0, triangles = 0;
  long indexed_floats = 0;               // 3 * vertices
  long indexed_integers = 0;             // 3 * triangles
  long indexed_floats_with_normals = 0;  // 6 * vertices
  long soup_floats = 0;                  // 9 * triangles (STL without its normals)
  long soup_floats_with_normals = 0;     // 12 * triangles (STL as written)
};

// Every TrimmedSurface, NurbsCurve and PolygonMesh shape of `scene` (meshes in the scene are left out:
// they are no NURBS).
NurbsStorage nurbs_storage(const Scene& scene);

// `mesh` as it is: call it on a welded mesh (analysis/mesh/weld_exact) for the indexed figures to mean
// shared vertices.
MeshStorage mesh_storage(const TriangleMesh& mesh);

}  // namespace cadnurbs
