// The whole scene graph of every corpus VRML/X3D file through each encoding and back: every node kept
// (counted by type), every ROUTE and DEF name, and the geometry's numbers unchanged.
#include <gtest/gtest.h>

#include <functional>
#include <map>
#include <set>

#include "core/bounding_box.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/scene_graph_rewrite.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

const std::string corpus = std::string(CADNURBS_SHARED_DIR) + "/corpus/vrml/";

struct GraphCounts {
  std::map<std::string, int> types;  // nodes by type, each node once, PROTO bodies included
  std::map<std::string, std::string> defs;  // DEF name -> node type
  size_t routes = 0, protos = 0;
};

void count(const NodeDocument& d, GraphCounts& out, std::set<const Node*>& seen) {
  std::function<void(const NodePtr&)> walk = [&](const NodePtr& node) {
    if (!node || !seen.insert(node.get()).second) return;
    ++out.types[node->type];
    if (!node->def_name.empty()) out.defs[node->def_name] = node->type;
    for (const auto& f : node->fields) {
      if (const auto* sf = std::get_if<SFNode>(&f.value)) walk(sf->node);
      if (const auto* mf = std::get_if<MFNode>(&f.value))
        for (const auto& n : mf->nodes) walk(n);
    }
  };
  out.routes += d.routes.size();
  out.protos += d.protos.size();
  for (const auto& p : d.protos)
    if (p.body) count(*p.body, out, seen);
  for (const auto& r : d.roots) walk(r);
}

GraphCounts counts_of(const std::string& bytes) {
  GraphCounts out;
  std::set<const Node*> seen;
  count(parse_vrml_document(bytes, "t"), out, seen);
  return out;
}

std::string rewritten(const std::string& bytes, VrmlEncoding encoding) {
  VrmlWriteOptions options;
  options.encoding = encoding;
  return rewrite_scene_graph(bytes, "t", options).text;
}

VrmlEncoding encoding_of(const std::string& file) {
  if (file.ends_with(".wrl")) return VrmlEncoding::vrml97;
  return file.ends_with(".x3d") ? VrmlEncoding::x3d_xml : VrmlEncoding::x3d_classic;
}

class SceneGraphRewrite : public ::testing::TestWithParam<std::string> {};

