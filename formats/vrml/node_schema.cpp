#include "formats/vrml/node_schema.hpp"

namespace cadnurbs {

namespace {

using T = FieldType;

// Nodes spelled the same way in both dialects. Fields that only steer rendering (bounding boxes,
// lighting, tessellation hints, navigation) are listed so that files using them still read; the
// Scene mapping ignores them.
std::vector<NodeSchema> common_nodes() {
  return {
      {"Group", "children", {{"children", T::MFNode}, {"bboxCenter", T::SFVec3f}, {"bboxSize", T::SFVec3f}}},
      {"Transform",
       "children",
       {{"children", T::MFNode},
        {"translation", T::SFVec3f},
        {"rotation", T::SFRotation},
        {"scale", T::SFVec3f},
        {"scaleOrientation", T::SFRotation},
        {"center", T::SFVec3f},
        {"bboxCenter", T::SFVec3f},
        {"bboxSize", T::SFVec3f}}},
      {"Shape", "children", {{"appearance", T::SFNode}, {"geometry", T::SFNode}}},
      {"Appearance", "appearance", {{"material", T::SFNode}}},
      {"Material",
       "material",
       {{"diffuseColor", T::SFColor},
        {"emissiveColor", T::SFColor},
        {"specularColor", T::SFColor},
        {"ambientIntensity", T::SFFloat},
        {"shininess", T::SFFloat},
        {"transparency", T::SFFloat}}},
      {"WorldInfo", "children", {{"title", T::SFString}, {"info", T::MFString}}},
      {"NavigationInfo",
       "children",
       {{"type", T::MFString},
        {"headlight", T::SFBool},
        {"speed", T::SFFloat},
        {"avatarSize", T::MFFloat},
        {"visibilityLimit", T::SFFloat},
        {"transitionType", T::MFString},
        {"transitionTime", T::SFFloat}}},
      {"Viewpoint",
       "children",
       {{"position", T::SFVec3f},
        {"orientation", T::SFRotation},
        {"fieldOfView", T::SFFloat},
        {"description", T::SFString},
        {"jump", T::SFBool},
        {"centerOfRotation", T::SFVec3f}}},
      {"IndexedFaceSet",
       "geometry",
       {{"coord", T::SFNode},
        {"coordIndex", T::MFInt32},
        {"normal", T::SFNode},
        {"normalIndex", T::MFInt32},
        {"normalPerVertex", T::SFBool},
        {"creaseAngle", T::SFFloat},
        {"solid", T::SFBool},
        {"ccw", T::SFBool},
        {"convex", T::SFBool}}},
      {"IndexedLineSet", "geometry", {{"coord", T::SFNode}, {"coordIndex", T::MFInt32}, {"colorPerVertex", T::SFBool}}},
      {"Box", "geometry", {{"size", T::SFVec3f}, {"solid", T::SFBool}}},
      {"Coordinate", "coord", {{"point", T::MFVec3f}}},
      {"Normal", "normal", {{"vector", T::MFVec3f}}},
      {"Contour2D", "trimmingContour", {{"children", T::MFNode}}},
  };
}

// VRML97 with the NURBS nodes of the VRML97 amendment (blaxxun proposal).
std::vector<NodeSchema> vrml97_nodes() {
  auto nodes = common_nodes();
  const std::vector<FieldSchema> surface_fields = {
      {"uDimension", T::SFInt32},    {"vDimension", T::SFInt32},    {"uKnot", T::MFFloat},
      {"vKnot", T::MFFloat},         {"uOrder", T::SFInt32},        {"vOrder", T::SFInt32},
      {"controlPoint", T::MFVec3f},  {"weight", T::MFFloat},        {"uTessellation", T::SFInt32},
      {"vTessellation", T::SFInt32}, {"ccw", T::SFBool},            {"solid", T::SFBool}};
  nodes.push_back({"NurbsSurface", "geometry", surface_fields});
  nodes.push_back({"TrimmedSurface", "geometry", {{"surface", T::SFNode}, {"trimmingContour", T::MFNode}}});
  nodes.push_back({"NurbsCurve2D",
                   "children",
                   {{"point", T::MFVec2f},
                    {"knot", T::MFFloat},
                    {"order", T::SFInt32},
                    {"weight", T::MFFloat},
                    {"tessellation", T::SFInt32}}});
  nodes.push_back({"Polyline2D", "children", {{"point", T::MFVec2f}}});
  nodes.push_back({"NurbsCurve",
                   "geometry",
                   {{"controlPoint", T::MFVec3f},
                    {"knot", T::MFFloat},
                    {"order", T::SFInt32},
                    {"weight", T::MFFloat},
                    {"tessellation", T::SFInt32}}});
  nodes.push_back({"NurbsGroup",
                   "children",
                   {{"children", T::MFNode},
                    {"tessellationScale", T::SFFloat},
                    {"bboxCenter", T::SFVec3f},
                    {"bboxSize", T::SFVec3f}}});
  return nodes;
}

// X3D 3.x with the NURBS component.
std::vector<NodeSchema> x3d_nodes() {
  auto nodes = common_nodes();
  std::vector<FieldSchema> surface_fields = {
      {"uDimension", T::SFInt32},    {"vDimension", T::SFInt32}, {"uKnot", T::MFFloat},
      {"vKnot", T::MFFloat},         {"uOrder", T::SFInt32},     {"vOrder", T::SFInt32},
      {"controlPoint", T::SFNode},   {"weight", T::MFFloat},     {"uTessellation", T::SFInt32},
      {"vTessellation", T::SFInt32}, {"uClosed", T::SFBool},     {"vClosed", T::SFBool},
      {"solid", T::SFBool}};
  nodes.push_back({"NurbsPatchSurface", "geometry", surface_fields});
  surface_fields.push_back({"trimmingContour", T::MFNode});
  nodes.push_back({"NurbsTrimmedSurface", "geometry", surface_fields});
  nodes.push_back({"NurbsCurve2D",
                   "children",
                   {{"controlPoint", T::MFVec2f},
                    {"knot", T::MFFloat},
                    {"order", T::SFInt32},
                    {"weight", T::MFFloat},
                    {"tessellation", T::SFInt32},
                    {"closed", T::SFBool}}});
  // The X3D 3.0 DTD gives ContourPolyline2D containerField "children", view3dscene takes "geometry": with
  // "geometry" here the XML writer always spells it out, and the XML parser falls back to "children".
  nodes.push_back({"ContourPolyline2D", "geometry", {{"controlPoint", T::MFVec2f}}});
  nodes.push_back({"NurbsCurve",
                   "geometry",
                   {{"controlPoint", T::SFNode},
                    {"knot", T::MFFloat},
                    {"order", T::SFInt32},
                    {"weight", T::MFFloat},
                    {"tessellation", T::SFInt32},
                    {"closed", T::SFBool}}});
  nodes.push_back({"CoordinateDouble", "coord", {{"point", T::MFVec3f}}});
  return nodes;
}

const std::vector<NodeSchema>& nodes_of(VrmlDialect dialect) {
  static const std::vector<NodeSchema> vrml97 = vrml97_nodes();
  static const std::vector<NodeSchema> x3d = x3d_nodes();
  return dialect == VrmlDialect::vrml97 ? vrml97 : x3d;
}

}  // namespace

const NodeSchema* node_schema(VrmlDialect dialect, std::string_view type) {
  for (const auto& schema : nodes_of(dialect))
    if (schema.type == type) return &schema;
  return nullptr;
}

std::optional<FieldType> field_type(const NodeSchema& schema, std::string_view name) {
  for (const auto& field : schema.fields)
    if (field.name == name) return field.type;
  return std::nullopt;
}

}  // namespace cadnurbs
