#pragma once
// A scene with every shape moved into world coordinates, so that geometry in different nodes can be
// compared point for point (sewing faces that a writer placed with Transform + USE).
//
// In:  any scene.
// Out: the same tree (names, colours, order) with every node transform the identity and every shape's
//      geometry mapped by its world transform: control points, polygon and mesh positions by the affine
//      map, mesh normals by its inverse transpose (re-normalised). Exact for NURBS: a rational curve or
//      surface maps affinely by mapping its Euclidean control points with the weights kept.
#include "core/scene.hpp"

namespace cadnurbs {

Scene flatten_transforms(const Scene& scene);

}  // namespace cadnurbs
