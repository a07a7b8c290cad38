#pragma once
// Whether a face's mesh covers the face once: its area against the trimmed NURBS area, allowing what a
// mesh within D of the face may differ by anyway.
//
// In:  a trimmed surface, its mesh (tessellate_to_deviation at D), and D.
// Out: both areas and the allowance max(0.1 % of the area (0.5 % under 1 unit^2), D x (L + k A)), L the
//      mesh's boundary length, k the largest principal curvature sampled over the surface, A the area.
//      Why: every boundary chord lies within D of its trimming curve, so the strips between chords and
//      curves hold at most D x L; inside, flat triangles within D of a surface curved by k differ from it
//      by about D k per unit area (a cylinder of radius r loses D/3r). A difference beyond the allowance
//      means the mesh covers part of the face twice, or tilts away from it (long triangles across a
//      twisted surface), which the deviation certificate cannot see.
// The exact area costs 1.5-20 times the meshing (trimmed_surface_area, relative tolerance 1e-7).
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

struct FaceAreaCheck {
  double area = 0;            // of the trimmed surface
  double mesh_area = 0;
  double relative_limit = 0;  // 0.001, or 0.005 for faces under 1 unit^2
  double allowance = 0;       // max(relative_limit x area, D x (boundary length + curvature x area))
  bool beyond() const { return mesh_area - area > allowance || area - mesh_area > allowance; }
};

// The largest |principal curvature| over a grid of the surface's domain (trims ignored: an upper value
// for the trimmed face), poles skipped.
double largest_curvature(const NurbsSurface& surface);

FaceAreaCheck check_face_area(const TrimmedSurface& face, const TriangleMesh& mesh, double max_deviation);

// The same for every face of `exact` whose mesh is in `meshed`, the same tree (as tessellate_to_deviation
// returns it), in scene order.
struct SceneFaceAreaCheck {
  const Shape* face;  // in `exact`
  FaceAreaCheck check;
};
std::vector<SceneFaceAreaCheck> check_face_areas(const Scene& exact, const Scene& meshed, double max_deviation);

}  // namespace cadnurbs
