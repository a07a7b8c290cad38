#include "analysis/coding_choice/cheapest_coding.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

#include "analysis/coding_choice/certified_body_mesh.hpp"
#include "analysis/coding_choice/scene_bodies.hpp"
#include "analysis/mesh/merge_world_meshes.hpp"
#include "core/geometry_error.hpp"

namespace cadnurbs {

namespace {

// A whole candidate: the scene with the bodies `meshed` says replaced by their meshes, and its tally.
struct Candidate {
  Scene scene;
  int bodies = 0, bodies_refused = 0;  // of the scene it was made from
  int bodies_meshed = 0, faces_meshed = 0;
  long polygons_meshed = 0, triangles = 0;
  int unshared_edge_uses = 0;
  double certified_deviation = 0;
  size_t bytes = 0;
};

// Each body's certified mesh within `deviation` (world), or nullopt; `refused` counts the bodies that had
// faces but no certified mesh.
std::vector<std::optional<CertifiedBodyMesh>> body_meshes(const Scene& scene, const SceneBodies& bodies,
                                                          double deviation, int& refused) {
  std::vector<std::optional<CertifiedBodyMesh>> meshes(bodies.bodies.size());
  for (size_t i = 0; i < meshes.size(); ++i) {
    std::string refusal;
    meshes[i] = certified_body_mesh(body_scene(scene, bodies, static_cast<int>(i)), deviation, &refusal);
    refused += !meshes[i] && !refusal.empty();
  }
  return meshes;
}

Candidate with_meshes(const Scene& scene, const SceneBodies& bodies,
                      const std::vector<std::optional<CertifiedBodyMesh>>& meshes, const std::vector<bool>& meshed) {
  Candidate out{scene, static_cast<int>(meshes.size())};
  const std::vector<SceneNode*> nodes = nodes_in_order(out.scene.root);
  for (size_t i = 0; i < meshes.size(); ++i) {
    if (!meshed[i] || !meshes[i]) continue;
    const CertifiedBodyMesh& mesh = *meshes[i];
    for (size_t k = 0; k < bodies.bodies[i].size(); ++k) nodes[bodies.bodies[i][k]]->shapes = mesh.shapes[k];
    ++out.bodies_meshed;
    out.faces_meshed += mesh.faces;
    out.polygons_meshed += mesh.polygons;
    out.triangles += mesh.triangles;
    out.unshared_edge_uses += mesh.unshared_edge_uses;
    out.certified_deviation = std::max(out.certified_deviation, mesh.world_deviation);
  }
  return out;
}

}  // namespace

namespace {
// The bytes field of the report's chosen candidate (const or not).
template <class Report>
auto& chosen_bytes(Report& r) {
  decltype(&r.as_is_bytes) const by_whole[] = {&r.as_is_bytes, &r.per_body_bytes, &r.all_meshed_bytes,
                                               &r.exact_meshed_bytes, &r.merged_meshes_bytes};  // Whole's order
  return *by_whole[static_cast<int>(r.chosen)];
}
}  // namespace

size_t CodingChoiceReport::bytes() const { return chosen_bytes(*this); }

void CodingChoiceReport::set_bytes(size_t bytes) { chosen_bytes(*this) = bytes; }

Scene cheapest_coding(const Scene& scene, const CodingChoiceParameters& parameters, const CodedBytes& coded_bytes,
                      CodingChoiceReport* report, const Scene* exact) {
  const double d = parameters.max_deviation, t = parameters.mesh_share;
  if (!(d > 0) || !std::isfinite(d))
    throw GeometryError("cheapest_coding", "the maximum deviation must be a positive number, not " + std::to_string(d));
  if (!(t > 0 && t < 1))
    throw GeometryError("cheapest_coding", "the mesh share must lie in (0, 1), not " + std::to_string(t));
  const SceneBodies bodies = scene_bodies(scene);
  const size_t n = bodies.bodies.size();
  int refused = 0;
  // Bodies that may meet along unnamed edges are not meshed one by one (per body, every body meshed, and
  // their merge then equal the scene as it is).
  const auto meshes = parameters.bodies_named ? body_meshes(scene, bodies, t * d, refused)
                                              : std::vector<std::optional<CertifiedBodyMesh>>(n);
  std::vector<bool> cheaper_meshed(n, false), meshable(n, false);
  for (size_t i = 0; i < n; ++i) {
    if (!meshes[i]) continue;
    meshable[i] = true;
    const Scene meshed = body_scene(scene, bodies, static_cast<int>(i), meshes[i]->shapes);
    cheaper_meshed[i] = coded_bytes(meshed, meshes[i]->world_deviation) <
                        coded_bytes(body_scene(scene, bodies, static_cast<int>(i)), 0.0);
  }
  // The whole candidates; equal ones are costed once.
  Candidate as_is{scene, static_cast<int>(n)};
  as_is.bytes = coded_bytes(scene, 0.0);
  as_is.bodies_refused = refused;
  Candidate per_body = with_meshes(scene, bodies, meshes, cheaper_meshed);
  per_body.bodies_refused = refused;
  per_body.bytes =
      per_body.bodies_meshed == 0 ? as_is.bytes : coded_bytes(per_body.scene, per_body.certified_deviation);
  Candidate all_meshed = with_meshes(scene, bodies, meshes, meshable);
  all_meshed.bodies_refused = refused;
  all_meshed.bytes = all_meshed.bodies_meshed == per_body.bodies_meshed
                         ? per_body.bytes
                         : coded_bytes(all_meshed.scene, all_meshed.certified_deviation);
  Candidate exact_meshed;
  if (exact) {
    const SceneBodies exact_bodies = scene_bodies(*exact);
    int exact_refused = 0;
    const auto exact_meshes = body_meshes(*exact, exact_bodies, t * d, exact_refused);
    exact_meshed = with_meshes(*exact, exact_bodies, exact_meshes, std::vector<bool>(exact_meshes.size(), true));
    exact_meshed.bodies_refused = exact_refused;
    // Bodies kept as NURBS beside meshed ones may meet them along edges nobody named: not made then.
    if (parameters.bodies_named || exact_refused == 0)
      exact_meshed.bytes = coded_bytes(exact_meshed.scene, exact_meshed.certified_deviation);
  }
  Candidate merged_meshes = exact ? exact_meshed : all_meshed;
  if (merged_meshes.bodies_meshed > 0 && (merged_meshes.bytes > 0 || !exact)) {
    merged_meshes.scene = merge_world_meshes(merged_meshes.scene);
    merged_meshes.bytes = coded_bytes(merged_meshes.scene, merged_meshes.certified_deviation);
  }
  using Whole = CodingChoiceReport::Whole;
  Whole chosen = Whole::as_is;
  Candidate* best = &as_is;
  for (auto [whole, candidate] :
       {std::pair{Whole::per_body, &per_body}, std::pair{Whole::all_meshed, &all_meshed},
        std::pair{Whole::exact_meshed, &exact_meshed}, std::pair{Whole::merged_meshes, &merged_meshes}})
    if (candidate->bytes > 0 && candidate->bytes < best->bytes) chosen = whole, best = candidate;  // 0: not made
  if (report) {
    CodingChoiceReport& r = *report;
    r = {};
    r.chosen = chosen;
    r.bodies = best->bodies;
    r.bodies_meshed = best->bodies_meshed;
    r.bodies_kept = r.bodies - r.bodies_meshed;
    r.bodies_refused = best->bodies_refused;
    r.faces_meshed = best->faces_meshed;
    r.polygons_meshed = best->polygons_meshed;
    r.triangles = best->triangles;
    r.unshared_edge_uses = best->unshared_edge_uses;
    r.certified_deviation = best->certified_deviation;
    r.as_is_bytes = as_is.bytes;
    r.per_body_bytes = per_body.bytes;
    r.all_meshed_bytes = all_meshed.bytes;
    r.exact_meshed_bytes = exact_meshed.bytes;
    r.merged_meshes_bytes = merged_meshes.bytes;
  }
  return std::move(best->scene);
}

}  // namespace cadnurbs
