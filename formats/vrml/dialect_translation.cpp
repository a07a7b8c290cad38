#include "formats/vrml/dialect_translation.hpp"

#include <functional>
#include <map>
#include <set>

#include "formats/vrml/node_schema.hpp"
#include "formats/vrml/nurbs_protos.hpp"
#include "formats/vrml/proto_library.hpp"

namespace cadnurbs {

namespace {

// The amendment's nodes that the VRML97 writer declares from the cadnurbs PROTO library.
bool library_declares(const std::string& type) {
  return type == "NurbsSurface" || type == "TrimmedSurface" || type == "Contour2D" || type == "NurbsCurve2D" ||
         type == "Polyline2D" || type == "NurbsGroup" || type == "NurbsCurve";
}

// The amendment's nodes that X3D has in another spelling (or as Group / Inline).
bool x3d_has_counterpart(const std::string& type) {
  return library_declares(type) || type == "NurbsTextureSurface" ||
         type == "NurbsPositionInterpolator" || type == "InlineLoadControl";
}

bool is_amendment_node(const std::string& type) { return x3d_has_counterpart(type) || type == "CoordinateDeformer"; }

// Nodes whose spellings differ by a field name (and the type): VRML97 type, X3D type, VRML97 field, X3D field.
struct Spelling {
  const char* vrml97_type;
  const char* x3d_type;
  const char* vrml97_field;
  const char* x3d_field;
};
const Spelling kSpellings[] = {
    {"NurbsCurve2D", "NurbsCurve2D", "point", "controlPoint"},
    {"Polyline2D", "ContourPolyline2D", "point", "controlPoint"},
    {"NurbsTextureSurface", "NurbsTextureCoordinate", "point", "controlPoint"},
    {"Switch", "Switch", "choice", "children"},
    {"LOD", "LOD", "level", "children"},
    {"Collision", "Collision", "collide", "enabled"},
};

// Where a ROUTE's field went: (DEF, field) -> (DEF, field).
using FieldMoves = std::map<std::pair<std::string, std::string>, std::pair<std::string, std::string>>;

// An event name split into its prefix, field and suffix: "set_point" -> {"set_", "point", ""}.
struct EventName {
  std::string prefix, field, suffix;
};
EventName split_event(const std::string& name) {
  if (name.starts_with("set_")) return {"set_", name.substr(4), ""};
  if (name.ends_with("_changed")) return {"", name.substr(0, name.size() - 8), "_changed"};
  return {"", name, ""};
}

// The DEF a VRML97 NURBS node gets from the X3D Coordinate whose points it took (and gives back).
const std::string kOwnerSuffix = "_owner";

class Translator {
 public:
  Translator(VrmlDialect source, VrmlDialect target) : source_(source), target_(target) {}

  void document(NodeDocument& d) {
    FieldMoves moves;
    std::swap(moves, moves_);
    for (auto& proto : d.protos) {
      for (auto& declaration : proto.interface)
        if (declaration.default_value) collect(*declaration.default_value);
      if (proto.body) document(*proto.body);
    }
    std::vector<NodePtr> nodes;
    for (const auto& root : d.roots) collect_into(root, nodes);
    for (const auto& node : nodes) translate(*node);
    for (auto& route : d.routes) {
      move_route_end(route.from_node, route.from_field);
      move_route_end(route.to_node, route.to_field);
    }
    declarations(d);
    if (target_ == VrmlDialect::vrml97 && !d.imports_exports.empty()) {
      for (size_t i = 0; i < d.imports_exports.size(); ++i) note("IMPORT/EXPORT dropped: VRML97 has none");
      d.imports_exports.clear();
    }
    d.dialect = target_;
    std::swap(moves, moves_);
  }

  std::vector<std::string> notes() const {
    std::vector<std::string> out;
    for (const auto& kind : order_) out.push_back(std::to_string(counts_.at(kind)) + " " + kind);
    return out;
  }

 private:
  void note(const std::string& kind) {
    if (counts_[kind]++ == 0) order_.push_back(kind);
  }

  void collect(const FieldValue& value) {
    std::vector<NodePtr> nodes;
    if (const auto* sf = std::get_if<SFNode>(&value)) collect_into(sf->node, nodes);
    if (const auto* mf = std::get_if<MFNode>(&value))
      for (const auto& n : mf->nodes) collect_into(n, nodes);
    for (const auto& node : nodes) translate(*node);
  }

  // Pre-order, each node once (a USE'd node is the DEF'd one).
  void collect_into(const NodePtr& node, std::vector<NodePtr>& out) {
    if (!node || !seen_.insert(node.get()).second) return;
    out.push_back(node);
    for (const auto& field : node->fields) {
      if (const auto* sf = std::get_if<SFNode>(&field.value)) collect_into(sf->node, out);
      if (const auto* mf = std::get_if<MFNode>(&field.value))
        for (const auto& n : mf->nodes) collect_into(n, out);
    }
  }

