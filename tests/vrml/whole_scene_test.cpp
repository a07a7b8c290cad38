// Whole scene graphs: every node of the standards, PROTOs, Scripts and ROUTEs are read; the Scene is the
// geometry at rest, and what has no place in it is named in one note per kind.
#include <gtest/gtest.h>

#include "formats/common/file_io.hpp"
#include "formats/vrml/classic_parser.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/xml_parser.hpp"

namespace cadnurbs {
namespace {

// A bilinear patch whose Coordinate a looping animation moves: its first key set is (0 0 5)... .
const std::string animated_patch =
    "Shape { appearance Appearance { material Material { diffuseColor 1 0 0 }\n"
    "                                texture ImageTexture { url \"wood.png\" } }\n"
    "  geometry NurbsPatchSurface { uDimension 2 vDimension 2 uOrder 2 vOrder 2\n"
    "    controlPoint DEF C Coordinate { point [0 0 0 1 0 0 0 1 0 1 1 0] }\n"
    "    texCoord TextureCoordinate { point [0 0 1 0 0 1 1 1] } } }\n"
    "DEF T TimeSensor { loop TRUE cycleInterval 4 }\n"
    "DEF I CoordinateInterpolator { key [0 1]\n"
    "  keyValue [0 0 5 1 0 5 0 1 5 1 1 5  0 0 9 1 0 9 0 1 9 1 1 9] }\n"
    "ROUTE T.fraction_changed TO I.set_fraction\n"
    "ROUTE I.value_changed TO C.set_point\n";

TEST(WholeScene, ClassicScenesAreReadAtRestWithANotePerKindLeftOut) {
  const std::string text =
      "#X3D V3.3 utf8\nPROFILE Immersive\n"
      "PROTO Blob [ field SFFloat size 1 exposedField SFNode look NULL eventIn SFTime go ] { Group {} }\n"
      "EXTERNPROTO Far [ field SFFloat size ] \"far.x3dv#Far\"\n" +
      animated_patch +
      "Switch { whichChoice 1 children [ Shape { geometry Box {} } Shape { geometry Sphere { radius 2 } } ] }\n"
      "LOD { range [10] children [ Shape { geometry Box { size 1 1 1 } } Shape { geometry Box {} } ] }\n"
      "Transform { scale 0 0 0 children Shape { geometry Box {} } }\n"
      "Shape { geometry Text { string \"hi\" } }\n"
      "Shape { geometry Blob { size 3 } }\n"
      "Far { size 2 }\n"
      "DEF S Script { field SFVec2f offset 1 2 eventOut SFTime out url \"javascript: function initialize() {}\" }\n"
      "DirectionalLight { direction 0 0 -1 color 1 1 0.5 }\n"
      "Background { skyColor [0 0 1, 1 1 1] skyAngle [1.5] }\n"
      "ROUTE S.out TO T.set_startTime\n"
      "EXPORT S AS Other\n";
  const SceneFromNodes read = parse_vrml_scene(text, "t.x3dv");
  const SceneCounts c = count_entities(read.scene);
  // The patch, Switch's second child (a sphere), LOD's first level (a unit box); not the box scaled to
  // nothing, not Switch's first child nor LOD's second level.
  EXPECT_EQ(c.surfaces, 2);
  EXPECT_EQ(c.meshes, 1);
  EXPECT_EQ(c.mesh_triangles, 12);
  const Shape* patch = nullptr;
  for_each_shape(read.scene, [&](const Shape& shape, const Eigen::Affine3d&, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry); t && t->surface.points.size() == 4) patch = &shape;
  });
  ASSERT_NE(patch, nullptr);
  // At rest: the animation's first key set, not the file's point field.
  EXPECT_EQ(std::get<TrimmedSurface>(patch->geometry).surface.points[3], Eigen::Vector3d(1, 1, 5));
  EXPECT_EQ(patch->colour, (Colour{1, 0, 0}));
  const std::vector<std::string> notes = {
      "1 CoordinateInterpolator routed to Coordinate.point: taken at the first key of its looping animation (fraction 0)",
      "1 TextureCoordinate left out: textures are not converted; the shape keeps its material's colour",
      "1 ImageTexture left out: textures are not converted; the shape keeps its material's colour",
      "1 TimeSensor left out: animation and interaction are not converted: the scene is taken at rest",
      "1 CoordinateInterpolator left out: animation and interaction are not converted: the scene is taken at rest",
      "1 Transform scaled to nothing left out: it draws nothing at rest; its children are left out with it",
      "1 Text left out: geometry without a NURBS or mesh form in cadnurbs",
      "1 Blob (PROTO) left out: PROTO instances are not expanded",
      "1 Far (PROTO) left out: PROTO instances are not expanded",
      "1 Script left out: animation and interaction are not converted: the scene is taken at rest",
      "1 DirectionalLight left out: lights, sound and environment have no place in the output",
      "1 Background left out: lights, sound and environment have no place in the output",
      "3 ROUTE left out: animation and interaction are not converted: the scene is taken at rest",
  };
  EXPECT_EQ(read.notes, notes);
}

