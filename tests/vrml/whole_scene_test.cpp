// Whole scene graphs: every node of the standards, PROTOs, Scripts and ROUTEs are read; the Scene is the
// geometry at rest, and what has no place in it is named in one note per kind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "core/bounding_box.hpp"
#include "core/nurbs_surface.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/coordinate_deformer.hpp"
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
      "1 Group left out: geometry without a NURBS or mesh form in cadnurbs",  // Blob's body, a Group
      "1 Far (PROTO) left out: its EXTERNPROTO's urls name no local file that declares it: not expanded",
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
      "1 Script left out: animation and interaction are not converted: the scene is taken at rest",
      "1 TimeSensor left out: animation and interaction are not converted: the scene is taken at rest",
      "1 Far (PROTO) left out: its EXTERNPROTO's urls name no local file that declares it: not expanded",
      "1 ROUTE left out: animation and interaction are not converted: the scene is taken at rest",
  };
  EXPECT_EQ(read.notes, notes);
}

TEST(WholeScene, VrmlProposalNodesDeclaredByExternprotoAreReadAsTheProposalDefinesThem) {
  // white_dune declares the amendment's nodes by EXTERNPROTO, with fields the proposal adds (texCoord);
  // an empty trimming segment trims nothing; a CoordinateDeformer without control points deforms nothing;
  // one whose single control point cannot make a volume of order 2 is left out with its children.
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
                            "1 CoordinateDeformer with an invalid volume left out: uKnot: 1 control points are too few for order 2 (need at least 2); its children are left out with it"}));
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


// ---- PROTO instances expanded on the scene path (proto_expansion.hpp) ----

// A box of size 2 scaled by `size`, coloured `colour`; two of them through a PROTO that nests it.
const std::string pane_protos =
    "PROTO Pane [ field SFVec3f size 1 1 1 field SFColor colour 1 0 0 ] {\n"
    "  Transform { scale IS size children Shape {\n"
    "    appearance Appearance { material Material { diffuseColor IS colour } } geometry Box {} } }\n"
    "  DEF Clock TimeSensor { loop TRUE }\n"
    "}\n"
    "PROTO Pair [ field SFVec3f size 1 1 1 ] {\n"
    "  Transform { translation 10 0 0 children [ Pane { size IS size } Pane { size IS size colour 0 0 1 } ] }\n"
    "}\n";

TEST(WholeScene, ProtoInstancesDrawTheirBodyWithTheirFieldValues) {
  const std::string text = "#VRML V2.0 utf8\n" + pane_protos + "DEF Big Pane { size 2 3 4 }\nPane {}\nPair { size 1 1 5 }\n";
  const SceneFromNodes read = parse_vrml_scene(text, "t.wrl");
  const SceneCounts c = count_entities(read.scene);
  EXPECT_EQ(c.meshes, 4);
  EXPECT_EQ(c.mesh_triangles, 4 * 12);
  // Big: the unit-2 box scaled 2 3 4 about the origin, named by the instance's DEF.
  const SceneNode* big = nullptr;
  for (const auto& child : read.scene.root.children)
    if (child.name == "Big") big = &child;
  ASSERT_NE(big, nullptr);
  EXPECT_EQ(big->transform.linear().diagonal(), Eigen::Vector3d(2, 3, 4));
  // Pair: two boxes scaled 1 1 5 at x = 10, one red (the default), one blue (given inside Pair's body).
  const Eigen::AlignedBox3d all = scene_bounding_box(read.scene);
  EXPECT_EQ(all.min(), Eigen::Vector3d(-2, -3, -5));
  EXPECT_EQ(all.max(), Eigen::Vector3d(11, 3, 5));
  std::vector<Colour> colours;
  for_each_shape(read.scene, [&](const Shape&, const Eigen::Affine3d&, const Colour& colour) { colours.push_back(colour); });
  EXPECT_EQ(std::count(colours.begin(), colours.end(), Colour{0, 0, 1}), 1);
  EXPECT_EQ(std::count(colours.begin(), colours.end(), Colour{1, 0, 0}), 3);
  // Only the first node of a body is what an instance is: the TimeSensors are never drawn, no note.
  EXPECT_TRUE(read.notes.empty()) << read.notes.front();
}

