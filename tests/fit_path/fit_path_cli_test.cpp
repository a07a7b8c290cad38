// `cadnurbs fit-path` on files the tests write: the interpolator replaced, every other byte kept, the
// curve read back from the output within the deviation, declarations added, and the refusals.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include "converters/command_fixture.hpp"
#include "core/nurbs_curve.hpp"
#include "fit_path/path_shapes.hpp"
#include "formats/common/gzip.hpp"

namespace cadnurbs::test {
namespace {

class FitPath : public CommandTest {};

std::vector<double> numbers_after(const std::string& text, const std::string& opening, char closing) {
  const size_t at = text.find(opening);
  EXPECT_NE(at, std::string::npos) << opening;
  if (at == std::string::npos) return {};
  const size_t begin = at + opening.size(), end = text.find(closing, begin);
  std::string list = text.substr(begin, end - begin);
  for (char& c : list)
    if (c == ',') c = ' ';
  std::istringstream in(list);
  std::vector<double> out;
  for (double x; in >> x;) out.push_back(x);
  return out;
}

// The curve as the output file states it: order, knots and control points of its only NURBS node.
NurbsCurve curve_in(const std::string& text, const std::string& order_opening, const std::string& knot_opening,
                    char knot_closing, const std::string& points_opening, char points_closing) {
  NurbsCurve curve;
  curve.order = static_cast<int>(numbers_after(text, order_opening, ' ').at(0));
  curve.knots = numbers_after(text, knot_opening, knot_closing);
  const std::vector<double> p = numbers_after(text, points_opening, points_closing);
  for (size_t i = 0; i + 2 < p.size(); i += 3) curve.points.emplace_back(p[i], p[i + 1], p[i + 2]);
  return curve;
}


const char* kRoutes =
    "ROUTE Clock.fraction_changed TO PATH.set_fraction\n"
    "ROUTE PATH.value_changed TO Ball.set_translation\n";

std::string vrml_world(const KeyframePath& path) {
  return "#VRML V2.0 utf8\n"
         "# a ball going round\n"
         "DEF Ball Transform { children Shape { geometry Sphere { radius 0.5 } } }\n"
         "DEF Clock TimeSensor { cycleInterval 10 loop TRUE }\n"
         "DEF PATH PositionInterpolator { key [ " + keys_text(path) + "] keyValue [ " + key_values_text(path) + "] }\n" +
         kRoutes;
}

TEST_F(FitPath, AVrmlCircleOfAThousandKeysShrinksTenfoldAndReadsBackWithinTheDeviation) {
  const KeyframePath frames = circle_path(1000, 10.0);
  const std::string input = vrml_world(frames);
  write_file_atomically(path("in.wrl"), input);
  const CommandResult r = run("fit-path " + path("in.wrl") + " -o " + path("out.wrl") + " --deviation 0.01");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string output = read_file(path("out.wrl"));
  // The node is replaced and declared; everything else is the input's, byte for byte.
  const size_t node_in = input.find("DEF PATH PositionInterpolator"), node_out = output.find("DEF PATH NurbsPositionInterpolator{");
  ASSERT_NE(node_out, std::string::npos) << output.substr(0, 2000);
  const std::string url_end = "cadnurbs-nurbs-protos.wrl#NurbsPositionInterpolator\"]\n";
  const size_t declared = output.find(url_end) + url_end.size();
  EXPECT_EQ(output.rfind("#VRML V2.0 utf8\nEXTERNPROTO NurbsPositionInterpolator [\n", 0), 0u);
  EXPECT_EQ(output.substr(declared, node_out - declared), input.substr(16, node_in - 16));
  EXPECT_EQ(output.substr(output.size() - std::string(kRoutes).size()), kRoutes);
  EXPECT_TRUE(std::filesystem::exists(path("cadnurbs-nurbs-protos.wrl")));
  EXPECT_GE(input.size(), 10 * output.size()) << input.size() << " -> " << output.size();

  const NurbsCurve curve = curve_in(output, "order ", "knot[", ']', "keyValue[", ']');
  EXPECT_EQ(curve.knots.size(), curve.points.size() + curve.order);
  EXPECT_LE(sampled_path_error(curve, frames), 0.01);

  const std::regex line(".*in\\.wrl: PositionInterpolator PATH \\(line 5\\): 1000 keys -> [0-9]+ control points "
                        "\\(order 4\\), max error [0-9.e-]+ \\(bound\\), [0-9]+ -> [0-9]+ bytes\n"
                        ".*out\\.wrl: 1 of 1 interpolators fitted within 0\\.01; [0-9]+ -> [0-9]+ bytes "
                        "\\([0-9]+ -> [0-9]+ gzip'd\\)\n");
  EXPECT_TRUE(std::regex_match(r.out, line)) << r.out;
}

TEST_F(FitPath, AnX3dClassicHelixGetsTheNurbsComponentAndAControlPointCoordinate) {
  const KeyframePath frames = helix_path(400, 5.0, 2.0, 3.0);
  const std::string input = "#X3D V3.3 utf8\nPROFILE Interchange\nDEF T Transform {}\nDEF PATH PositionInterpolator { key [ " +
                            keys_text(frames) + "] keyValue [ " + key_values_text(frames) +
                            "] }\nROUTE PATH.value_changed TO T.set_translation\n";
  write_file_atomically(path("in.x3dv"), gzip(input));  // gzip'd in, plain out
  const CommandResult r = run("fit-path " + path("in.x3dv") + " -o " + path("out.x3dv") + " --deviation 0.005");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string output = read_file(path("out.x3dv"));
  EXPECT_EQ(output.rfind("#X3D V3.3 utf8\nPROFILE Interchange\nCOMPONENT NURBS:1\nDEF T Transform {}\n"
                         "DEF PATH NurbsPositionInterpolator{order 4 knot[0 0 0 0 ",
                         0),
            0u)
      << output.substr(0, 300);
  const std::string route = "}\nROUTE PATH.value_changed TO T.set_translation\n";
  EXPECT_EQ(output.substr(output.size() - route.size()), route);
  const NurbsCurve curve = curve_in(output, "order ", "knot[", ']', "point[", ']');
  EXPECT_LE(sampled_path_error(curve, frames), 0.005);
  EXPECT_FALSE(std::filesystem::exists(path("cadnurbs-nurbs-protos.wrl")));
}

TEST_F(FitPath, AnX3dXmlUseOfTheRewrittenNodeIsRenamedWithIt) {
  const KeyframePath frames = figure_eight_path(300, 8.0);
  const std::string input = "<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Interchange' version='3.3'>\n<Scene>\n"
                            "<PositionInterpolator DEF='PATH' key='" + keys_text(frames) + "' keyValue='" +
                            key_values_text(frames) + "'/>\n<Group><PositionInterpolator USE='PATH'/></Group>\n</Scene>\n</X3D>\n";
  write_file_atomically(path("in.x3d"), input);
  const CommandResult r = run("fit-path " + path("in.x3d") + " -o " + path("out.x3dz") + " --deviation 0.002");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string output = gunzip(read_file(path("out.x3dz")), "out.x3dz");
  EXPECT_EQ(output.rfind("<?xml version='1.0' encoding='UTF-8'?>\n<X3D profile='Interchange' version='3.3'>\n"
                         "<head><component name='NURBS' level='1'/></head>\n<Scene>\n<NurbsPositionInterpolator DEF='PATH' order='4' knot='",
                         0),
            0u)
      << output.substr(0, 300);
  EXPECT_NE(output.find("</NurbsPositionInterpolator>\n<Group><NurbsPositionInterpolator USE='PATH'/></Group>\n</Scene>\n</X3D>\n"),
            std::string::npos);
  const NurbsCurve curve = curve_in(output, "order='", "knot='", '\'', "point='", '\'');
  EXPECT_LE(sampled_path_error(curve, frames), 0.002);
}

TEST_F(FitPath, PathsItCannotOrNeedNotRewriteAreLeftAsTheyAreAndSaySo) {
  const std::string input =
      "#VRML V2.0 utf8\n"
      "DEF JUMP PositionInterpolator { key [ 0 .5 .5 1 ] keyValue [ 0 0 0 1 0 0 2 0 0 3 0 0 ] }\n"
      "DEF TURN OrientationInterpolator { key [ 0 1 ] keyValue [ 0 0 1 0, 0 0 1 3 ] }\n"
      "DEF TWO PositionInterpolator { key [ 0 1 ] keyValue [ 0 0 0 1 1 1 ] }\n";
  write_file_atomically(path("in.wrl"), input);
  const CommandResult r = run("fit-path " + path("in.wrl") + " -o " + path("out.wrl") + " --deviation 0.01");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(read_file(path("out.wrl")), input);
  EXPECT_FALSE(std::filesystem::exists(path("cadnurbs-nurbs-protos.wrl")));
  const std::string in = path("in.wrl");
  EXPECT_EQ(r.out,
            in + ": PositionInterpolator JUMP (line 2): 4 keys, left as it is: the NURBS would take 197 bytes, not "
                 "fewer\n" +
                in + ": OrientationInterpolator TURN (line 3): 2 keys, left as it is: NurbsOrientationInterpolator "
                     "gives the rotation from +Z to the curve's tangent, which cannot hold a roll about the path\n" +
                in + ": PositionInterpolator TWO (line 4): 2 keys, left as it is: the NURBS would take 106 bytes, "
                     "not fewer\n" +
                path("out.wrl") + ": 0 of 3 interpolators fitted within 0.01; " + std::to_string(input.size()) +
                " -> " + std::to_string(input.size()) + " bytes (" + std::to_string(gzip(input).size()) + " -> " +
                std::to_string(gzip(input).size()) + " gzip'd)\n");
}

TEST_F(FitPath, RefusalsAreOneLineAndWriteNothing) {
  write_file_atomically(path("in.wrl"), vrml_world(circle_path(20, 1.0)));
  CommandResult r = run("fit-path " + path("in.wrl") + " -o " + path("out.x3dv") + " --deviation 0.01");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "cadnurbs fit-path: " + path("out.x3dv") + ": fit-path keeps the file's encoding: " +
                       path("in.wrl") + " is VRML97, " + path("out.x3dv") + " would be X3D classic\n");
  r = run("fit-path " + path("in.wrl") + " -o " + path("out.stl") + " --deviation 0.01");
  EXPECT_EQ(r.status, 2);
  r = run("fit-path " + path("in.wrl") + " -o " + path("out.wrl") + " --deviation 0");
  EXPECT_EQ(r.err, "cadnurbs fit-path: --deviation must be > 0\n");
  write_file_atomically(path("broken.wrl"), "#VRML V2.0 utf8\nWorldInfo { title \"never closed }\n");
  r = run("fit-path " + path("broken.wrl") + " -o " + path("out.wrl") + " --deviation 0.01");
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cadnurbs fit-path: " + path("broken.wrl") + ": line 2: string is not terminated\n");
  write_file_atomically(path("mesh.stl"), "solid x\nendsolid x\n");
  r = run("fit-path " + path("mesh.stl") + " -o " + path("out.wrl") + " --deviation 0.01");
  EXPECT_EQ(r.err, "cadnurbs fit-path: " + path("mesh.stl") +
                       ": not a VRML97 (#VRML V2.0), X3D classic (#X3D) or X3D XML file\n");
  EXPECT_FALSE(std::filesystem::exists(path("out.wrl")));
  EXPECT_FALSE(std::filesystem::exists(path("out.x3dv")));
}

}  // namespace
}  // namespace cadnurbs::test
