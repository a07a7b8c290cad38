#include "formats/vrml/nodes_to_scene.hpp"

#include <filesystem>
#include <map>
#include <set>
#include <stdexcept>

#include "formats/vrml/coordinate_deformer.hpp"
#include "formats/vrml/linked_files.hpp"
#include "formats/vrml/node_schema.hpp"
#include "formats/vrml/nodes_to_geometry.hpp"
#include "formats/vrml/parse_error.hpp"
#include "formats/vrml/proto_expansion.hpp"
#include "formats/vrml/transform_fields.hpp"
#include "formats/vrml/vrml_identifier.hpp"
#include "formats/vrml/world_info.hpp"

namespace cadnurbs {

namespace {

// Grouping nodes placed by translation, rotation, scale, scaleOrientation and center, as Transform is.
bool is_placed_like_transform(const std::string& type) {
  static const std::set<std::string> kinds = {"Transform", "HAnimHumanoid", "HAnimJoint",
                                              "HAnimSite", "CADPart",       "CADAssembly"};
  return kinds.contains(type);
}

bool is_plain_group(const std::string& type) {
  static const std::set<std::string> kinds = {"Group",     "NurbsGroup", "StaticGroup",       "Anchor",
                                              "Billboard", "Collision",  "HAnimSegment",      "CADLayer",
                                              "Switch",    "LOD",        "CoordinateDeformer"};
  return kinds.contains(type);
}

// Nodes that draw another file's scene where they stand.
bool is_inline(const Node& node) {
  static const std::set<std::string> kinds = {"Inline", "InlineLoadControl"};
  return !node.proto_instance && kinds.contains(node.type);
}

bool is_grouping(const Node& node) {
  return !node.proto_instance && (is_placed_like_transform(node.type) || is_plain_group(node.type));
}

// Read and not reported: the writers make their own.
bool is_ignored(const Node& node) {
  return node.type == "WorldInfo" || node.type == "NavigationInfo" || node.type == "Viewpoint";
}

const char* const kAnimation = "animation and interaction are not converted: the scene is taken at rest";

// Why a node of this type has no place in a Scene.
std::string why_kind_left_out(const Node& node) {
  const std::string& t = node.type;
  if (node.proto_instance)
    return "PROTO instances nested deeper than " + std::to_string(kMaxProtoDepth) + " levels are not expanded";
  auto ends = [&](const char* suffix) { return t.ends_with(suffix); };
  if (ends("Interpolator") || ends("Sensor") || ends("Trigger") || ends("Sequencer") || ends("Chaser") ||
      ends("Damper") || t == "Script" || t == "BooleanFilter" || t == "BooleanToggle")
    return kAnimation;
  if (ends("Light") || t == "Background" || t == "TextureBackground" || t == "Fog" || t == "LocalFog" || t == "Sound" ||
      t == "SpatialSound" || t == "AudioClip")
    return "lights, sound and environment have no place in the output";
  return "no place in a Scene";
}

// The nodes of a grouping node that are drawn: Switch's chosen one, LOD's first level, HAnimHumanoid's
// skeleton and skin, CADFace's shape, else the children.
std::vector<NodePtr> drawn_children(const Node& node) {
  auto nodes = [&](const char* field) {
    if (const auto* mf = node.get<MFNode>(field)) return mf->nodes;
    if (const auto* sf = node.get<SFNode>(field); sf && sf->node) return std::vector<NodePtr>{sf->node};
    return std::vector<NodePtr>{};
  };
  if (node.type == "Switch") {
    auto choices = node.get<MFNode>("choice") ? nodes("choice") : nodes("children");
    const int* which = node.get<int>("whichChoice");
    if (!which || *which < 0 || static_cast<size_t>(*which) >= choices.size()) return {};
    return {choices[static_cast<size_t>(*which)]};
  }
  if (node.type == "LOD") {
    auto levels = node.get<MFNode>("level") ? nodes("level") : nodes("children");
    if (levels.size() > 1) levels.resize(1);
    return levels;
  }
  if (node.type == "HAnimHumanoid") {
    auto out = nodes("skeleton");
    for (auto& skin : nodes("skin")) out.push_back(skin);
    return out;
  }
  if (node.type == "CADFace") return nodes("shape");
  return nodes("children");
}

// What the builders of a file and of the files it inlines share: the notes, the copy count, the files read.
struct SharedState {
  std::map<std::string, std::pair<size_t, std::string>> left_out;  // kind -> count, why
  std::vector<std::string> left_out_order;
  long expanded = 0;
  LinkedFiles files;
};

// A CoordinateDeformer the builder is inside: its volume and the transform from the current node's
// coordinates to the deformer's.
struct ActiveDeformer {
  NurbsVolume volume;
  Eigen::Affine3d to_deformer = Eigen::Affine3d::Identity();
};

class SceneBuilder {
 public:
  struct Ancestor {
    std::string def_name;
    SceneNode* node;
  };

