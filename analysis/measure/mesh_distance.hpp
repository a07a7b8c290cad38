#pragma once
// Two-sided distance between two triangle meshes (e.g. our tessellation and OCCT's BRepMesh of the same
// part): points sampled on each mesh (sample_triangles) to the nearest point of the other (CGAL AABB
// tree of its triangles). The maxima are attained sample distances: a measure, not a bound. The RMS
// is a surface integral, each sample weighted by the area it stands for (as Metro, Cignoni et al.
// 1998, samples by area): sqrt(integral of d^2 / area) on each side, and overall both sides'
// integrals over both areas. Pooled by count instead, a mesh of large triangles was undercounted
// (the lattice stops at 2,145 points a triangle) and one of small ones overcounted (7 at least).
#include "analysis/measure/measure_deviation.hpp"

namespace cadnurbs {

struct MeshDistance {
  DeviationStats a_to_b, b_to_a, overall;
};

// spacing 0: a third of the smaller of the two meshes' mean edge lengths. Refuses (GeometryError) a
// mesh without non-degenerate triangles.
MeshDistance mesh_distance(const TriangleMesh& a, const TriangleMesh& b, double spacing = 0);

}  // namespace cadnurbs
