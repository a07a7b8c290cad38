#include "analysis/certified_mesh/certified_scene_mesh.hpp"

#include <unordered_map>

#include "core/bounding_box.hpp"

namespace cadnurbs {

namespace {
// Whether two shapes hold the same trimmed surface: copies placed by compaction keep their original's
// edge numbers, which join no two faces.
bool same_surface(const Shape& a, const Shape& b) {
  const auto* x = std::get_if<TrimmedSurface>(&a.geometry);
  const auto* y = std::get_if<TrimmedSurface>(&b.geometry);
  // Trims too: the two halves of a cylinder may be one surface, and share their seams.
  const bool same_trims = x && y && x->loops.size() == y->loops.size() &&
                          (x->loops.empty() || (!x->loops[0].segments.empty() && !y->loops[0].segments.empty() &&
                                                segment_start(x->loops[0].segments[0]) ==
                                                    segment_start(y->loops[0].segments[0])));
  return same_trims && x->surface.points == y->surface.points && x->surface.u_knots == y->surface.u_knots &&
         x->surface.v_knots == y->surface.v_knots && x->surface.weights == y->surface.weights;
}

// Whether the scene's trimming loops say which faces meet where: every face is trimmed, every loop names a
// model edge for each of its segments, and two different faces (not copies) name the same edge. (OCCT
// names every edge of an IGES file's faces, but each face has its own, a seam aside; compaction's
// untrimmed faces and joined trims name none.)
bool names_shared_edges(const Scene& scene) {
  std::unordered_map<int, const Shape*> first_face;
  bool every_loop = true, shared = false;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry)) {
      every_loop = every_loop && !t->loops.empty();  // a domain's sides name nothing
      for (const auto& loop : t->loops) {
        every_loop = every_loop && loop.edges.size() == loop.segments.size();
        for (const auto& ref : loop.edges)
          if (ref.edge >= 0) {
            const Shape* first = first_face.emplace(ref.edge, &shape).first->second;
            shared = shared || (first != &shape && !same_surface(*first, shape));
          }
      }
    }
  });
  return every_loop && shared;
}
}  // namespace

bool sewn_when_meshed(const Scene& scene) {
  const SceneCounts counts = count_entities(scene);
  return counts.surfaces + counts.polygon_meshes > 0 && (counts.polygon_meshes > 0 || !names_shared_edges(scene));
}

namespace {
// The faces certified_scene_mesh tessellates: `scene`, or its faces sewn (into result.faces).
const Scene& faces_to_tessellate(const Scene& scene, double max_deviation, EdgeSource edges, CertifiedMesh& result) {
  result.sewn = edges == EdgeSource::file && sewn_when_meshed(scene);
  if (!result.sewn) return scene;
  result.sewing_tolerance = sewing_tolerance(scene_bounding_box(scene).diagonal().norm(), max_deviation);
  result.faces = sew_faces(scene, result.sewing_tolerance, &result.sewing);
  return result.faces;
}
}  // namespace

CertifiedMesh certified_scene_mesh(const Scene& scene, double max_deviation, EdgeSource edges,
                                   bool check_face_areas) {
  CertifiedMesh result;
  const Scene& faces = faces_to_tessellate(scene, max_deviation, edges, result);
  result.meshes = tessellate_to_deviation(faces, max_deviation, &result.report, check_face_areas);
  return result;
}

int certified_scene_unshared_edge_uses(const Scene& scene, double max_deviation, EdgeSource edges) {
  CertifiedMesh sewing;
  return unshared_edge_uses(faces_to_tessellate(scene, max_deviation, edges, sewing), max_deviation);
}

}  // namespace cadnurbs
