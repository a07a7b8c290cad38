#pragma once
// A small generic VRML/X3D node graph: the one form between the Scene mapping and the text encodings,
// so that Scene <-> nodes is written once and VRML97, X3D classic and X3D XML differ only in spelling.
#include <Eigen/Core>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "core/number_format.hpp"

namespace cadnurbs {

struct Node;
using NodePtr = std::shared_ptr<Node>;

// Field values. Single precision VRML types (SFFloat, MFFloat, MFVec3f...) and their X3D double
// counterparts (SFDouble, MFDouble, MFVec3d...) share one alternative: values are doubles either way.
struct MFFloat { std::vector<double> values; };
struct MFInt32 { std::vector<int> values; };
struct MFVec2f { std::vector<Eigen::Vector2d> values; };
struct MFVec3f { std::vector<Eigen::Vector3d> values; };
struct MFString { std::vector<std::string> values; };
struct SFColor { Eigen::Vector3d value = Eigen::Vector3d::Zero(); };
struct SFVec3f { Eigen::Vector3d value = Eigen::Vector3d::Zero(); };
struct SFRotation { Eigen::Vector3d axis = Eigen::Vector3d::UnitZ(); double angle = 0.0; };
// A value of a type the Scene mapping never reads, kept as its words (numbers, TRUE/FALSE) so that it
// can be written again: one value of `type_name` or, for an MF type, any number of them.
struct FieldWords {
  std::string type_name;  // "SFVec2f", "MFColorRGBA"...
  std::vector<std::string> words;
};
struct SFNode { NodePtr node; };  // null: NULL
struct MFNode { std::vector<NodePtr> nodes; };

using FieldValue = std::variant<bool, int, double, std::string, MFFloat, MFInt32, MFVec2f, MFVec3f, MFString,
                                SFColor, SFVec3f, SFRotation, SFNode, MFNode, FieldWords>;

struct Field {
  std::string name;
  FieldValue value;
  NumberPrecision precision;  // how the numbers of this field are written
  int line = 0;               // where it was read (0 for fields built in memory)
};

// A field as a PROTO interface or a Script node declares it.
struct InterfaceDeclaration {
  std::string access;     // as written: field, exposedField, eventIn, eventOut, initializeOnly...
  std::string type_name;  // "SFFloat", "MFNode"...
  std::string name;
  std::optional<FieldValue> default_value;  // a PROTO's field or exposedField (a Script's are its fields)
};

// Inside a PROTO body: field `node_field` of a node IS the PROTO's `proto_field`.
struct IsConnection {
  std::string node_field, proto_field;
};

struct Node {
  std::string type;      // "Transform", "NurbsPatchSurface"... or the name of a PROTO
  std::string def_name;  // empty unless DEF'd; a node reached twice in a graph is written once, then USE'd
  std::vector<Field> fields;  // in writing order
  int line = 0;               // where it was read (0 for nodes built in memory)
  bool proto_instance = false;  // an instance of a PROTO or EXTERNPROTO the file declares
  std::vector<InterfaceDeclaration> declarations;  // a Script's (or shader's) own fields
  std::vector<IsConnection> is_connections;        // in a PROTO body

  // The field called `name`, or null.
  const Field* find(std::string_view name) const;

  // The value of field `name` when it holds a T; null when the field is absent or holds another type.
  template <class T>
  const T* get(std::string_view name) const {
    const Field* field = find(name);
    return field ? std::get_if<T>(&field->value) : nullptr;
  }

  // Appends a field (or replaces the value of an existing one of that name).
  void set(std::string name, FieldValue value, NumberPrecision precision = {});
};

// A new node of `type`, DEF'd as `def_name` when that is not empty.
NodePtr make_node(std::string type, std::string def_name = {});

// A file's worth of nodes: the dialect decides the NURBS node names and field types.
enum class VrmlDialect { vrml97, x3d };

// ROUTE from_node.from_field TO to_node.to_field (DEF names).
struct Route {
  std::string from_node, from_field, to_node, to_field;
  int line = 0;
};

struct NodeDocument;

// IMPORT inline_def.name [AS as] (import), or EXPORT name [AS as].
struct ImportExport {
  bool import = false;
  std::string inline_def;  // IMPORT only: the DEF of the Inline
  std::string name;        // IMPORT: the name the Inline's file EXPORTs; EXPORT: a local DEF
  std::string as;          // empty: not given
};

// A PROTO or EXTERNPROTO declaration.
struct ProtoDeclaration {
  std::string name;
  bool external = false;
  std::vector<InterfaceDeclaration> interface;
  std::vector<std::string> urls;         // an EXTERNPROTO's
  std::shared_ptr<NodeDocument> body;   // a PROTO's nodes, ROUTEs and PROTOs, in their own DEF scope
  int line = 0;
};

struct NodeDocument {
  VrmlDialect dialect = VrmlDialect::x3d;
  std::vector<NodePtr> roots;  // top-level nodes in file order
  std::vector<Route> routes;
  std::vector<ProtoDeclaration> protos;
  std::vector<ImportExport> imports_exports;
  std::string profile = "Interchange";       // X3D: the profile the writers declare
};

// Calls `visit` once for every node of the document: its roots' graphs and its PROTOs' bodies and
// defaults (each node once, however often USE'd).
void for_each_node(const NodeDocument& document, const std::function<void(const Node&)>& visit);

// Calls `visit` once for every node of the document's own DEF name scope: its roots' graphs, not its
// PROTOs (each of which is a scope of its own).
void for_each_scope_node(NodeDocument& document, const std::function<void(Node&)>& visit);

// The declaration keyword of an access ("exposedField", "inputOutput"...) in `dialect`'s spelling.
std::string access_keyword(const std::string& access, VrmlDialect dialect);

}  // namespace cadnurbs
