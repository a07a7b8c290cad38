#include "formats/vrml/scene_to_nodes.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

#include "core/bounding_box.hpp"
#include "core/geometry_error.hpp"
#include "formats/vrml/geometry_to_nodes.hpp"
#include "formats/vrml/share_repeated_nodes.hpp"
#include "formats/vrml/transform_fields.hpp"
#include "formats/vrml/vrml_identifier.hpp"
#include "formats/vrml/world_info.hpp"

namespace cadnurbs {

namespace {

// Colours are 0..1; half a step of 8 bits is as fine as any display shows.
constexpr double colour_tolerance = 1.0 / 512.0;

SFColor sf_colour(const Colour& c) { return SFColor{Eigen::Vector3d(c.r, c.g, c.b)}; }

SFRotation sf_rotation(const Eigen::AngleAxisd& r) { return SFRotation{r.axis(), r.angle()}; }

// A node whose colour shapes inherit, while its subtree is being mapped.
struct ColourOwner {
  Node* node = nullptr;  // its Transform or Group (DEF'd when a shape needs it)
  Colour colour;
  NodePtr surface_appearance, line_appearance;
};

class SceneMapper {
 public:
  SceneMapper(const Scene& scene, const VrmlWriteOptions& options)
      : scene_(scene), options_(options), dialect_(dialect_of(options.encoding)),
        tau_(effective_coordinate_tolerance(scene, options)), box_(scene_bounding_box(scene)) {}

  NodeDocument map() {
    claim_names(scene_.root);
    std::vector<ColourOwner*> owners;
    // Entity paths as core validate() names them.
    NodePtr root = map_node(scene_.root, Eigen::Affine3d::Identity(), owners,
                            scene_.root.name.empty() ? "scene" : scene_.root.name);
    NodeDocument document;
    document.dialect = dialect_;
    document.roots = {world_info(), navigation_info(), viewpoint(), root};
    share_repeated_nodes(document, ids_);
    return document;
  }

 private:
  // DEF names for every named node and shape first, so the scene's own names win over generated ones.
  void claim_names(const SceneNode& node) {
    if (!node.name.empty()) node_defs_[&node] = claim(node.name, node.name);
    for (const auto& shape : node.shapes)
      if (!shape.name.empty()) shape_defs_[&shape] = claim(shape.name, shape.name);
    for (const auto& child : node.children) claim_names(child);
  }

  std::string claim(const std::string& wanted, const std::string& original) {
    std::string def = ids_.claim(wanted);
    // A scene name that looks like a generated DEF ("_12") must be declared, or a reader drops it.
    if (def != original || is_generated_identifier(def)) renamed_.emplace_back(def, original);
    return def;
  }

  NodePtr map_node(const SceneNode& node, const Eigen::Affine3d& parent_world, std::vector<ColourOwner*>& owners,
                   const std::string& path) {
    const Eigen::Affine3d world = parent_world * node.transform;
    NodePtr out = transform_node(node, parent_world, world, path);
    auto it = node_defs_.find(&node);
    if (it != node_defs_.end()) out->def_name = it->second;
    ColourOwner owner;
    if (node.colour) {
      owner.node = out.get();
      owner.colour = *node.colour;
      owners.push_back(&owner);
    }
    // Local units: a tolerance in world units shrinks by the largest stretch of the world transform.
    const double stretch = std::max(world.linear().jacobiSvd().singularValues()(0), 1e-300);
    const GeometryPrecision precision{tau_ / stretch, options_.significant_digits, options_.homogeneous_control_points};
    MFNode children;
    // VRML97: the NURBS surfaces of one node go into a NurbsGroup (blaxxun proposal), which lets a
    // browser tessellate them together; X3D has no grouping equivalent (NurbsSet holds geometry only).
    int surfaces = 0;
    for (const auto& shape : node.shapes) surfaces += std::holds_alternative<TrimmedSurface>(shape.geometry);
    NodePtr nurbs_group;
    if (dialect_ == VrmlDialect::vrml97 && surfaces >= 2) {
      nurbs_group = make_node("NurbsGroup");
      children.nodes.push_back(nurbs_group);
    }
    MFNode grouped;
    for (const auto& shape : node.shapes) {
      auto shape_node = make_node("Shape");
      auto def = shape_defs_.find(&shape);
      if (def != shape_defs_.end()) shape_node->def_name = def->second;
      const bool line = std::holds_alternative<NurbsCurve>(shape.geometry);
      if (NodePtr appearance = appearance_for(shape, line, owners)) shape_node->set("appearance", SFNode{appearance});
      std::optional<TessellationHints> hints;
      const auto* face = std::get_if<TrimmedSurface>(&shape.geometry);
      if (face && options_.tessellation_hints && options_.display_deviation > 0)
        hints = options_.tessellation_hints(*face, options_.display_deviation / stretch);
      shape_node->set("geometry", SFNode{geometry_node(shape.geometry, dialect_, precision, hints ? &*hints : nullptr)});
      (nurbs_group ? grouped : children).nodes.push_back(shape_node);
    }
    if (nurbs_group) nurbs_group->set("children", std::move(grouped));
    for (size_t i = 0; i < node.children.size(); ++i) {
      const auto& child = node.children[i];
      children.nodes.push_back(
          map_node(child, world, owners, path + "/" + (child.name.empty() ? "node " + std::to_string(i) : child.name)));
    }
    if (node.colour) owners.pop_back();
    if (!children.nodes.empty()) out->set("children", std::move(children));
    return out;
  }

