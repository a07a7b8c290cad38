#pragma once
// For each node type of VRML97 (with the NURBS nodes of its amendment) and of X3D 4.0: its fields with
// their types and access, and the default containerField of the XML encoding. The parsers need it
// (classic text does not say what type a value is; an XML attribute does not say whether it holds one
// string or several). X3D's nodes come from the standard's table (x3d_standard_nodes.hpp); VRML97 uses
// them with VRML97's own names where they differ (Switch choice, LOD level, Collision collide) and the
// NURBS proposal's nodes (NurbsSurface, TrimmedSurface, NurbsCurve2D, Polyline2D, NurbsGroup,
// NurbsTextureSurface, NurbsPositionInterpolator, CoordinateDeformer, InlineLoadControl).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/vrml/node_graph.hpp"

namespace cadnurbs {

// How a field's value is held (node_graph.hpp's FieldValue alternatives). X3D's double types share the
// single precision ones (SFDouble, SFTime -> SFFloat; MFDouble, MFTime -> MFFloat; MFVec3d -> MFVec3f...);
// types the Scene mapping never reads (SFVec2f, SFVec4f, SFColorRGBA, SFImage, SFMatrix*, MFBool,
// MFColorRGBA, MFRotation, MFVec4f, MFMatrix*...) are kept as their words (FieldWords).
enum class FieldType {
  SFBool, SFInt32, SFFloat, SFString, MFFloat, MFInt32, MFVec2f, MFVec3f, MFString,
  SFColor, SFVec3f, SFRotation, SFNode, MFNode, SFWords, MFWords
};

enum class FieldAccess { initialize_only, input_output, input_only, output_only };

struct FieldSchema {
  std::string name;
  FieldType type;
  std::string type_name;  // as the standard spells it: "SFTime", "MFVec3d"...
  FieldAccess access = FieldAccess::input_output;
};

struct NodeSchema {
  std::string type;
  std::string container_field;  // the field an X3D XML child element fills by default
  std::vector<FieldSchema> fields;
};

// The schema of node `type` in `dialect`, or null for a node the standard does not have.
const NodeSchema* node_schema(VrmlDialect dialect, std::string_view type);

// The schema of field `name` of the node, or null.
const FieldSchema* find_field(const NodeSchema& schema, std::string_view name);

// The type of field `name` of the node, or nothing when the node has no such field.
std::optional<FieldType> field_type(const NodeSchema& schema, std::string_view name);

// A field of a standard type name ("SFTime", "MFNode"...), as a PROTO interface or a Script declares it;
// null when the name is not a field type.
std::optional<FieldSchema> declared_field(std::string name, std::string_view type_name, FieldAccess access);

// The access of a declaration keyword: field/initializeOnly, exposedField/inputOutput, eventIn/inputOnly,
// eventOut/outputOnly; nothing for any other word.
std::optional<FieldAccess> declaration_access(std::string_view keyword);

// Whether nodes of `type` carry fields the file declares ("field SFFloat x 1" / <field>): Script and
// the shader nodes.
bool declares_own_fields(std::string_view type);

// How many words one value of a FieldWords type holds (SFVec2f 2, SFColorRGBA 4, SFMatrix4f 16...);
// 0 for SFImage / MFImage, whose length its first three numbers say.
int words_per_value(std::string_view type_name);

}  // namespace cadnurbs
