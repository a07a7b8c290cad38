#include "formats/vrml/node_schema.hpp"

#include <map>
#include <sstream>

#include "formats/vrml/x3d_standard_nodes.hpp"

namespace cadnurbs {

namespace {

using T = FieldType;
using A = FieldAccess;

// Standard type names to the way their values are held.
const std::map<std::string_view, FieldType>& held_as() {
  static const std::map<std::string_view, FieldType> table = {
      {"SFBool", T::SFBool},       {"SFInt32", T::SFInt32},     {"SFFloat", T::SFFloat},
      {"SFDouble", T::SFFloat},    {"SFTime", T::SFFloat},      {"SFString", T::SFString},
      {"MFFloat", T::MFFloat},     {"MFDouble", T::MFFloat},    {"MFTime", T::MFFloat},
      {"MFInt32", T::MFInt32},     {"MFVec2f", T::MFVec2f},     {"MFVec2d", T::MFVec2f},
      {"MFVec3f", T::MFVec3f},     {"MFVec3d", T::MFVec3f},     {"MFColor", T::MFVec3f},
      {"MFString", T::MFString},   {"SFColor", T::SFColor},     {"SFVec3f", T::SFVec3f},
      {"SFVec3d", T::SFVec3f},     {"SFRotation", T::SFRotation}, {"SFNode", T::SFNode},
      {"MFNode", T::MFNode},       {"SFVec2f", T::SFWords},     {"SFVec2d", T::SFWords},
      {"SFVec4f", T::SFWords},     {"SFVec4d", T::SFWords},     {"SFColorRGBA", T::SFWords},
      {"SFImage", T::SFWords},     {"SFMatrix3f", T::SFWords},  {"SFMatrix3d", T::SFWords},
      {"SFMatrix4f", T::SFWords},  {"SFMatrix4d", T::SFWords},  {"MFBool", T::MFWords},
      {"MFColorRGBA", T::MFWords}, {"MFRotation", T::MFWords},  {"MFVec4f", T::MFWords},
      {"MFVec4d", T::MFWords},     {"MFImage", T::MFWords},     {"MFMatrix3f", T::MFWords},
      {"MFMatrix3d", T::MFWords},  {"MFMatrix4f", T::MFWords},  {"MFMatrix4d", T::MFWords},
  };
  return table;
}

FieldSchema field(std::string name, std::string_view type_name, A access = A::input_output) {
  return *declared_field(std::move(name), type_name, access);
}

NodeSchema standard_node(const StandardNodeRow& row) {
  NodeSchema schema{row.type, row.container_field, {}};
  std::istringstream words(row.fields);
  std::string word;
  while (words >> word) {
    const size_t a = word.find(':'), b = word.rfind(':');
    const char letter = word[b + 1];
    const A access = letter == 'f' ? A::initialize_only : letter == 'e' ? A::input_output
                     : letter == 'i' ? A::input_only : A::output_only;
    schema.fields.push_back(field(word.substr(0, a), word.substr(a + 1, b - a - 1), access));
  }
  return schema;
}

using SchemaTable = std::map<std::string, NodeSchema, std::less<>>;

SchemaTable x3d_nodes() {
  SchemaTable table;
  for (const auto& row : x3d_standard_nodes()) table.emplace(row.type, standard_node(row));
  // The X3D 3.0 DTD gives ContourPolyline2D containerField "children", view3dscene takes "geometry": with
  // "geometry" here the XML writer always spells it out, and the XML parser falls back to "children".
  table.at("ContourPolyline2D").container_field = "geometry";
  return table;
}

void rename_field(NodeSchema& schema, std::string_view from, std::string to) {
  for (auto& f : schema.fields)
    if (f.name == from) f.name = std::move(to);
}

// VRML97's 54 nodes, with X3D's fields under VRML97's names, and the NURBS nodes of the VRML97 amendment
// (the blaxxun proposal, as white_dune declares them).
SchemaTable vrml97_nodes() {
  static const char* const vrml97_types[] = {
      "Anchor", "Appearance", "AudioClip", "Background", "Billboard", "Box", "Collision", "Color",
      "ColorInterpolator", "Cone", "Coordinate", "CoordinateInterpolator", "Cylinder", "CylinderSensor",
      "DirectionalLight", "ElevationGrid", "Extrusion", "Fog", "FontStyle", "Group", "ImageTexture",
      "IndexedFaceSet", "IndexedLineSet", "Inline", "LOD", "Material", "MovieTexture", "NavigationInfo", "Normal",
      "NormalInterpolator", "OrientationInterpolator", "PixelTexture", "PlaneSensor", "PointLight", "PointSet",
      "PositionInterpolator", "ProximitySensor", "ScalarInterpolator", "Script", "Shape", "Sound", "Sphere",
      "SphereSensor", "SpotLight", "Switch", "Text", "TextureCoordinate", "TextureTransform", "TimeSensor",
      "TouchSensor", "Transform", "Viewpoint", "VisibilitySensor", "WorldInfo"};
  const SchemaTable x3d = x3d_nodes();
  SchemaTable table;
  for (const char* type : vrml97_types) table.emplace(type, x3d.at(type));
  rename_field(table.at("Switch"), "children", "choice");
  rename_field(table.at("LOD"), "children", "level");
  rename_field(table.at("Collision"), "enabled", "collide");
  auto add = [&](NodeSchema schema) { table[schema.type] = std::move(schema); };
  const std::vector<FieldSchema> surface_fields = {
      field("uDimension", "SFInt32", A::initialize_only), field("vDimension", "SFInt32", A::initialize_only),
      field("uKnot", "MFFloat", A::initialize_only),      field("vKnot", "MFFloat", A::initialize_only),
      field("uOrder", "SFInt32", A::initialize_only),     field("vOrder", "SFInt32", A::initialize_only),
      field("controlPoint", "MFVec3f"),                   field("weight", "MFFloat"),
      field("uTessellation", "SFInt32"),                  field("vTessellation", "SFInt32"),
      field("texCoord", "SFNode"),                        field("ccw", "SFBool", A::initialize_only),
      field("solid", "SFBool", A::initialize_only)};
  add({"NurbsSurface", "geometry", surface_fields});
  add({"NurbsTextureSurface",
       "texCoord",
       {field("uDimension", "SFInt32", A::initialize_only), field("vDimension", "SFInt32", A::initialize_only),
        field("uKnot", "MFFloat", A::initialize_only), field("vKnot", "MFFloat", A::initialize_only),
        field("uOrder", "SFInt32", A::initialize_only), field("vOrder", "SFInt32", A::initialize_only),
        field("point", "MFVec2f"), field("weight", "MFFloat")}});
  add({"TrimmedSurface",
       "geometry",
       {field("surface", "SFNode"), field("trimmingContour", "MFNode"), field("addTrimmingContour", "MFNode", A::input_only),
        field("removeTrimmingContour", "MFNode", A::input_only)}});
  add({"Contour2D",
       "trimmingContour",
       {field("children", "MFNode"), field("addChildren", "MFNode", A::input_only),
        field("removeChildren", "MFNode", A::input_only)}});
  add({"NurbsCurve2D",
       "children",
       {field("point", "MFVec2f"), field("knot", "MFFloat", A::initialize_only),
        field("order", "SFInt32", A::initialize_only), field("weight", "MFFloat"), field("tessellation", "SFInt32")}});
  add({"Polyline2D", "children", {field("point", "MFVec2f")}});
  add({"NurbsCurve",
       "geometry",
       {field("controlPoint", "MFVec3f"), field("knot", "MFFloat", A::initialize_only),
        field("order", "SFInt32", A::initialize_only), field("weight", "MFFloat"), field("tessellation", "SFInt32")}});
  add({"NurbsGroup",
       "children",
       {field("children", "MFNode"), field("tessellationScale", "SFFloat"),
        field("bboxCenter", "SFVec3f", A::initialize_only), field("bboxSize", "SFVec3f", A::initialize_only),
        field("addChildren", "MFNode", A::input_only), field("removeChildren", "MFNode", A::input_only)}});
  add({"NurbsPositionInterpolator",
       "children",
       {field("set_fraction", "SFFloat", A::input_only), field("dimension", "SFInt32"), field("keyValue", "MFVec3f"),
        field("keyWeight", "MFFloat"), field("knot", "MFFloat"), field("order", "SFInt32"),
        field("value_changed", "SFVec3f", A::output_only)}});
  add({"CoordinateDeformer",
       "children",
       {field("addChildren", "MFNode", A::input_only), field("removeChildren", "MFNode", A::input_only),
        field("children", "MFNode"), field("controlPoint", "MFVec3f"), field("inputCoord", "MFNode"),
        field("inputTransform", "MFNode"), field("outputCoord", "MFNode"), field("weight", "MFFloat"),
        field("bboxCenter", "SFVec3f", A::initialize_only), field("bboxSize", "SFVec3f", A::initialize_only),
        field("uDimension", "SFInt32", A::initialize_only), field("vDimension", "SFInt32", A::initialize_only),
        field("wDimension", "SFInt32", A::initialize_only), field("uKnot", "MFFloat", A::initialize_only),
        field("vKnot", "MFFloat", A::initialize_only), field("wKnot", "MFFloat", A::initialize_only),
        field("uOrder", "SFInt32", A::initialize_only), field("vOrder", "SFInt32", A::initialize_only),
        field("wOrder", "SFInt32", A::initialize_only)}});
  add({"InlineLoadControl",
       "children",
       {field("load", "SFBool"), field("url", "MFString"), field("bboxCenter", "SFVec3f", A::initialize_only),
        field("bboxSize", "SFVec3f", A::initialize_only), field("children", "MFNode", A::output_only)}});
  return table;
}

const SchemaTable& nodes_of(VrmlDialect dialect) {
  static const SchemaTable vrml97 = vrml97_nodes();
  static const SchemaTable x3d = x3d_nodes();
  return dialect == VrmlDialect::vrml97 ? vrml97 : x3d;
}

}  // namespace

const NodeSchema* node_schema(VrmlDialect dialect, std::string_view type) {
  const auto& table = nodes_of(dialect);
  const auto it = table.find(type);
  return it == table.end() ? nullptr : &it->second;
}

const FieldSchema* find_field(const NodeSchema& schema, std::string_view name) {
  for (const auto& f : schema.fields)
    if (f.name == name) return &f;
  return nullptr;
}

std::optional<FieldType> field_type(const NodeSchema& schema, std::string_view name) {
  const FieldSchema* f = find_field(schema, name);
  if (!f) return std::nullopt;
  return f->type;
}

std::optional<FieldSchema> declared_field(std::string name, std::string_view type_name, FieldAccess access) {
  const auto& table = held_as();
  const auto it = table.find(type_name);
  if (it == table.end()) return std::nullopt;
  return FieldSchema{std::move(name), it->second, std::string(type_name), access};
}

std::optional<FieldAccess> declaration_access(std::string_view keyword) {
  if (keyword == "field" || keyword == "initializeOnly") return A::initialize_only;
  if (keyword == "exposedField" || keyword == "inputOutput") return A::input_output;
  if (keyword == "eventIn" || keyword == "inputOnly") return A::input_only;
  if (keyword == "eventOut" || keyword == "outputOnly") return A::output_only;
  return std::nullopt;
}

bool declares_own_fields(std::string_view type) {
  return type == "Script" || type == "ComposedShader" || type == "PackagedShader" || type == "ShaderProgram";
}

int words_per_value(std::string_view type_name) {
  const std::string_view base = type_name.substr(2);
  if (base == "Bool" || base == "Time") return 1;
  if (base == "Vec2f" || base == "Vec2d") return 2;
  if (base == "Color" || base == "Vec3f" || base == "Vec3d") return 3;
  if (base == "Vec4f" || base == "Vec4d" || base == "ColorRGBA" || base == "Rotation") return 4;
  if (base == "Matrix3f" || base == "Matrix3d") return 9;
  if (base == "Matrix4f" || base == "Matrix4d") return 16;
  return 0;  // Image
}

}  // namespace cadnurbs