  NodePtr transform_node(const SceneNode& node, const Eigen::Affine3d& parent_world, const Eigen::Affine3d& world,
                         const std::string& path) {
    TransformFields f;
    try {
      f = decompose_transform(node.transform);
    } catch (const std::invalid_argument& e) {
      throw GeometryError(path, e.what());
    }
    // First-order precision: an error δ in a translation moves the subtree by (parent stretch)·δ; in an
    // angle or axis by δ times its distance from the node's origin, at most `reach`.
    const double parent_stretch = std::max(parent_world.linear().jacobiSvd().singularValues()(0), 1e-300);
    double reach = 0.0;
    if (!box_.isEmpty())
      for (int corner = 0; corner < 8; ++corner)
        reach = std::max(reach, (box_.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)) -
                                 world.translation()).norm());
    reach = std::max(reach, 1e-300);
    const double translation_tol = tau_ / parent_stretch;
    const double angle_tol = 0.25 * tau_ / reach;
    const double scale_tol = 0.25 * tau_ * f.scale.cwiseAbs().minCoeff() / reach;
    const int digits = options_.significant_digits;
    const bool has_translation = f.translation.cwiseAbs().maxCoeff() > translation_tol;
    const bool has_rotation = std::abs(f.rotation.angle()) > angle_tol;
    const bool has_scale = (f.scale - Eigen::Vector3d::Ones()).cwiseAbs().maxCoeff() > scale_tol;
    const bool has_scale_orientation = has_scale && std::abs(f.scale_orientation.angle()) > angle_tol;
    if (!has_translation && !has_rotation && !has_scale) return make_node("Group");
    auto out = make_node("Transform");
    if (has_translation) out->set("translation", SFVec3f{f.translation}, {translation_tol, digits});
    if (has_rotation) out->set("rotation", sf_rotation(f.rotation), {angle_tol, digits});
    if (has_scale) out->set("scale", SFVec3f{f.scale}, {scale_tol, digits});
    if (has_scale_orientation) out->set("scaleOrientation", sf_rotation(f.scale_orientation), {angle_tol, digits});
    return out;
  }

  NodePtr material_appearance(const Colour& colour, bool line) {
    auto material = make_node("Material");
    material->set(line ? "emissiveColor" : "diffuseColor", sf_colour(colour),
                  {colour_tolerance, options_.significant_digits});
    auto appearance = make_node("Appearance");
    appearance->set("material", SFNode{material});
    return appearance;
  }

  NodePtr appearance_for(const Shape& shape, bool line, std::vector<ColourOwner*>& owners) {
    if (shape.colour) return material_appearance(*shape.colour, line);
    if (owners.empty()) {
      if (line) return nullptr;  // viewers draw lines without an Appearance in white
      if (!default_appearance_) {
        default_appearance_ = make_node("Appearance", ids_.claim("default_appearance"));
        default_appearance_->set("material", SFNode{make_node("Material")});
      }
      return default_appearance_;
    }
    ColourOwner& owner = *owners.back();
    NodePtr& shared = line ? owner.line_appearance : owner.surface_appearance;
    if (shared) return shared;
    if (owner.node->def_name.empty()) owner.node->def_name = claim("node", "");
    const std::string def = owner.node->def_name + (line ? "_line_colour" : "_colour");
    shared = material_appearance(owner.colour, line);
    // A scene name already holds that DEF: the colour is still right, only not marked as the node's.
    if (!ids_.is_taken(def)) shared->def_name = ids_.claim(def);
    return shared;
  }

  NodePtr world_info() {
    auto node = make_node("WorldInfo");
    const std::string title = options_.title.empty() ? scene_.root.name : options_.title;
    if (!title.empty()) node->set("title", title);
    node->set("info", MFString{world_info_strings(scene_.unit, options_.homogeneous_control_points, renamed_)});
    return node;
  }

  NodePtr navigation_info() {
    auto node = make_node("NavigationInfo");
    node->set("type", MFString{{"EXAMINE", "ANY"}});
    node->set("headlight", true);
    return node;
  }

  NodePtr viewpoint() {
    const Viewpoint view = options_.viewpoint.value_or(framing_viewpoint(box_));
    // Precision independent of the scene, so that the same Viewpoint is written the same way in a NURBS
    // file and in the mesh file of the same part.
    const int digits = options_.significant_digits;
    auto node = make_node("Viewpoint");
    node->set("position", SFVec3f{view.position}, {1e-6 * std::max(view.position.norm(), 1e-300), digits});
    node->set("orientation", sf_rotation(view.orientation), {1e-6, digits});
    if (std::abs(view.field_of_view - 0.785398) > 1e-7) node->set("fieldOfView", view.field_of_view, {1e-6, digits});
    return node;
  }

  const Scene& scene_;
  const VrmlWriteOptions& options_;
  VrmlDialect dialect_;
  double tau_;
  Eigen::AlignedBox3d box_;
  IdentifierRegistry ids_;
  std::map<const SceneNode*, std::string> node_defs_;
  std::map<const Shape*, std::string> shape_defs_;
  std::vector<std::pair<std::string, std::string>> renamed_;
  NodePtr default_appearance_;
};

}  // namespace

double effective_coordinate_tolerance(const Scene& scene, const VrmlWriteOptions& options) {
  if (options.coordinate_tolerance > 0.0) return options.coordinate_tolerance;
  const Eigen::AlignedBox3d box = scene_bounding_box(scene);
  const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
  return diagonal > 0.0 ? 1e-6 * diagonal : 1e-6;
}

NodeDocument scene_to_nodes(const Scene& scene, const VrmlWriteOptions& options) {
  return SceneMapper(scene, options).map();
}

}  // namespace cadnurbs
