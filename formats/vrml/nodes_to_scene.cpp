#include "formats/vrml/nodes_to_scene.hpp"

#include <stdexcept>

#include "formats/vrml/parse_error.hpp"
#include "formats/vrml/nodes_to_geometry.hpp"
#include "formats/vrml/transform_fields.hpp"
#include "formats/vrml/vrml_identifier.hpp"
#include "formats/vrml/world_info.hpp"

namespace cadnurbs {

namespace {

bool is_grouping(const Node& node) {
  return node.type == "Transform" || node.type == "Group" || node.type == "NurbsGroup";
}

bool is_ignored(const Node& node) {
  return node.type == "WorldInfo" || node.type == "NavigationInfo" || node.type == "Viewpoint";
}

class SceneBuilder {
 public:
  SceneBuilder(const NodeDocument& document, const std::string& file, bool homogeneous)
      : document_(document), file_(file) {
    context_.file = file;
    context_.homogeneous = homogeneous;
  }

  Scene build() {
    for (const auto& root : document_.roots)
      if (root && root->type == "WorldInfo") read_world_info(*root);
    Scene scene;
    scene.unit = scene.source_unit = conventions_.unit.value_or(LengthUnit{});
    std::vector<const Node*> content;
    for (const auto& root : document_.roots)
      if (root && !is_ignored(*root)) content.push_back(root.get());
    std::vector<Ancestor> ancestors;
    if (content.size() == 1 && is_grouping(*content.front())) {
      scene.root = scene_node(*content.front(), ancestors);
    } else {
      ancestors.push_back(Ancestor{"", &scene.root});
      for (const Node* node : content) add_child(scene.root, *node, ancestors);
    }
    return scene;
  }

 private:
  struct Ancestor {
    std::string def_name;
    SceneNode* node;
  };

  [[noreturn]] void fail(const Node& node, const std::string& reason) const {
    throw_parse_error(file_, node.line, reason);
  }

  void read_world_info(const Node& node) {
    const auto* info = node.get<MFString>("info");
    if (!info) return;
    try {
      conventions_ = parse_world_info(info->values);
    } catch (const std::invalid_argument& e) {
      fail(node, std::string("WorldInfo: ") + e.what());
    }
    if (conventions_.homogeneous_control_points) context_.homogeneous = *conventions_.homogeneous_control_points;
  }

  std::string name_of(const Node& node) const {
    auto it = conventions_.names.find(node.def_name);
    if (it != conventions_.names.end()) return it->second;
    return is_generated_identifier(node.def_name) ? std::string() : node.def_name;
  }

  // A USE is a copy in the Scene: nested USEs multiply; stop a file that multiplies without bound.
  void count(const Node& node) {
    if (++expanded_ > max_expanded)
      fail(node, "DEF/USE expand to more than " + std::to_string(max_expanded) + " nodes and shapes");
  }

  SceneNode scene_node(const Node& node, std::vector<Ancestor>& ancestors) {
    count(node);
    SceneNode out;
    out.name = name_of(node);
    if (node.type == "Transform") out.transform = transform(node);
    ancestors.push_back(Ancestor{node.def_name, &out});
    if (const auto* children = node.get<MFNode>("children"))
      for (const auto& child : children->nodes)
        if (child) add_child(out, *child, ancestors);
    ancestors.pop_back();
    return out;
  }

  void add_child(SceneNode& parent, const Node& child, std::vector<Ancestor>& ancestors) {
    // An unnamed NurbsGroup only gathers the NURBS shapes of its parent (as the writer makes it; a
    // generated DEF, "_<n>", names nothing).
    if (child.type == "NurbsGroup" && (child.def_name.empty() || is_generated_identifier(child.def_name))) {
      if (const auto* children = child.get<MFNode>("children"))
        for (const auto& grandchild : children->nodes)
          if (grandchild) add_child(parent, *grandchild, ancestors);
      return;
    }
    if (is_grouping(child)) parent.children.push_back(scene_node(child, ancestors));
    else if (child.type == "Shape") add_shapes(parent, child, ancestors);
    else if (!is_ignored(child)) fail(child, child.type + " cannot stand among the children of a group");
  }

  Eigen::Affine3d transform(const Node& node) const {
    TransformFields f;
    if (const auto* t = node.get<SFVec3f>("translation")) f.translation = t->value;
    if (const auto* c = node.get<SFVec3f>("center")) f.center = c->value;
    if (const auto* s = node.get<SFVec3f>("scale")) f.scale = s->value;
    if (const auto* r = node.get<SFRotation>("rotation")) f.rotation = rotation(node, *r);
    if (const auto* r = node.get<SFRotation>("scaleOrientation")) f.scale_orientation = rotation(node, *r);
    const Eigen::Affine3d m = compose_transform(f);
    if (!m.matrix().allFinite() || std::abs(m.linear().determinant()) == 0.0) fail(node, "Transform is singular");
    return m;
  }

  Eigen::AngleAxisd rotation(const Node& node, const SFRotation& r) const {
    const double length = r.axis.norm();
    if (length == 0.0) {
      if (r.angle == 0.0) return Eigen::AngleAxisd(0.0, Eigen::Vector3d::UnitZ());
      fail(node, "rotation about a zero axis");
    }
    return Eigen::AngleAxisd(r.angle, r.axis / length);
  }

  // The colour of an Appearance, and the enclosing node it belongs to when its DEF says so.
  void apply_appearance(const Node& shape, Shape& out, std::vector<Ancestor>& ancestors) const {
    const auto* appearance_field = shape.get<SFNode>("appearance");
    if (!appearance_field || !appearance_field->node) return;
    const Node& appearance = *appearance_field->node;
    if (appearance.type != "Appearance") fail(appearance, "appearance must be an Appearance");
    const auto* material_field = appearance.get<SFNode>("material");
    if (!material_field || !material_field->node) return;
    const Node& material = *material_field->node;
    if (material.type != "Material") fail(material, "material must be a Material");
    const SFColor* colour = material.get<SFColor>("diffuseColor");
    if (!colour) colour = material.get<SFColor>("emissiveColor");
    if (!colour) return;
    const Colour c{colour->value.x(), colour->value.y(), colour->value.z()};
    if (!appearance.def_name.empty())
      for (auto it = ancestors.rbegin(); it != ancestors.rend(); ++it) {
        if (it->def_name.empty()) continue;
        if (appearance.def_name != it->def_name + "_colour" && appearance.def_name != it->def_name + "_line_colour")
          continue;
        if (!it->node->colour) it->node->colour = c;
        if (*it->node->colour == c) return;  // inherited
        break;
      }
    out.colour = c;
  }

  void add_shapes(SceneNode& parent, const Node& shape, std::vector<Ancestor>& ancestors) {
    const auto* geometry = shape.get<SFNode>("geometry");
    if (!geometry || !geometry->node) return;  // draws nothing
    count(shape);
    Shape prototype;
    prototype.name = name_of(shape);
    apply_appearance(shape, prototype, ancestors);
    for (auto& g : geometry_from_node(*geometry->node, context_)) {
      Shape s{prototype.name, std::move(g), prototype.colour};
      parent.shapes.push_back(std::move(s));
    }
  }

  const NodeDocument& document_;
  const std::string& file_;
  GeometryReadContext context_;
  WorldInfoConventions conventions_;
  static constexpr long max_expanded = 1000000;
  long expanded_ = 0;
};

}  // namespace

Scene nodes_to_scene(const NodeDocument& document, const std::string& name_for_errors, bool homogeneous_control_points) {
  return SceneBuilder(document, name_for_errors, homogeneous_control_points).build();
}

}  // namespace cadnurbs
