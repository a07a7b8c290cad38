#include "converters/subd_objects_as_nurbs.hpp"

#include "analysis/subd_nurbs/subd_to_nurbs.hpp"
#include "core/find_scene_node.hpp"
#include "core/geometry_error.hpp"
#include "core/number_format.hpp"

namespace cadnurbs {

namespace {

constexpr double kDefaultShareOfDiagonal = 1e-4;

double box_diagonal(const SubdControlNet& net) {
  Eigen::AlignedBox3d box;
  for (const auto& p : net.points) box.extend(p);
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

}  // namespace

void add_subd_objects_as_nurbs(const std::vector<rhino::RhinoScene::SubdObject>& objects, double deviation,
                               BrepTranslation& out) {
  for (const auto& object : objects) {
    SceneNode* node = find_scene_node(out.scene.root, object.source_entity);
    const double d = deviation > 0 ? deviation : kDefaultShareOfDiagonal * box_diagonal(object.net);
    if (!node || !(d > 0)) {
      out.repairs.push_back(object.object_label + ": SubD left out: " + (node ? "all its points coincide" : "no node"));
      continue;
    }
    SubdNurbs patches;
    try {
      patches = subd_to_nurbs(object.net, d, static_cast<int>(out.degenerated_edges.size()), object.object_label);
    } catch (const GeometryError& error) {
      out.repairs.push_back(object.object_label + ": SubD left out: " + error.reason());
      continue;
    }
    out.degenerated_edges.resize(out.degenerated_edges.size() + patches.edges_used, false);
    out.face_count += static_cast<int>(patches.patches.size());
    for (size_t k = 0; k < patches.patches.size(); ++k) {
      Shape shape;
      shape.source_entity = "patch " + std::to_string(k + 1);
      shape.source_type = "SubD patch";
      shape.geometry = std::move(patches.patches[k]);
      node->shapes.push_back(std::move(shape));
    }
    std::string line = object.object_label + ": SubD as " +
                       std::to_string(patches.exact_patches + patches.fitted_patches) + " NURBS patches, " +
                       std::to_string(patches.exact_patches) + " exact bicubic";
    if (patches.fitted_patches > 0)
      line += ", " + std::to_string(patches.fitted_patches) + " fitted near extraordinary points" +
              (patches.rhino_rule_patches > 0
                   ? " (" + std::to_string(patches.rhino_rule_patches) + " beside Rhino's sector coefficients)"
                   : std::string()) +
              " within " + message_number(patches.fitted_bound) +
              " mm of the limit surface (a bound, but in squares of 1/1024 of a patch at those points" +
              (patches.rhino_rule_patches > 0 ? std::string(", 1/16 at tagged ones") : std::string()) + ", where " +
              message_number(patches.fitted_sampled_at_features) + " mm is sampled)";
    out.notes.push_back(line);
  }
}

}  // namespace cadnurbs