TEST(WholeScene, XmlProtoInstancesAreExpandedToo) {
  const std::string text =
      "<X3D profile='Immersive' version='3.3'><Scene>\n"
      "<ProtoDeclare name='Pane'><ProtoInterface>\n"
      " <field name='size' type='SFVec3f' accessType='initializeOnly' value='1 1 1'/>\n"
      "</ProtoInterface><ProtoBody>\n"
      " <Transform><IS><connect nodeField='scale' protoField='size'/></IS><Shape><Box/></Shape></Transform>\n"
      "</ProtoBody></ProtoDeclare>\n"
      "<ProtoInstance name='Pane'><fieldValue name='size' value='1 2 3'/></ProtoInstance>\n"
      "</Scene></X3D>\n";
  const SceneFromNodes read = parse_vrml_scene(text, "t.x3d");
  EXPECT_EQ(count_entities(read.scene).meshes, 1);
  EXPECT_EQ(scene_bounding_box(read.scene).max(), Eigen::Vector3d(1, 2, 3));
  EXPECT_TRUE(read.notes.empty());
}

// A fresh folder for files that name each other.
std::filesystem::path scratch_folder(const std::string& name) {
  auto folder = std::filesystem::temp_directory_path() / ("cadnurbs_" + name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

void write_text(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

TEST(WholeScene, ExternprotosInALocalFileAreExpanded) {
  const auto folder = scratch_folder("externproto");
  write_text(folder / "library.wrl", "#VRML V2.0 utf8\n" + pane_protos);
  write_text(folder / "main.wrl",
             "#VRML V2.0 utf8\n"
             "EXTERNPROTO Pair [ field SFVec3f size ] [ \"urn:x:Pair\" \"library.wrl#Pair\" ]\n"
             "EXTERNPROTO Gone [ field SFVec3f size ] [ \"http://example.com/library.wrl#Gone\" \"library.wrl#Gone\" ]\n"
             "Pair { size 1 1 1 }\nGone { size 1 1 1 }\n");
  const SceneFromNodes read = read_vrml_scene((folder / "main.wrl").string());
  // Pair's body uses Pane, which library.wrl declares beside it.
  EXPECT_EQ(count_entities(read.scene).meshes, 2);
  EXPECT_EQ(scene_bounding_box(read.scene).min(), Eigen::Vector3d(9, -1, -1));
  EXPECT_EQ(read.notes, (std::vector<std::string>{
                            "1 Gone (PROTO) left out: its EXTERNPROTO's urls name no local file that declares it: not expanded"}));
  std::filesystem::remove_all(folder);
}

// ---- Inline followed to local files (linked_files.hpp) ----

TEST(WholeScene, InlinesOfLocalFilesAreReadUnderTheirTransformOthersAreNamed) {
  const auto folder = scratch_folder("inline");
  std::filesystem::create_directories(folder / "parts");
  write_text(folder / "parts" / "box.x3dv", "#X3D V3.3 utf8\nShape { geometry Box { size 1 2 3 } }\n"
                                            "Inline { url \"../main.wrl\" }\n");
  write_text(folder / "parts" / "my part.wrl", "#VRML V2.0 utf8\nTransform { translation 0 0 1 children "
                                               "Inline { url \"box.x3dv\" } }\n");
  write_text(folder / "main.wrl",
             "#VRML V2.0 utf8\n"
             "Transform { translation 10 0 0 children DEF Part Inline { url [\"http://example.com/x.wrl\" \"parts/my%20part.wrl\"] } }\n"
             "Inline { url \"file:" + (folder / "parts" / "box.x3dv").string() + "\" }\n"
             "Inline { url \"missing.wrl\" }\n"
             "Inline { url \"http://example.com/remote.wrl\" }\n");
  const SceneFromNodes read = read_vrml_scene((folder / "main.wrl").string());
  // The box twice: through parts/my part.wrl at (10, 0, 1), and by its file: url at the origin.
  EXPECT_EQ(count_entities(read.scene).meshes, 2);
  const Eigen::AlignedBox3d box = scene_bounding_box(read.scene);
  EXPECT_EQ(box.min(), Eigen::Vector3d(-0.5, -1, -1.5));
  EXPECT_EQ(box.max(), Eigen::Vector3d(10.5, 1, 2.5));
  ASSERT_GE(read.scene.root.children.size(), 1u);
  ASSERT_EQ(read.scene.root.children[0].children.size(), 1u);
  EXPECT_EQ(read.scene.root.children[0].children[0].name, "Part");
  // box.x3dv inlines main.wrl, which is reading it: refused twice (once per path to it), one line.
  EXPECT_EQ(read.notes, (std::vector<std::string>{
                            "2 Inline \"../main.wrl\" left out: it includes itself: not followed",
                            "1 Inline \"missing.wrl\" left out: not a local file: not followed",
                            "1 Inline \"http://example.com/remote.wrl\" left out: not a local file: not followed"}));
  std::filesystem::remove_all(folder);
}

// ---- CoordinateDeformer evaluated at rest (coordinate_deformer.hpp) ----

// A CoordinateDeformer over [0,1] x [-1,1] x [0,2] whose control points sit at their Greville abscissae,
// each moved by `move` (text of a function of the grid point, applied here in C++): u linear with a knot at
// 0.5 (3 points), v linear (2 points), w quadratic Bezier (3 points).
template <class Move>
std::string deformer_text(Move move) {
  std::string points;
  const double u[3] = {0, 0.5, 1}, v[2] = {-1, 1}, w[3] = {0, 1, 2};
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector3d p = move(Eigen::Vector3d(u[i], v[j], w[k]), k);
        points += std::to_string(p.x()) + " " + std::to_string(p.y()) + " " + std::to_string(p.z()) + "\n";
      }
  return "CoordinateDeformer { uDimension 3 vDimension 2 wDimension 3 uOrder 2 vOrder 2 wOrder 3\n"
         "  uKnot [0 0 0.5 1 1] vKnot [-1 -1 1 1] wKnot [0 0 0 2 2 2]\n  controlPoint [" + points + "]\n";
}

// A bilinear patch, a polyline-like curve and a triangle, some points outside the volume's domain.
const std::string deformed_children =
    "  children [ Shape { geometry NurbsSurface { uDimension 2 vDimension 2 uOrder 2 vOrder 2\n"
    "      controlPoint [0.1 -0.5 0.3  0.9 -0.5 0.7  0.2 0.8 1.9  0.7 0.3 1.1] } }\n"
    "    Transform { translation 0.25 0 0.5 children Shape { geometry IndexedFaceSet {\n"
    "      coord Coordinate { point [0 0 0  1.7 0.2 -0.3  0.3 -1.4 2.6] } coordIndex [0 1 2 -1] } } } ] }\n";

// Every shape's points in world coordinates, in reading order.
std::vector<Eigen::Vector3d> world_points(const Scene& scene) {
  std::vector<Eigen::Vector3d> out;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&shape.geometry))
      for (const auto& p : t->surface.points) out.push_back(world * p);
    if (const auto* m = std::get_if<TriangleMesh>(&shape.geometry))
      for (const auto& p : m->positions) out.push_back(world * p);
  });
  return out;
}