  SceneBuilder(const NodeDocument& document, const std::string& file, bool homogeneous, SharedState& shared,
               std::vector<std::filesystem::path> chain, std::vector<ActiveDeformer> deformers)
      : document_(document), file_(file), shared_(shared), chain_(std::move(chain)), deformers_(std::move(deformers)) {
    context_.file = file;
    context_.homogeneous = homogeneous;
    directory_ = std::filesystem::path(file).parent_path();
  }

  SceneFromNodes build() {
    for (const auto& root : document_.roots)
      if (root && root->type == "WorldInfo") read_world_info(*root);
    Scene scene;
    scene.unit = scene.source_unit = conventions_.unit.value_or(LengthUnit{});
    const std::vector<const Node*> content = drawn_roots();
    std::vector<Ancestor> ancestors;
    if (content.size() == 1 && is_grouping(*content.front())) {
      scene.root = scene_node(*content.front(), ancestors);
    } else {
      ancestors.push_back(Ancestor{"", &scene.root});
      for (const Node* node : content) add_child(scene.root, *node, ancestors);
    }
    note_routes();
    SceneFromNodes out{std::move(scene), {}};
    for (const auto& kind : shared_.left_out_order) {
      const auto& [count, why] = shared_.left_out[kind];
      out.notes.push_back(std::to_string(count) + " " + kind + " left out: " + why);
    }
    return out;
  }

  // The file's content as the children of `out` (an Inline of it).
  void add_content(SceneNode& out, std::vector<Ancestor>& ancestors) {
    for (const auto& root : document_.roots)
      if (root && root->type == "WorldInfo") read_world_names(*root);
    for (const Node* node : drawn_roots()) add_child(out, *node, ancestors);
    note_routes();
  }

 private:
  // The top-level nodes that draw, PROTO instances expanded (proto_expansion.hpp).
  std::vector<const Node*> drawn_roots() {
    if (!document_.protos.empty()) {
      try {
        expanded_ = expand_protos(document_, [this](const ProtoDeclaration& p) { return load_extern(p); });
      } catch (const std::length_error& e) {
        throw_parse_error(file_, 0, e.what());
      }
    } else {
      expanded_.roots = document_.roots;
    }
    std::vector<const Node*> content;
    for (const auto& root : expanded_.roots)
      if (root && !is_ignored(*root)) content.push_back(root.get());
    return content;
  }

  void note_routes() {
    const size_t routes = document_.routes.size() + expanded_.body_routes;
    if (routes) left_out("ROUTE", kAnimation, routes);
  }

  // An EXTERNPROTO's PROTO from a local file its urls name ("file.wrl#Name", else the PROTO of its name).
  LoadedProto load_extern(const ProtoDeclaration& externproto) {
    for (const auto& url : externproto.urls) {
      const auto opened = shared_.files.open({url}, directory_, chain_);
      if (!opened.document) continue;
      const size_t hash = url.find('#');
      const std::string name = hash == std::string::npos ? externproto.name : url.substr(hash + 1);
      for (const auto& proto : opened.document->protos)
        if (proto.name == name && !proto.external) return LoadedProto{opened.document, &proto};
    }
    return {};
  }

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

  // The original names of renamed DEFs (an inlined file's unit and conventions are its includer's).
  void read_world_names(const Node& node) {
    const auto* info = node.get<MFString>("info");
    if (!info) return;
    try {
      conventions_.names = parse_world_info(info->values).names;
    } catch (const std::invalid_argument& e) {
      fail(node, std::string("WorldInfo: ") + e.what());
    }
  }

  std::string name_of(const Node& node) const {
    auto it = conventions_.names.find(node.def_name);
    if (it != conventions_.names.end()) return it->second;
    return is_generated_identifier(node.def_name) ? std::string() : node.def_name;
  }

  // A USE is a copy in the Scene: nested USEs multiply; stop a file that multiplies without bound.
  void count(const Node& node) {
    if (++shared_.expanded > max_expanded)
      fail(node, "DEF/USE expand to more than " + std::to_string(max_expanded) + " nodes and shapes");
  }

