#include "analysis/coding_choice/certified_body_mesh.hpp"

#include <algorithm>

#include "analysis/mesh/weld_vertices.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/geometry_error.hpp"
#include "core/world_scale.hpp"

namespace cadnurbs {

namespace {

// The share of the deviation left to welding the meshes (at most 1e-6 of their size).
constexpr double kWeldShare = 1e-3;

bool has_faces(const Scene& body) {
  for (const auto& node : body.root.children)
    for (const auto& shape : node.shapes)
      if (std::holds_alternative<TrimmedSurface>(shape.geometry) || std::holds_alternative<PolygonMesh>(shape.geometry))
        return true;
  return false;
}

// One node's shapes after tessellation (`tessellated`, its trimmed surfaces already meshes, in the order
// of `original`): what the node held besides faces, then the faces merged per colour.
std::vector<Shape> merged_per_colour(const SceneNode& original, const SceneNode& tessellated, double weld_tolerance,
                                     CertifiedBodyMesh& out) {
  std::vector<Shape> kept;
  std::vector<Shape> merged;  // one per colour, in order of first use
  for (size_t i = 0; i < original.shapes.size(); ++i) {
    const Shape& source = original.shapes[i];
    TriangleMesh triangles;
    if (std::holds_alternative<TrimmedSurface>(source.geometry)) {
      triangles = std::get<TriangleMesh>(tessellated.shapes[i].geometry);
      ++out.faces;
    } else if (const auto* polygons = std::get_if<PolygonMesh>(&source.geometry)) {
      triangles = triangulated(*polygons);
      out.polygons += static_cast<long>(polygons->polygons.size());
    } else {
      kept.push_back(source);
      continue;
    }
    triangles.corner_normals.clear();
    auto same_colour = [&](const Shape& s) { return s.colour == source.colour; };
    auto it = std::find_if(merged.begin(), merged.end(), same_colour);
    if (it == merged.end()) {
      merged.push_back({"", TriangleMesh{}, source.colour, "certified mesh"});
      it = merged.end() - 1;
    }
    append(std::get<TriangleMesh>(it->geometry), triangles);
  }
  for (auto& shape : merged) {
    auto& mesh = std::get<TriangleMesh>(shape.geometry);
    // The compact form's polygons and the tessellated faces meet at corners equal only up to rounding.
    WeldReport weld;
    mesh = weld_vertices(mesh, std::min(default_weld_tolerance(mesh), weld_tolerance), &weld);
    out.weld_move = std::max(out.weld_move, weld.largest_merge_distance);
    out.triangles += static_cast<long>(mesh.triangles.size());
    if (!mesh.triangles.empty()) kept.push_back(std::move(shape));
  }
  return kept;
}

}  // namespace

std::optional<CertifiedBodyMesh> certified_body_mesh(const Scene& body, double max_world_deviation,
                                                     std::string* refusal) {
  if (!(max_world_deviation > 0))
    throw GeometryError("certified_body_mesh",
                        "the deviation must be positive, not " + std::to_string(max_world_deviation));
  auto refuse = [&](const std::string& why) -> std::optional<CertifiedBodyMesh> {
    if (refusal) *refusal = why;
    return std::nullopt;
  };
  if (!has_faces(body)) return refuse("");
  const double scale = largest_world_scale(body);
  const double own_deviation = max_world_deviation / scale;
  TessellationReport report;
  Scene tessellated;
  try {
    tessellated = tessellate_to_deviation(body, (1 - kWeldShare) * own_deviation, &report);
  } catch (const GeometryError& error) {
    return refuse(error.what());
  }
  if (report.uncertified_triangles > 0)
    return refuse(std::to_string(report.uncertified_triangles) + " triangles not certified");
  CertifiedBodyMesh out;
  out.unshared_edge_uses = report.unshared_edge_uses;
  for (size_t k = 0; k < body.root.children.size(); ++k)
    out.shapes.push_back(
        merged_per_colour(body.root.children[k], tessellated.root.children[k], kWeldShare * own_deviation, out));
  // The welding's chains may move a vertex beyond the tolerance: checked.
  const double world = scale * (report.certified_deviation + out.weld_move);
  if (world > max_world_deviation * (1 + 1e-12))
    return refuse("certified " + std::to_string(world) + " above " + std::to_string(max_world_deviation));
  out.world_deviation = std::min(world, max_world_deviation);  // above only by rounding
  return out;
}

}  // namespace cadnurbs