std::vector<Eigen::Vector3d> deformed_points(const std::function<Eigen::Vector3d(Eigen::Vector3d, int)>& move) {
  const SceneFromNodes read =
      parse_vrml_scene("#VRML V2.0 utf8\n" + deformer_text(move) + deformed_children, "t.wrl");
  EXPECT_TRUE(read.notes.empty());
  return world_points(read.scene);
}

std::vector<Eigen::Vector3d> undeformed_points() {
  return world_points(parse_vrml_scene("#VRML V2.0 utf8\nGroup {\n" + deformed_children, "t.wrl").scene);
}

TEST(CoordinateDeformer, AVolumeOfGrevillePointsLeavesPointsInsideAndOutsideItsDomainUnmoved) {
  const auto before = undeformed_points();
  const auto after = deformed_points([](Eigen::Vector3d p, int) { return p; });
  ASSERT_EQ(after.size(), 7u);
  for (size_t i = 0; i < after.size(); ++i) EXPECT_LE((after[i] - before[i]).norm(), 1e-12) << i;
}

TEST(CoordinateDeformer, AVolumeScaledByTwoDoublesCoordinatesInTheDeformersSpace) {
  // The triangle lies under a Transform (translation 0.25 0 0.5) inside the deformer: doubled in the
  // deformer's space, its world points are doubled too.
  const auto before = undeformed_points();
  const auto after = deformed_points([](Eigen::Vector3d p, int) { return Eigen::Vector3d(2 * p); });
  ASSERT_EQ(after.size(), before.size());
  for (size_t i = 0; i < after.size(); ++i) EXPECT_LE((after[i] - 2 * before[i]).norm(), 1e-12) << i;
}

