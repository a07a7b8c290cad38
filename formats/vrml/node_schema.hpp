#pragma once
// The subset of VRML97 and X3D that cadnurbs writes and reads: for each node type, its fields and their
// types. The parsers need it (classic text does not say what type a value is); the XML encoding needs
// the default containerField. A node or field not listed here is outside the subset.
#include <optional>
#include <string_view>
#include <vector>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

enum class FieldType {
  SFBool, SFInt32, SFFloat, SFString, MFFloat, MFInt32, MFVec2f, MFVec3f, MFString,
  SFColor, SFVec3f, SFRotation, SFNode, MFNode
};

struct FieldSchema {
  std::string_view name;
  FieldType type;
};

struct NodeSchema {
  std::string_view type;
  std::string_view container_field;  // the field an X3D XML child element fills by default
  std::vector<FieldSchema> fields;
};

// The schema of node `type` in `dialect`, or null when the node is outside the subset.
const NodeSchema* node_schema(VrmlDialect dialect, std::string_view type);

// The type of field `name` of the node, or nothing when the node has no such field in the subset.
std::optional<FieldType> field_type(const NodeSchema& schema, std::string_view name);

}  // namespace cadnurbs
