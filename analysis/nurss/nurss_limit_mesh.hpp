#pragma once
// Triangle meshes of a NURSS, for the IndexedFaceSet writers and for measure_deviation.
//
// The limit mesh joins face points (nurss_face_point.hpp) after `levels` refinement steps: one vertex per
// face, one polygon per interior vertex (the face points of the faces around it, in the order of its
// V-face, so orientation follows the faces), each quad split along its shorter diagonal, other polygons
// fanned. Where the mesh is a tensor-product net its vertices are exact points of the limit surface (the
// surface at the refined knot grid), so its deviation there is only the chord error of the triangles;
// at extraordinary faces the face point approximates the limit point (better with every level). A
// clamped net's boundary faces have their face points on the boundary curve, so the mesh reaches it.
// Zero knot intervals (clamped ends, double knots, the lids' creases) leave faces of no width whose face
// points coincide or lie on one line: equal face points are one vertex, and triangles of no area
// (twice the area <= 1e-10 x the longest side squared) are left out, so a closed NURSS gives a closed,
// manifold mesh.
#include <vector>

#include "core/nurss_mesh.hpp"
#include "core/triangle_mesh.hpp"

namespace cadnurbs {

struct NurssTriangles {
  TriangleMesh mesh;
  std::vector<int> triangle_labels;  // per triangle: the largest label of the faces it comes from
};

// The face-point mesh of `mesh` as it stands (no refinement). Refuses what validate refuses.
NurssTriangles nurss_face_point_mesh(const NurssMesh& mesh);

// The face-point mesh after `levels` refinement steps (refine_nurss).
NurssTriangles nurss_limit_mesh(const NurssMesh& mesh, int levels);

// The triangles of `triangles` with label `label` and only the vertices they use (e.g. label 0 of the
// capping: the part away from its n-gon faces), for measures that sample every vertex.
TriangleMesh nurss_triangles_with_label(const NurssTriangles& triangles, int label);

// The control mesh itself as triangles (each face fanned from its first corner; positions are the
// vertices'), e.g. to watch the levels converge.
NurssTriangles nurss_control_triangles(const NurssMesh& mesh);

}  // namespace cadnurbs