// The bend used below: the middle w layer moved by +s in x gives x' = x + s * B1((z - z0) / h), with
// B1(t) = 2t(1 - t) the middle quadratic Bernstein polynomial (the other layers stay at their Greville
// points, so u, v and w are otherwise the identity).
double bent_x(const Eigen::Vector3d& p, double s, double z0, double h) {
  const double t = (p.z() - z0) / h;
  return p.x() + s * 2 * t * (1 - t);
}

TEST(CoordinateDeformer, AQuadraticBendMovesPointsAsItsBernsteinPolynomialSays) {
  const auto before = undeformed_points();
  const auto after = deformed_points([](Eigen::Vector3d p, int k) { return Eigen::Vector3d(p.x() + (k == 1 ? 3.0 : 0.0), p.y(), p.z()); });
  ASSERT_EQ(after.size(), before.size());
  for (size_t i = 0; i < after.size(); ++i) {
    const Eigen::Vector3d expected(bent_x(before[i], 3.0, 0.0, 2.0), before[i].y(), before[i].z());
    EXPECT_LE((after[i] - expected).norm(), 1e-12) << i;
  }
}

TEST(CoordinateDeformer, TestallsSurfaceBentByADeformerHasTheBoxItsControlPointsPredict) {
  // white_dune's testall.wrl holds an empty CoordinateDeformer (it deforms nothing). Put its 4 x 4
  // NurbsSurface (DEF Transform1) under one that bends it: a volume over x in [-8, 8], y in [-7, 1],
  // z in [-1, 4], the middle of its three z layers moved by +2 in x.
  std::string text = read_file(std::string(CADNURBS_SHARED_DIR) + "/corpus/vrml/testall.wrl");
  const size_t at = text.find("CoordinateDeformer \n  {\n  }");
  ASSERT_NE(at, std::string::npos);
  std::string points;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        points += std::to_string((i ? 8 : -8) + (k == 1 ? 2 : 0)) + " " + std::to_string(j ? 1 : -7) + " " +
                  std::to_string(-1 + 2.5 * k) + "\n";
  text.replace(at, 27,
               "DEF Bent CoordinateDeformer { uDimension 2 vDimension 2 wDimension 3 uOrder 2 vOrder 2 wOrder 3\n"
               "  uKnot [-8 -8 8 8] vKnot [-7 -7 1 1] wKnot [-1 -1 -1 4 4 4]\n  controlPoint [" + points +
               "]\n  children USE Transform1 }");
  const SceneFromNodes read = parse_vrml_scene(text, "testall.wrl");
  const SceneNode* bent = nullptr;
  for (const auto& child : read.scene.root.children)
    if (child.name == "Bent") bent = &child;
  ASSERT_NE(bent, nullptr);
  Scene only;
  only.root = *bent;
  // The surface's control points in the file (line 170 on) span x [-7.065702, 7.065702], y [-6.080788, 0],
  // z [0, 3]; their bent x is largest at the top-right interior point (7.065702, z 2.918514): 7.065702 +
  // 2 * 2t(1 - t), t = 3.918514 / 5; smallest at the left column's -1.5 with z 1 or 2 (t 0.4, 0.6: +0.96)
  // against -7.065702 at z 2.918514 (+0.678...): the latter.
  const double t = 3.918514 / 5;
  const double shift = 2 * 2 * t * (1 - t);
  const Eigen::AlignedBox3d box = scene_bounding_box(only);
  EXPECT_NEAR(box.max().x(), 7.065702 + shift, 1e-12);
  EXPECT_NEAR(box.min().x(), -7.065702 + shift, 1e-12);
  EXPECT_NEAR(box.min().y(), -6.080788, 1e-12);
  EXPECT_NEAR(box.max().y(), 0.0, 1e-12);
  EXPECT_NEAR(box.min().z(), 0.0, 1e-12);
  EXPECT_NEAR(box.max().z(), 3.0, 1e-12);
  // Hull property of the volume: inside its domain every point stays within its control points' x range.
  EXPECT_GE(box.min().x(), -8.0);
  EXPECT_LE(box.max().x(), 10.0);
}

}  // namespace
}  // namespace cadnurbs