TEST_P(SceneGraphRewrite, EveryNodeRouteAndNameSurvivesEachEncodingAndBack) {
  const std::string file = GetParam();
  const std::string original = read_file(corpus + file);
  GraphCounts before = counts_of(original);
  const Scene scene_before = parse_vrml(original, file);
  for (VrmlEncoding via : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    SCOPED_TRACE(file + " via encoding " + std::to_string(static_cast<int>(via)));
    const std::string there = rewritten(original, via);
    // The geometry reads the same from the rewritten file: same entities, same box to the last bit.
    const Scene scene_there = parse_vrml(there, file);
    const SceneCounts a = count_entities(scene_before), b = count_entities(scene_there);
    EXPECT_EQ(a.surfaces, b.surfaces);
    EXPECT_EQ(a.control_points, b.control_points);
    EXPECT_EQ(a.trim_loops, b.trim_loops);
    EXPECT_EQ(a.mesh_triangles, b.mesh_triangles);
    EXPECT_EQ(scene_bounding_box(scene_before).min(), scene_bounding_box(scene_there).min());
    EXPECT_EQ(scene_bounding_box(scene_before).max(), scene_bounding_box(scene_there).max());
    // Back in the original's encoding, every node by type, DEF name and ROUTE. X3D has no NurbsGroup
    // and no InlineLoadControl: a VRML97 file through X3D comes back with Group and Inline. VRML97 has
    // no HAnim, triangle sets or RGBA colours: an X3D file through VRML97 comes back with Transforms,
    // Groups, face sets and Colors; a Coordinate that a NURBS node shares with another node comes back
    // as two (the VRML97 NURBS nodes hold their points), so Coordinates may only grow.
    GraphCounts back = counts_of(rewritten(there, encoding_of(file)));
    GraphCounts expected = before;
    std::vector<std::pair<std::string, std::string>> renamed;
    if (encoding_of(file) == VrmlEncoding::vrml97 && via != VrmlEncoding::vrml97)
      renamed = {{"NurbsGroup", "Group"}, {"InlineLoadControl", "Inline"}};
    if (encoding_of(file) != VrmlEncoding::vrml97 && via == VrmlEncoding::vrml97) {
      renamed = {{"HAnimHumanoid", "Transform"}, {"HAnimJoint", "Transform"},        {"HAnimSite", "Transform"},
                 {"HAnimSegment", "Group"},      {"IndexedTriangleSet", "IndexedFaceSet"}, {"ColorRGBA", "Color"}};
      EXPECT_GE(back.types["Coordinate"], expected.types["Coordinate"]);
      back.types.erase("Coordinate");
      expected.types.erase("Coordinate");
    }
    for (const auto& [from, to] : renamed)
      if (expected.types.count(from)) {
        expected.types[to] += expected.types[from];
        expected.types.erase(from);
      }
    EXPECT_EQ(back.types, expected.types);
    EXPECT_EQ(back.routes, before.routes);
    // A Coordinate that a DEF'd NURBS node held in X3D has no node in VRML97: its name goes (its ROUTEs
    // follow the NURBS node, the NurbsNodesAndTheirRoutesAreTranslated test).
    for (const auto& [name, type] : before.defs) {
      if (via == VrmlEncoding::vrml97 && type == "Coordinate") continue;
      EXPECT_TRUE(back.defs.count(name)) << "DEF " << name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Corpus, SceneGraphRewrite,
                         ::testing::Values("door.x3dv", "NurbsTrimmedSurface.x3d", "NurbsPatchSurface.x3d",
                                           "nurbs_dune_primitives.x3dv", "nurbs_weights.x3dv", "testall.wrl",
                                           "fish.wrl", "robot_jme2.x3dv", "robot_opengl.x3dv"),
                         [](const auto& info) {
                           std::string name = info.param;
                           for (auto& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(SceneGraphRewrite, NurbsNodesAndTheirRoutesAreTranslated) {
  // A VRML97 surface animated by a ROUTE to its controlPoint: in X3D the points live in a Coordinate,
  // DEF'd after the surface, and the ROUTE goes there; back in VRML97 it returns to the surface.
  const std::string wrl =
      "#VRML V2.0 utf8\n"
      "DEF T TimeSensor { loop TRUE }\n"
      "DEF I CoordinateInterpolator { key [0 1] keyValue [0 0 0 1 0 0 0 1 0 1 1 0  0 0 1 1 0 1 0 1 1 1 1 1] }\n"
      "Shape { geometry DEF S NurbsSurface { uDimension 2 vDimension 2 uOrder 2 vOrder 2 ccw FALSE\n"
      "  controlPoint [0 0 0 1 0 0 0 1 0 1 1 0] } }\n"
      "Shape { geometry TrimmedSurface { surface NurbsSurface { uDimension 2 vDimension 2 uOrder 2 vOrder 2\n"
      "  controlPoint [0 0 0 1 0 0 0 1 0 1 1 0] }\n"
      "  trimmingContour Contour2D { children Polyline2D { point [0 0 1 0 1 1 0 0] } } } }\n"
      "ROUTE T.fraction_changed TO I.set_fraction\n"
      "ROUTE I.value_changed TO S.set_controlPoint\n";
  VrmlWriteOptions options;
  options.encoding = VrmlEncoding::x3d_classic;
  const RewrittenSceneGraph x3d = rewrite_scene_graph(wrl, "t.wrl", options);
  EXPECT_EQ(x3d.notes, (std::vector<std::string>{"1 NurbsSurface ccw dropped: X3D's NURBS surfaces have no ccw"}));
  const NodeDocument d = parse_vrml_document(x3d.text, "t.x3dv");
  ASSERT_EQ(d.routes.size(), 2u);
  EXPECT_EQ(d.routes[1].to_node, "S_controlPoint");
  EXPECT_EQ(d.routes[1].to_field, "set_point");
  GraphCounts c;
  std::set<const Node*> seen;
  count(d, c, seen);
  EXPECT_EQ(c.types["NurbsPatchSurface"], 1);
  EXPECT_EQ(c.types["NurbsTrimmedSurface"], 1);
  EXPECT_EQ(c.types["ContourPolyline2D"], 1);
  EXPECT_EQ(c.types["Coordinate"], 2);
  // The animation at rest reads through the translated ROUTE.
  const Scene scene = parse_vrml(x3d.text, "t.x3dv");
  bool moved = false;
  for_each_shape(scene, [&](const Shape& s, const Eigen::Affine3d&, const Colour&) {
    const auto& t = std::get<TrimmedSurface>(s.geometry);
    if (t.loops.empty()) moved = t.surface.points[3] == Eigen::Vector3d(1, 1, 0);
  });
  EXPECT_TRUE(moved);
  options.encoding = VrmlEncoding::vrml97;
  const NodeDocument back = parse_vrml_document(rewrite_scene_graph(x3d.text, "t.x3dv", options).text, "t.wrl");
  ASSERT_EQ(back.routes.size(), 2u);
  EXPECT_EQ(back.routes[1].to_node, "S");
  EXPECT_EQ(back.routes[1].to_field, "set_controlPoint");
}

TEST(SceneGraphRewrite, NamesThatAreNoIdentifiersAreRenamedWithTheirRoutes) {
  // XML takes any string as a DEF; the classic encoding takes identifiers only (found by fuzzing: a
  // DEF holding NUL bytes).
  const std::string x3d =
      "<X3D><Scene>\n<TimeSensor DEF='the clock' loop='true'/>\n<Transform DEF='TRUE'/>\n"
      "<ROUTE fromNode='the clock' fromField='fraction_changed' toNode='TRUE' toField='set_scale'/>\n"
      "<EXPORT localDEF='the clock' AS='clock'/>\n</Scene></X3D>\n";
  for (VrmlEncoding encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    VrmlWriteOptions options;
    options.encoding = encoding;
    const RewrittenSceneGraph graph = rewrite_scene_graph(x3d, "t.x3d", options);
    EXPECT_EQ(graph.notes.back(), "2 DEF names renamed: they were not identifiers");
    const NodeDocument d = parse_vrml_document(graph.text, "t");
    if (encoding == VrmlEncoding::vrml97) {  // VRML97 has no EXPORT
      EXPECT_EQ(graph.notes.front(), "1 IMPORT/EXPORT dropped: VRML97 has none");
      EXPECT_TRUE(d.imports_exports.empty());
      continue;
    }
    ASSERT_EQ(d.routes.size(), 1u);
    EXPECT_EQ(d.routes[0].from_node, "the_clock");
    EXPECT_EQ(d.routes[0].to_node, "TRUE_");
    EXPECT_EQ(d.roots[0]->def_name, "the_clock");
    ASSERT_EQ(d.imports_exports.size(), 1u);
    EXPECT_EQ(d.imports_exports[0].name, "the_clock");
    EXPECT_EQ(d.imports_exports[0].as, "clock");
  }
}

}  // namespace
}  // namespace cadnurbs
