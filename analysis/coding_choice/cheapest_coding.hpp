#pragma once
// Issue 39's choice above the .cnb writer: for each body of a scene (scene_bodies.hpp: a node's shapes,
// joined across nodes by shared model edges), the exact NURBS as they are or a certified mesh of them,
// whichever a coder writes in fewer bytes; then the whole result against "every body as it is", "every
// body meshed", when the caller has it "every body of the exact part meshed", and the last of those two
// with its meshes placed in world coordinates and merged into one per colour (merge_world_meshes), the
// smallest returned.
//
// In: a scene (any shapes, scene units) and the writer's deviation budget; the byte cost is a callback
// (`coded_bytes(scene, mesh_deviation)`: the size of a scene as the writer would write it when told that
// the meshes made here lie within mesh_deviation of the exact faces, world units, 0 when it holds none),
// so that analysis does not depend on a file format. Out: the scene with the chosen bodies' trimmed
// surfaces and planar polygons replaced by triangle meshes (certified_body_mesh.hpp: one per node and
// colour, welded, without corner normals); the node tree, transforms, node names, curves and existing
// meshes kept; a meshed body's faces lose their own names. A body whose tessellation fails or leaves a
// triangle uncertified keeps its NURBS.
//
// The exact part: the same faces before the compact rewrites (compaction/compact_scene: instances, exact
// polygons, joined trims), sharing their edges exactly. Its meshes are closed where the part is, while
// the compact form's polygons meet its tessellated faces at T-junctions and its instanced faces sit in
// nodes of their own; and its one mesh per node and colour often codes smaller (5 KiCad parts at
// D = 1 mm: 216-587 bytes against 240-833 meshed from the compact form).
//
// Why the bound holds: each meshed body is tessellated and welded so that its world deviation is at most
// mesh_share·D (certificate plus welding move in its own coordinates, times its nodes' largest world
// scale), reported as CodingChoiceReport::certified_deviation; the writer adds that to the move of the
// quantised vertices (within (1 − mesh_share)·D when its trim share is mesh_share), so the decoded meshes
// stay within D of the exact faces. A body is meshed whole or not at all, so no meshed face meets a NURBS
// face along a shared edge.
//
// Each body is costed alone, in a scene holding just that body at its world placement (same units, so
// the writer's quantisation grid is the same as in the whole scene). Deterministic: ties keep the NURBS,
// and among the whole candidates the first in the order of CodingChoiceReport::Whole wins.
#include <cstddef>
#include <functional>

#include "core/scene.hpp"

namespace cadnurbs {

struct CodingChoiceParameters {
  double max_deviation = 1.0;  // D > 0, world, scene units: the writer's bound
  double mesh_share = 0.4;     // t in (0, 1): meshes are certified within t·D (the writer's trim share)
  // false: the scene's bodies may meet along edges its loops do not name (polygon sets, or a file naming no
  // shared edges, which a reader sews): meshes made of them would not join there, so of the candidates
  // only the scene as it is and the exact part's meshes (with `exact`, when none of its bodies was
  // refused) are made.
  bool bodies_named = true;
};

struct CodingChoiceReport {
  enum class Whole { as_is, per_body, all_meshed, exact_meshed, merged_meshes };
  Whole chosen = Whole::as_is;     // which whole candidate was returned
  int bodies = 0;                  // bodies with shapes
  int bodies_meshed = 0;           // in the returned scene
  int bodies_kept = 0;             // bodies - bodies_meshed
  int bodies_refused = 0;          // bodies whose mesh was not certified (kept as they are)
  int faces_meshed = 0;            // trimmed surfaces written as meshes in the returned scene
  long polygons_meshed = 0;        // planar polygons written as triangles in the returned scene
  long triangles = 0;              // triangles of the meshes made, in the returned scene
  // Of those meshes' faces, the uses of a shared edge that did not match it within t·D (the part's own
  // faces lie farther apart there): each leaves a crack that a larger t may close.
  int unshared_edge_uses = 0;
  double certified_deviation = 0;  // largest world deviation of the meshes made (0 when none), <= t·D
  // The whole candidates; exact_meshed_bytes is 0 when no exact part was given, merged_meshes_bytes when
  // no body could be meshed.
  size_t as_is_bytes = 0, per_body_bytes = 0, all_meshed_bytes = 0, exact_meshed_bytes = 0, merged_meshes_bytes = 0;
  size_t bytes() const;  // of the returned candidate
  void set_bytes(size_t bytes);  // when the caller writes the returned candidate in fewer bytes than costed
};

using CodedBytes = std::function<size_t(const Scene& scene, double mesh_deviation)>;

// `exact` (may be null): the part `scene` was made from by exact rewrites within the writer's precision.
// Throws GeometryError for D <= 0 or t outside (0, 1); whatever `coded_bytes` throws.
Scene cheapest_coding(const Scene& scene, const CodingChoiceParameters& parameters, const CodedBytes& coded_bytes,
                      CodingChoiceReport* report = nullptr, const Scene* exact = nullptr);

}  // namespace cadnurbs