  void move_route_end(std::string& node, std::string& field) {
    EventName event = split_event(field);
    const auto it = moves_.find({node, event.field});
    if (it == moves_.end()) return;
    node = it->second.first;
    field = event.prefix + it->second.second + event.suffix;
  }

  static Field* field_of(Node& node, const std::string& name) {
    for (auto& f : node.fields)
      if (f.name == name) return &f;
    return nullptr;
  }

  void rename(Node& node, const std::string& from, const std::string& to) {
    if (Field* f = field_of(node, from)) f->name = to;
    for (auto& c : node.is_connections)
      if (c.node_field == from) c.node_field = to;
    if (!node.def_name.empty()) moves_[{node.def_name, from}] = {node.def_name, to};
  }

  // Drops field `name`, said once per kind when the file gave it.
  void drop(Node& node, const std::string& name, const std::string& why) {
    for (auto it = node.fields.begin(); it != node.fields.end(); ++it)
      if (it->name == name) {
        note(node.type + " " + name + " dropped: " + why);
        node.fields.erase(it);
        return;
      }
  }

  // MFVec3f field `name` -> a Coordinate node in it (X3D), DEF'd when ROUTEs may name the points: as
  // "<node>_<field>", or with its own name back where out_of_coordinate made the node "<name>_owner".
  void into_coordinate(Node& node, const std::string& name) {
    Field* f = field_of(node, name);
    if (!f || !std::holds_alternative<MFVec3f>(f->value)) return;
    const std::string owner = node.def_name;
    std::string coordinate_name = owner.empty() ? "" : owner + "_" + name;
    if (owner.ends_with(kOwnerSuffix)) {
      coordinate_name = owner.substr(0, owner.size() - kOwnerSuffix.size());
      node.def_name.clear();
    }
    NodePtr coordinate = make_node("Coordinate", coordinate_name);
    coordinate->fields.push_back(Field{"point", f->value, f->precision, f->line});
    f->value = SFNode{coordinate};
    if (!owner.empty()) moves_[{owner, name}] = {coordinate->def_name, "point"};
  }

  // A Coordinate (or CoordinateDouble) node in field `name` -> its points (VRML97).
  void out_of_coordinate(Node& node, const std::string& name, const std::string& to) {
    Field* f = field_of(node, name);
    if (!f) return;
    f->name = to;
    const auto* sf = std::get_if<SFNode>(&f->value);
    if (!sf) return;
    NodePtr coordinate = sf->node;
    MFVec3f points;
    if (coordinate)
      if (const auto* p = coordinate->get<MFVec3f>("point")) points = *p;
    f->value = points;
    if (coordinate && !coordinate->def_name.empty()) {
      if (node.def_name.empty()) node.def_name = coordinate->def_name + kOwnerSuffix;
      moves_[{coordinate->def_name, "point"}] = {node.def_name, to};
    }
  }

  void translate(Node& node) {
    if (node.proto_instance) return;
    if (source_ != target_) {
      if (target_ == VrmlDialect::x3d) to_x3d(node);
      else to_vrml97(node);
    }
    if (target_ == VrmlDialect::vrml97) {
      fit_library(node);
      if (node.type == "TrimmedSurface")
        if (const auto* s = node.get<SFNode>("surface"); s && s->node) fit_library(*s->node);
      // The amendment's nodes the library does not define stay declared by EXTERNPROTO.
      if (is_amendment_node(node.type) && !library_declares(node.type)) {
        node.proto_instance = true;
        needs_declaration_.insert(node.type);
      }
    }
  }

  void surface_to_x3d(Node& node) {
    drop(node, "ccw", "X3D's NURBS surfaces have no ccw");
    node.type = "NurbsPatchSurface";
    into_coordinate(node, "controlPoint");
  }

  // A node of kSpellings in the target's spelling; false when it is none.
  bool respell(Node& node) {
    const bool to_x3d = target_ == VrmlDialect::x3d;
    for (const auto& s : kSpellings)
      if (node.type == (to_x3d ? s.vrml97_type : s.x3d_type)) {
        node.type = to_x3d ? s.x3d_type : s.vrml97_type;
        rename(node, to_x3d ? s.vrml97_field : s.x3d_field, to_x3d ? s.x3d_field : s.vrml97_field);
        return true;
      }
    return false;
  }

