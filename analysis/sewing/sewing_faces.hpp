#pragma once
// The preparation of sew_faces (see its header): the faces it sews, each with its surface and its group
// (internal to analysis/sewing/).
//
// In: the scene in world coordinates (flatten_transforms) and the first tolerance. Out: every polygon of a
// polygon set a planar trimmed surface of its own, every untrimmed surface trimmed by its domain rectangle
// (core's domain_loop), and the trimmed surfaces in scene order with their evaluators and groups.
// Refuses (drops, and counts in SewingReport::dropped_polygons) a polygon that is narrower than the
// tolerance everywhere, a sliver such as a fan triangle over collinear corners of a polygon: it bounds
// nothing and its sides lie on its neighbours', so sewing it would only add pieces that match nothing.
// Polygons that planar_polygon_surface makes no face of (fewer than 3 corners, no area) are dropped and
// counted the same way.
#include <memory>
#include <vector>

#include "analysis/eval/surface_evaluator.hpp"
#include "analysis/sewing/sew_faces.hpp"
#include "core/scene.hpp"
#include "core/trimmed_surface.hpp"

namespace cadnurbs::sewing {

// One face being sewn. `trimmed` points into the scene that sew_faces returns: the steps rewrite its loops.
struct SewFace {
  TrimmedSurface* trimmed;
  std::unique_ptr<SurfaceEvaluator> surface;
  int group;  // faces are sewn within their group only
};

// Replaces every polygon set of `node` and the nodes below it (a PolygonMesh, or a TriangleMesh without
// normals: how the readers return the compact writer's IndexedFaceSets of planar faces) by one Shape per
// polygon: a planar trimmed surface (planar_polygon_surface) with the set's name, colour and source.
// Other shapes keep their place.
void polygons_as_faces(SceneNode& node, double tolerance, SewingReport& report);

// Faces in scene order, each with its group: the nearest named node above it (a solid or part, as the
// source file named it) with all the unnamed nodes below it (writers' Groups and Transforms). Faces are
// sewn within their group only, so that parts of an assembly that touch stay separate solids. `group` is
// the group of `node`'s unnamed ancestors; `groups` counts the groups given so far. An untrimmed face gets
// its domain rectangle as its loop here.
void collect_faces(SceneNode& node, int group, int& groups, std::vector<SewFace>& faces);

}  // namespace cadnurbs::sewing
