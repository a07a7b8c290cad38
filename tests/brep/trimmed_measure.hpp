#pragma once
// Area and enclosed volume of trimmed NURBS surfaces, integrated from the core model alone (no OCCT): the
// trimmed (u, v) domain, its loops sampled as polygons, triangulated with CGAL together with an interior
// grid (analysis/mesh/triangulate_polygon, even-odd rule); |Su x Sv| and P . (Su x Sv) / 3 integrated over each
// triangle by a 7-point Gauss rule; the slivers between the polygon and the curved trims added back
// (their area by Green's theorem, weighted by the integrand on the curve).
#include <Eigen/Geometry>

#include "core/scene.hpp"

namespace cadnurbs::test {

struct SurfaceMeasure {
  double area = 0;
  // (1/3) integral of P . n dA with n = Su x Sv / |Su x Sv|: summed over a closed surface whose normals
  // point outward, the enclosed volume (positive).
  double volume = 0;
};

// One trimmed surface placed by `world`.
SurfaceMeasure measure_trimmed_surface(const TrimmedSurface& surface, const Eigen::Affine3d& world);

// One mesh placed by `world` (triangles counter-clockwise seen from outside).
SurfaceMeasure measure_mesh(const TriangleMesh& mesh, const Eigen::Affine3d& world);

// Trimming loop `loop` of `surface` follows the VRML/X3D rule when the kept region (even-odd over all
// loops) lies to its left: probed just left and right of several of its polygon edges.
bool region_left_of_loop(const TrimmedSurface& surface, size_t loop);

}  // namespace cadnurbs::test