TEST(WholeScene, XmlScenesWithProtosScriptsAndRoutesAreRead) {
  const std::string text =
      "<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Immersive' version='3.3'><head/><Scene>\n"
      "<ProtoDeclare name='Blob'><ProtoInterface>\n"
      " <field name='size' type='SFFloat' accessType='initializeOnly' value='1'/>\n"
      " <field name='shape' type='SFNode' accessType='inputOutput'/>\n"
      "</ProtoInterface><ProtoBody><Group/></ProtoBody></ProtoDeclare>\n"
      "<ExternProtoDeclare name='Far' url='\"far.x3d#Far\"'>\n"
      " <field name='size' type='SFFloat' accessType='initializeOnly'/></ExternProtoDeclare>\n"
      "<Transform translation='1 2 3'>\n"
      " <Shape><Appearance><PhysicalMaterial baseColor='0 1 0'/></Appearance><Sphere radius='2'/></Shape>\n"
      " <ProtoInstance name='Blob' DEF='B'><fieldValue name='size' value='3'/>\n"
      "  <fieldValue name='shape'><Shape><Box/></Shape></fieldValue></ProtoInstance>\n"
      "</Transform>\n"
      "<Script DEF='S'><field name='offset' type='SFVec2f' accessType='initializeOnly' value='1 2'/>\n"
      " <field name='flag' type='MFBool' accessType='inputOutput' value='true false'/>\n"
      "<![CDATA[ecmascript: function initialize() { if (1 < 2) {} }]]></Script>\n"
      "<TimeSensor DEF='T' loop='true'/>\n"
      "<ROUTE fromNode='T' fromField='isActive' toNode='S' toField='set_flag'/>\n"
      "<ProtoInstance name='Far'/>\n"
      "</Scene></X3D>\n";
  const SceneFromNodes read = parse_vrml_scene(text, "t.x3d");
  const SceneCounts c = count_entities(read.scene);
  EXPECT_EQ(c.surfaces, 1);
  ASSERT_EQ(read.scene.root.children.size(), 1u);
  EXPECT_EQ(read.scene.root.children[0].transform.translation(), Eigen::Vector3d(1, 2, 3));
  const auto& sphere = read.scene.root.children[0].shapes.at(0);
  EXPECT_EQ(sphere.colour, (Colour{0, 1, 0}));
  // The exact sphere: its control points' weights make every point of it lie at radius 2.
  const NurbsSurface& s = std::get<TrimmedSurface>(sphere.geometry).surface;
  for (double u : {0.1, 0.37, 0.8})
    for (double v : {0.05, 0.5, 0.93}) {
      const Eigen::Vector2d p(s.u_start() + u * (s.u_end() - s.u_start()), s.v_start() + v * (s.v_end() - s.v_start()));
      EXPECT_NEAR(surface_point(s, p.x(), p.y()).norm(), 2.0, 1e-12);
    }
  const std::vector<std::string> notes = {
      "1 Blob (PROTO) left out: PROTO instances are not expanded",
      "1 Script left out: animation and interaction are not converted: the scene is taken at rest",
      "1 TimeSensor left out: animation and interaction are not converted: the scene is taken at rest",
      "1 Far (PROTO) left out: PROTO instances are not expanded",
      "1 ROUTE left out: animation and interaction are not converted: the scene is taken at rest",
  };
  EXPECT_EQ(read.notes, notes);
}

TEST(WholeScene, VrmlProposalNodesDeclaredByExternprotoAreReadAsTheProposalDefinesThem) {
  // white_dune declares the amendment's nodes by EXTERNPROTO, with fields the proposal adds (texCoord);
  // an empty trimming segment trims nothing; a CoordinateDeformer without control points deforms nothing.
  const std::string text =
      "#VRML V2.0 utf8\n"
      "EXTERNPROTO NurbsSurface [ field SFInt32 uDimension field SFInt32 vDimension exposedField MFVec3f controlPoint\n"
      "  exposedField SFNode texCoord field SFInt32 uOrder field SFInt32 vOrder ] [ \"urn:web3d:vrml97:node:NurbsSurface\" ]\n"
      "CoordinateDeformer { children [ Shape { geometry TrimmedSurface {\n"
      "  trimmingContour [ Contour2D { children [ NurbsCurve2D {} Polyline2D {} ] } ]\n"
      "  surface NurbsSurface { uDimension 2 vDimension 2 uOrder 2 vOrder 2 texCoord NULL\n"
      "    controlPoint [0 0 0 1 0 0 0 1 0 1 1 0] } } } ] }\n"
      "CoordinateDeformer { controlPoint [0 0 0] uDimension 1 vDimension 1 wDimension 1\n"
      "  children Shape { geometry Box {} } }\n";
  const SceneFromNodes read = parse_vrml_scene(text, "t.wrl");
  const SceneCounts c = count_entities(read.scene);
  EXPECT_EQ(c.surfaces, 1);
  EXPECT_EQ(c.trim_loops, 0);
  EXPECT_EQ(c.meshes, 0);
  EXPECT_EQ(read.notes, (std::vector<std::string>{
                            "1 CoordinateDeformer left out: its deformation is not evaluated; its children are left out with it"}));
}