  SceneNode scene_node(const Node& node, std::vector<Ancestor>& ancestors) {
    count(node);
    SceneNode out;
    out.name = name_of(node);
    if (is_placed_like_transform(node.type)) out.transform = transform(node);
    const std::vector<ActiveDeformer> outer_deformers = deformers_;
    for (auto& deformer : deformers_) deformer.to_deformer = deformer.to_deformer * out.transform;
    ancestors.push_back(Ancestor{node.def_name, &out});
    const bool deforms = node.type == "CoordinateDeformer" && !deforms_nothing(node) && enter_deformer(node);
    if (node.type != "CoordinateDeformer" || deforms_nothing(node) || deforms) {
      for (const auto& child : drawn_children(node))
        if (child) add_child(out, *child, ancestors);
    }
    ancestors.pop_back();
    deformers_ = outer_deformers;
    return out;
  }

  // Pushes the deformer's volume (coordinate_deformer.hpp); false, with a note, when it is invalid.
  bool enter_deformer(const Node& node) {
    try {
      deformers_.push_back(
          ActiveDeformer{coordinate_deformer_volume(node, context_.homogeneous), Eigen::Affine3d::Identity()});
    } catch (const std::invalid_argument& e) {
      left_out("CoordinateDeformer with an invalid volume",
               std::string(e.what()) + "; its children are left out with it");
      return false;
    }
    for (const char* field : {"inputCoord", "outputCoord"})
      if (const auto* coords = node.get<MFNode>(field); coords && !coords->nodes.empty()) {
        left_out("CoordinateDeformer inputCoord/outputCoord",
                 "coordinates routed through a deformer are not evaluated: the Coordinate nodes keep their points");
        break;
      }
    return true;
  }

  // scale 0 in some direction (white_dune's robot grows parts from nothing by animating it).
  static bool scaled_to_nothing(const Node& node) {
    const auto* s = node.get<SFVec3f>("scale");
    return s && s->value.allFinite() && s->value.prod() == 0.0;
  }

  // A CoordinateDeformer with no control points moves no coordinate.
  static bool deforms_nothing(const Node& node) {
    const auto* points = node.get<MFVec3f>("controlPoint");
    return !points || points->values.empty();
  }

  void left_out(const std::string& kind, const std::string& why, size_t count = 1) {
    auto [it, added] = shared_.left_out.try_emplace(kind, 0, why);
    if (added) shared_.left_out_order.push_back(kind);
    it->second.first += count;
  }

  // An Inline's file read where it stands (linked_files.hpp), or a note naming its url.
  void add_inline(SceneNode& parent, const Node& node, std::vector<Ancestor>& ancestors) {
    if (const bool* load = node.get<bool>("load"); load && !*load) {
      left_out(node.type + " with load FALSE", "it loads nothing at rest");
      return;
    }
    const auto* urls = node.get<MFString>("url");
    const auto opened = shared_.files.open(urls ? urls->values : std::vector<std::string>{}, directory_, chain_);
    if (!opened.document) {
      left_out(node.type + " \"" + opened.url + "\"", opened.refusal + ": not followed");
      return;
    }
    count(node);
    SceneNode out;
    out.name = name_of(node);
    auto chain = chain_;
    chain.push_back(opened.path);
    SceneBuilder inlined(*opened.document, opened.path.string(), context_.homogeneous, shared_, std::move(chain),
                         deformers_);
    ancestors.push_back(Ancestor{node.def_name, &out});
    inlined.add_content(out, ancestors);
    ancestors.pop_back();
    parent.children.push_back(std::move(out));
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
    if (is_grouping(child) && is_placed_like_transform(child.type) && scaled_to_nothing(child))
      left_out(child.type + " scaled to nothing", "it draws nothing at rest; its children are left out with it");
    else if (is_grouping(child))
      parent.children.push_back(scene_node(child, ancestors));
    else if (child.type == "Shape" && !child.proto_instance)
      add_shapes(parent, child, ancestors);
    else if (is_inline(child))
      add_inline(parent, child, ancestors);
    else if (is_ignored(child) || child.type == "NurbsSet")
      return;  // NurbsSet only names geometry drawn elsewhere
    else if (node_schema_allows_children(child))
      left_out(kind_of(child), why_left_out(child));
    else
      fail(child, child.type + " cannot stand among the children of a group");
  }