  void to_x3d(Node& node) {
    const std::string type = node.type;
    if (respell(node)) return;
    if (type == "NurbsSurface") {
      surface_to_x3d(node);
    } else if (type == "TrimmedSurface") {
      node.type = "NurbsTrimmedSurface";
      std::vector<Field> fields;
      if (Field* s = field_of(node, "surface"))
        if (auto* sf = std::get_if<SFNode>(&s->value); sf && sf->node) {
          Node& surface = *sf->node;
          seen_.insert(&surface);
          if (surface.type == "NurbsSurface") surface_to_x3d(surface);
          fields = surface.fields;
        }
      for (auto& f : node.fields)
        if (f.name == "trimmingContour") fields.push_back(f);
      node.fields = std::move(fields);
    } else if (type == "NurbsCurve") {
      into_coordinate(node, "controlPoint");
    } else if (type == "NurbsPositionInterpolator") {
      rename(node, "keyValue", "controlPoint");
      into_coordinate(node, "controlPoint");
      rename(node, "keyWeight", "weight");
      for (auto it = node.fields.begin(); it != node.fields.end(); ++it)
        if (it->name == "dimension") {
          node.fields.erase(it);
          break;
        }
    } else if (type == "NurbsGroup") {
      node.type = "Group";
      drop(node, "tessellationScale", "X3D's Group has none");
    } else if (type == "InlineLoadControl") {
      node.type = "Inline";
    } else if (type == "CoordinateDeformer") {
      node.proto_instance = true;  // no X3D counterpart: declared by EXTERNPROTO
      needs_declaration_.insert(type);
    }
  }

  void surface_to_vrml97(Node& node) {
    node.type = "NurbsSurface";
    out_of_coordinate(node, "controlPoint", "controlPoint");
  }

  // The amendment's nodes are written with the cadnurbs PROTO library's declarations: fields they do
  // not declare (texCoord, uClosed...) are dropped.
  void fit_library(Node& node) {
    if (!library_declares(node.type)) return;
    for (const auto& proto : nurbs_protos())
      if (proto.name == node.type) {
        std::vector<std::string> undeclared;
        for (const auto& f : node.fields)
          if (!declares(proto, f.name)) undeclared.push_back(f.name);
        for (const auto& name : undeclared) drop(node, name, "the cadnurbs NURBS PROTO declares none");
      }
  }

  void to_vrml97(Node& node) {
    drop(node, "metadata", "VRML97 has no metadata");
    const std::string type = node.type;
    if (type == "NurbsCurve2D") drop(node, "closed", "the VRML97 NURBS proposal has none");
    if (respell(node)) return;
    if (type == "NurbsPatchSurface") {
      surface_to_vrml97(node);
    } else if (type == "NurbsTrimmedSurface") {
      node.type = "TrimmedSurface";
      NodePtr surface = make_node("NurbsSurface", node.def_name.empty() ? "" : node.def_name + "_surface");
      std::vector<Field> trimmed;
      for (auto& f : node.fields) {
        if (f.name == "trimmingContour") trimmed.push_back(f);
        else surface->fields.push_back(f);
      }
      // The ROUTEs to the Coordinate's points go to the new surface; to the trimmed node's own fields too.
      const std::string owner = node.def_name;
      surface_to_vrml97(*surface);
      if (!owner.empty())
        for (const auto& f : surface->fields) moves_[{owner, f.name}] = {surface->def_name, f.name};
      trimmed.insert(trimmed.begin(), Field{"surface", SFNode{surface}, {}, node.line});
      node.fields = std::move(trimmed);
    } else if (type == "NurbsCurve") {
      out_of_coordinate(node, "controlPoint", "controlPoint");
      drop(node, "closed", "the VRML97 NURBS proposal has none");
    } else if (type == "NurbsPositionInterpolator") {
      out_of_coordinate(node, "controlPoint", "keyValue");
      rename(node, "weight", "keyWeight");
    } else if (type == "IndexedTriangleSet") {
      triangle_set_to_face_set(node);
    } else if (type == "HAnimHumanoid" || type == "HAnimJoint" || type == "HAnimSite" || type == "HAnimSegment") {
      hanim_to_grouping(node);
    } else if (type == "ColorRGBA") {
      node.type = "Color";
      if (Field* f = field_of(node, "color"))
        if (const auto* words = std::get_if<FieldWords>(&f->value)) {
          MFVec3f rgb;
          for (size_t i = 0; i + 3 < words->words.size(); i += 4)
            rgb.values.emplace_back(std::stod(words->words[i]), std::stod(words->words[i + 1]), std::stod(words->words[i + 2]));
          f->value = rgb;
        }
      note("ColorRGBA written as Color: VRML97 has no alpha per colour");
    } else if (!node_schema(VrmlDialect::vrml97, type)) {
      node.proto_instance = true;  // an X3D node VRML97 lacks: declared by EXTERNPROTO
      needs_declaration_.insert(type);
      note(type + " declared by EXTERNPROTO urn:web3d:x3d:node:" + type + ": VRML97 has no such node");
    }
  }

