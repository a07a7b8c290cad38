#pragma once
// A CoordinateDeformer (the VRML97 NURBS proposal's free-form deformation node) evaluated at rest.
//
// Source of the node's definition: the blaxxun/Bitmanagement "NURBS Extension for VRML97" node reference
// (bitmanagement.de/developer/contact/nurbs/spec/nodes.htm) and white_dune's CoordinateDeformerPROTO.wrl
// and NodeCoordinateDeformer.cpp agree on the fields and defaults: children; uDimension, vDimension,
// wDimension (0); uKnot, vKnot, wKnot ([]); uOrder, vOrder, wOrder (2); controlPoint, weight; inputCoord,
// inputTransform, outputCoord (MFNode); bboxCenter, bboxSize. white_dune reads the node and draws
// nothing for it; X_ITE does not know it (it is not X3D). The prose of the reference that says how
// points enter the volume could not be read here (only its field table was), so the mapping below is
// our reading, the classic trivariate free-form deformation, stated so that it can be checked:
//   - The volume is the tensor-product NURBS of uDimension x vDimension x wDimension control points,
//     index i + j*uDimension + k*uDimension*vDimension (u fastest, as NurbsSurface orders its points),
//     knot vectors of dimension + order values each, weights empty (all 1) or one per point > 0; its
//     control points follow the same convention as the file's surfaces (w·P by default, see
//     nodes_to_geometry.hpp).
//   - A coordinate (x, y, z) in the deformer's own coordinate system is the parameter (u, v, w) = (x, y, z)
//     and moves to the volume's point there. Inside the knot domain [knot[order-1], knot[dimension]] of
//     each direction this is the NURBS volume; outside, the end spans' polynomials continue (so a volume
//     whose control points sit at their Greville abscissae, e.g. a linear grid, is the identity
//     everywhere, and an affine map of those points is that affine map everywhere).
//   - The coordinates moved are those of the geometry under its children, taken into the deformer's
//     coordinate system through the Transforms between (and back after). inputCoord / outputCoord /
//     inputTransform (which route coordinates elsewhere through the deformer) are not evaluated: the
//     reader says so in one line.
//   - NURBS geometry under it: its control points are deformed, not its surface. That is exact for the
//     control net only: the result is the NURBS of the deformed net, which equals the deformed surface
//     when the volume is affine (B-splines commute with affine maps) and otherwise differs from it by as
//     much as the volume bends between control points; it keeps the geometry NURBS (the converter's
//     output form) at its own size, where tessellating first would turn every surface into a mesh at a
//     chosen deviation. Meshes: their vertices are deformed exactly; per-corner normals are dropped
//     (they no longer hold), and exact planar polygons become triangles (they are no longer planar).
#include <Eigen/Core>
#include <array>
#include <vector>

#include "core/scene.hpp"
#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

struct NurbsVolume {
  std::array<int, 3> orders{2, 2, 2};
  std::array<int, 3> counts{0, 0, 0};
  std::array<std::vector<double>, 3> knots;
  std::vector<Eigen::Vector3d> points;  // Euclidean, counts[0] * counts[1] * counts[2], u fastest
  std::vector<double> weights;          // empty, or one > 0 per point
};

// The volume of a CoordinateDeformer node; `homogeneous`: controlPoint holds w·P. Throws
// std::invalid_argument "<reason>" when the fields do not make a valid volume (counts, orders, knots,
// weights).
NurbsVolume coordinate_deformer_volume(const Node& deformer, bool homogeneous);

// The volume's point at parameter (u, v, w) = `parameter` (outside the domain: the end spans continued).
Eigen::Vector3d volume_point(const NurbsVolume& volume, const Eigen::Vector3d& parameter);

// Every coordinate p of `geometry` moved to `to_deformer^-1 * volume_point(volume, to_deformer * p)`:
// `to_deformer` takes the geometry's coordinates into the deformer's system.
void deform_geometry(Geometry& geometry, const NurbsVolume& volume, const Eigen::Affine3d& to_deformer);

}  // namespace cadnurbs