  // "Text", or "SuperShape (PROTO)".
  static std::string kind_of(const Node& node) { return node.type + (node.proto_instance ? " (PROTO)" : ""); }

  // Why a node is left out; an instance left unexpanded is one of an EXTERNPROTO no local file declares,
  // or one nested too deep.
  std::string why_left_out(const Node& node) const {
    if (node.proto_instance && declares_externproto(document_, node.type))
      return "its EXTERNPROTO's urls name no local file that declares it: not expanded";
    return why_kind_left_out(node);
  }

  static bool declares_externproto(const NodeDocument& document, const std::string& name) {
    for (const auto& proto : document.protos)
      if ((proto.external && proto.name == name) || (proto.body && declares_externproto(*proto.body, name)))
        return true;
    return false;
  }

  // Nodes that may stand among children: anything but the property nodes (Material, Appearance,
  // Coordinate, geometry...), whose default containerField is not "children".
  bool node_schema_allows_children(const Node& node) const {
    if (node.proto_instance) return true;
    const NodeSchema* schema = node_schema(document_.dialect, node.type);
    return schema && schema->container_field == "children";
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
  void apply_appearance(const Node& shape, Shape& out, std::vector<Ancestor>& ancestors) {
    const auto* appearance_field = shape.get<SFNode>("appearance");
    if (!appearance_field || !appearance_field->node) return;
    const Node& appearance = *appearance_field->node;
    if (appearance.type != "Appearance") fail(appearance, "appearance must be an Appearance");
    for (const char* field : {"texture", "textureTransform"})
      if (const auto* t = appearance.get<SFNode>(field); t && t->node)
        left_out(t->node->type, "textures are not converted; the shape keeps its material's colour");
    const auto* material_field = appearance.get<SFNode>("material");
    if (!material_field || !material_field->node) return;
    const Node& material = *material_field->node;
    const bool is_material = material.type == "Material" || material.type == "TwoSidedMaterial" ||
                             material.type == "PhysicalMaterial" || material.type == "UnlitMaterial";
    if (!is_material) fail(material, "material must be a Material");
    const SFColor* colour = material.get<SFColor>(material.type == "PhysicalMaterial" ? "baseColor" : "diffuseColor");
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
    const Node& geometry_node = *geometry->node;
    if (geometry_node.proto_instance || !reads_geometry_node(geometry_node.type)) {
      left_out(kind_of(geometry_node), geometry_node.proto_instance
                                           ? why_left_out(geometry_node)
                                           : "geometry without a NURBS or mesh form in cadnurbs");
      return;
    }
    for (const char* field : {"texCoord", "color"})
      if (const auto* f = geometry_node.get<SFNode>(field); f && f->node)
        left_out(f->node->type, std::string(field) == "color"
                                    ? "per-vertex colours are not converted; the shape keeps its material's colour"
                                    : "textures are not converted; the shape keeps its material's colour");
    count(shape);
    Shape prototype;
    prototype.name = name_of(shape);
    apply_appearance(shape, prototype, ancestors);
    for (auto& g : geometry_from_node(*geometry->node, context_)) {
      // The innermost deformer first: each maps the shape's coordinates and back.
      for (auto d = deformers_.rbegin(); d != deformers_.rend(); ++d) deform_geometry(g, d->volume, d->to_deformer);
      Shape s{prototype.name, std::move(g), prototype.colour};
      parent.shapes.push_back(std::move(s));
    }
  }

  const NodeDocument& document_;
  std::string file_;
  SharedState& shared_;
  std::vector<std::filesystem::path> chain_;  // the files inlining this one, and this one
  std::vector<ActiveDeformer> deformers_;     // outermost first
  std::filesystem::path directory_;           // where its relative urls point
  ExpandedProtos expanded_;
  GeometryReadContext context_;
  WorldInfoConventions conventions_;
  static constexpr long max_expanded = 1000000;
};

}  // namespace

SceneFromNodes nodes_to_scene(const NodeDocument& document, const std::string& name_for_errors,
                              bool homogeneous_control_points) {
  SharedState shared;
  std::vector<std::filesystem::path> chain;
  std::error_code error;
  if (std::filesystem::is_regular_file(name_for_errors, error))
    chain.push_back(std::filesystem::weakly_canonical(name_for_errors, error));
  return SceneBuilder(document, name_for_errors, homogeneous_control_points, shared, std::move(chain), {}).build();
}

}  // namespace cadnurbs