  // Triangles as faces: the same geometry in VRML97's only indexed face node.
  void triangle_set_to_face_set(Node& node) {
    node.type = "IndexedFaceSet";
    if (Field* f = field_of(node, "index")) {
      MFInt32 faces;
      if (const auto* index = std::get_if<MFInt32>(&f->value))
        for (size_t i = 0; i < index->values.size(); ++i) {
          faces.values.push_back(index->values[i]);
          if (i % 3 == 2) faces.values.push_back(-1);
        }
      f->name = "coordIndex";
      f->value = faces;
    }
    note("IndexedTriangleSet written as IndexedFaceSet: VRML97 has no triangle sets");
  }

  // HAnim joints and sites are placed like Transforms, segments and the humanoid's skeleton grouped:
  // the geometry keeps its place; the HAnim data (names, limits, skin weights) has no VRML97 form.
  void hanim_to_grouping(Node& node) {
    const std::string from = node.type;
    const bool placed = from != "HAnimSegment";
    static const std::set<std::string> transform_fields = {"translation", "rotation", "scale", "scaleOrientation",
                                                           "center", "bboxCenter", "bboxSize", "children"};
    std::vector<Field> kept;
    MFNode children;
    for (auto& f : node.fields) {
      if (from == "HAnimHumanoid" && (f.name == "skeleton" || f.name == "skin")) {
        if (const auto* mf = std::get_if<MFNode>(&f.value))
          children.nodes.insert(children.nodes.end(), mf->nodes.begin(), mf->nodes.end());
      } else if (f.name == "children") {
        if (const auto* mf = std::get_if<MFNode>(&f.value))
          children.nodes.insert(children.nodes.end(), mf->nodes.begin(), mf->nodes.end());
      } else if (transform_fields.count(f.name) && (placed || f.name.starts_with("bbox"))) {
        kept.push_back(f);
      }
    }
    kept.push_back(Field{"children", children, {}, node.line});
    node.fields = std::move(kept);
    node.type = placed ? "Transform" : "Group";
    note(from + " written as " + node.type + ": VRML97 has no HAnim; its joint data is dropped");
  }

  // Drops the declarations the target has built in or the writer makes; adds EXTERNPROTOs for the nodes
  // that became PROTO instances.
  void declarations(NodeDocument& d) {
    std::vector<ProtoDeclaration> kept;
    std::set<std::string> declared;
    for (auto& proto : d.protos) {
      const bool built_in = target_ == VrmlDialect::x3d ? x3d_has_counterpart(proto.name) : library_declares(proto.name);
      if (built_in) continue;
      declared.insert(proto.name);
      kept.push_back(std::move(proto));
    }
    for (const auto& type : needs_declaration_) {
      if (declared.count(type)) continue;
      ProtoDeclaration proto;
      proto.name = type;
      proto.external = true;
      const bool amendment = is_amendment_node(type);
      const NodeSchema* schema = node_schema(amendment ? VrmlDialect::vrml97 : VrmlDialect::x3d, type);
      if (schema)
        for (const auto& f : schema->fields)
          if (f.name != "metadata")
            proto.interface.push_back(InterfaceDeclaration{access_name(f.access), f.type_name, f.name, std::nullopt});
      if (amendment) {
        proto.urls = {"urn:web3d:vrml97:node:" + type, "urn:inet:blaxxun.com:node:" + type, type + "PROTO.wrl",
                      "http://wdune.ourproject.org/docs/vrml97Amendment1/" + type + "PROTO.wrl"};
        if (type == "NurbsPositionInterpolator") proto.urls.insert(proto.urls.begin(), "cadnurbs-nurbs-protos.wrl#" + type);
      } else {
        proto.urls = {"urn:web3d:x3d:node:" + type};
      }
      kept.insert(kept.begin(), std::move(proto));
    }
    needs_declaration_.clear();
    d.protos = std::move(kept);
  }

  static std::string access_name(FieldAccess access) {
    switch (access) {
      case FieldAccess::initialize_only: return "initializeOnly";
      case FieldAccess::input_output: return "inputOutput";
      case FieldAccess::input_only: return "inputOnly";
      case FieldAccess::output_only: return "outputOnly";
    }
    return "inputOutput";
  }

  VrmlDialect source_, target_;
  FieldMoves moves_;
  std::set<const Node*> seen_;
  std::set<std::string> needs_declaration_;
  std::map<std::string, size_t> counts_;
  std::vector<std::string> order_;
};

}  // namespace

std::vector<std::string> translate_dialect(NodeDocument& document, VrmlDialect target) {
  Translator translator(document.dialect, target);
  translator.document(document);
  return translator.notes();
}

}  // namespace cadnurbs