TEST(WholeScene, ProtoBodiesAreReadWithTheirIsConnectionsRoutesAndOwnNames) {
  // The body's DEF T is its own: the T after the PROTO is another node.
  const NodeDocument classic = parse_classic(
      "#X3D V3.3 utf8\n"
      "PROTO Mover [ inputOutput SFVec3f where 1 2 3 inputOnly SFFloat go initializeOnly SFNode look Material {} ] {\n"
      "  DEF T Transform { translation IS where children Shape { appearance Appearance { material IS look } } }\n"
      "  DEF S Script { inputOnly SFFloat go IS go outputOnly SFVec3f to url \"ecmascript: function go(f) {}\" }\n"
      "  ROUTE S.to TO T.set_translation\n"
      "}\n"
      "EXTERNPROTO Far [ initializeOnly SFFloat size ] [ \"urn:x:Far\" \"far.x3dv#Far\" ]\n"
      "DEF T Mover { where 4 5 6 }\n",
      "t.x3dv");
  ASSERT_EQ(classic.protos.size(), 2u);
  const ProtoDeclaration& mover = classic.protos[0];
  ASSERT_EQ(mover.interface.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<SFVec3f>(*mover.interface[0].default_value));
  EXPECT_FALSE(mover.interface[1].default_value.has_value());
  ASSERT_TRUE(std::holds_alternative<SFNode>(*mover.interface[2].default_value));
  ASSERT_NE(mover.body, nullptr);
  ASSERT_EQ(mover.body->roots.size(), 2u);
  ASSERT_EQ(mover.body->routes.size(), 1u);
  EXPECT_EQ(mover.body->routes[0].to_node, "T");
  const Node& transform = *mover.body->roots[0];
  ASSERT_EQ(transform.is_connections.size(), 1u);
  EXPECT_EQ(transform.is_connections[0].node_field, "translation");
  EXPECT_EQ(transform.is_connections[0].proto_field, "where");
  const Node& script = *mover.body->roots[1];
  ASSERT_EQ(script.declarations.size(), 2u);
  ASSERT_EQ(script.is_connections.size(), 1u);
  EXPECT_EQ(script.is_connections[0].node_field, "go");
  EXPECT_EQ(classic.protos[1].urls, (std::vector<std::string>{"urn:x:Far", "far.x3dv#Far"}));
  ASSERT_EQ(classic.roots.size(), 1u);
  EXPECT_TRUE(classic.roots[0]->proto_instance);
  EXPECT_EQ(classic.roots[0]->get<SFVec3f>("where")->value, Eigen::Vector3d(4, 5, 6));

  const NodeDocument xml = parse_xml(
      "<X3D><Scene>\n"
      "<ProtoDeclare name='Mover'><ProtoInterface>\n"
      " <field name='where' type='SFVec3f' accessType='inputOutput' value='1 2 3'/>\n"
      " <field name='look' type='SFNode' accessType='initializeOnly'><Material/></field>\n"
      "</ProtoInterface><ProtoBody>\n"
      " <Transform DEF='T'><IS><connect nodeField='translation' protoField='where'/></IS></Transform>\n"
      " <Script DEF='S'><field name='to' type='SFVec3f' accessType='outputOnly'/>\n"
      "  <![CDATA[ecmascript: function initialize() { if (1 < 2) {} }]]></Script>\n"
      " <ROUTE fromNode='S' fromField='to' toNode='T' toField='set_translation'/>\n"
      "</ProtoBody></ProtoDeclare>\n"
      "<ExternProtoDeclare name='Far' url='\"urn:x:Far\" \"far.x3d#Far\"'>\n"
      " <field name='size' type='SFFloat' accessType='initializeOnly'/></ExternProtoDeclare>\n"
      "<ProtoInstance name='Mover' DEF='T'><fieldValue name='where' value='4 5 6'/></ProtoInstance>\n"
      "</Scene></X3D>\n",
      "t.x3d");
  ASSERT_EQ(xml.protos.size(), 2u);
  ASSERT_NE(xml.protos[0].body, nullptr);
  ASSERT_EQ(xml.protos[0].body->roots.size(), 2u);
  EXPECT_EQ(xml.protos[0].body->routes.size(), 1u);
  EXPECT_EQ(xml.protos[0].body->roots[0]->is_connections.size(), 1u);
  ASSERT_TRUE(xml.protos[0].interface[1].default_value.has_value());
  EXPECT_EQ(std::get<SFNode>(*xml.protos[0].interface[1].default_value).node->type, "Material");
  const auto* url = xml.protos[0].body->roots[1]->get<MFString>("url");
  ASSERT_NE(url, nullptr);
  EXPECT_EQ(url->values, (std::vector<std::string>{"ecmascript: function initialize() { if (1 < 2) {} }"}));
  EXPECT_EQ(xml.protos[1].urls, (std::vector<std::string>{"urn:x:Far", "far.x3d#Far"}));
  EXPECT_EQ(xml.roots[0]->get<SFVec3f>("where")->value, Eigen::Vector3d(4, 5, 6));
}

}  // namespace
}  // namespace cadnurbs
