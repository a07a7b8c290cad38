// The cadnurbs command as a user runs it: exit codes, messages, files written and not written.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis/mesh/count_boundary_edges.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "converters/file_formats.hpp"
#include "formats/common/file_io.hpp"
#include "samples/capping_shapes.hpp"
#include "command_fixture.hpp"

namespace fs = std::filesystem;
using namespace cadnurbs;

namespace {

using test::CommandResult;
class Cli : public test::CommandTest {};

}  // namespace

TEST_F(Cli, CappingRegeneratesTheCommittedSamplesByteForByte) {
  // STEP and IGES carry a time stamp: SOURCE_DATE_EPOCH=0 makes it reproducible (README).
  const CommandResult r = run("capping --shape all -o " + path("gen") + "/", "SOURCE_DATE_EPOCH=0 ");
  ASSERT_EQ(r.status, 0) << r.err;
  int compared = 0;
  for (const auto& name : capping_shape_names())
    for (const char* ext : {".wrl", ".x3dv", ".x3d", ".stl", ".step", ".iges"}) {
      const std::string committed = std::string(CADNURBS_SOURCE_DIR) + "/samples/" + name + ext;
      EXPECT_EQ(read_file(path("gen/" + name + ext)), read_file(committed)) << committed;
      ++compared;
    }
  EXPECT_EQ(read_file(path("gen/cadnurbs-nurbs-protos.wrl")),
            read_file(std::string(CADNURBS_SOURCE_DIR) + "/samples/cadnurbs-nurbs-protos.wrl"));
  EXPECT_EQ(compared, 24);  // four shapes in six formats
}

TEST_F(Cli, DemoPrintsTheThesisCountsAndTheFilesItWrote) {
  const CommandResult r = run("demo -o " + path("demo"));
  ASSERT_EQ(r.status, 0) << r.err;
  // capping-90: body 21 x 7 points + two 2 x 2 lids = 155 control points; knots 24 + 10 + 2 x 8 = 50;
  // floats 4 x 155 + 50 = 670.
  EXPECT_NE(r.out.find("capping-90               3         155      50          670"), std::string::npos) << r.out;
  for (const auto& name : capping_shape_names())
    for (const char* ext : {".wrl", ".x3dv", ".x3d", ".stl", ".step", ".iges"}) {
      const std::string file = path("demo/" + name + ext);
      EXPECT_TRUE(fs::exists(file)) << file;
      EXPECT_NE(r.out.find(file), std::string::npos) << file;
    }
  // It ends with the storage report of the cappings: a table row per capping, written to report.md too.
  EXPECT_TRUE(fs::exists(path("demo/report.md")));
  for (const auto& name : capping_shape_names())
    EXPECT_NE(r.out.find("| " + path("demo/" + name + ".x3dv") + " | 1 mm |"), std::string::npos) << name;
}

TEST_F(Cli, MissingInputIsOneLineNamingTheFile) {
  const CommandResult r = run("convert " + path("nothing.stl") + " -o " + path("out.wrl"));
  EXPECT_EQ(r.status, 1);
  EXPECT_EQ(r.err, "cadnurbs convert: " + path("nothing.stl") + ": cannot open (No such file or directory)\n");
  EXPECT_FALSE(fs::exists(path("out.wrl")));
}

TEST_F(Cli, TruncatedStlFailsWithTheTriangleAndWritesNothing) {
  const std::string full = read_file(std::string(CADNURBS_SHARED_DIR) + "/corpus/stl/featuretype.STL");
  std::ofstream(path("cut.stl"), std::ios::binary) << full.substr(0, 5101);
  const CommandResult r = run("convert " + path("cut.stl") + " -o " + path("out.x3dv"));
  EXPECT_EQ(r.status, 1);
  EXPECT_NE(r.err.find("triangle 101 of 3476"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1);
  EXPECT_FALSE(fs::exists(path("out.x3dv")));
  for (const auto& entry : fs::directory_iterator(dir_))
    EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos) << entry.path();
}

// A conversion that would write a file without geometry fails, naming what the input held: a VRML file with
// no shape. (The corpus's Rhino files that once did, SubD and Rhino 1 solids, are read now.)
TEST_F(Cli, NothingToWriteFailsNamingWhatTheInputHeld) {
  std::ofstream(path("view.wrl")) << "#VRML V2.0 utf8\nViewpoint { position 0 0 10 }\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {path("view.wrl"), "no geometry to write (the file holds none that cadnurbs reads)"}};
  for (const auto& [input, reason] : cases)
    for (const std::string output : {"out.x3dv", "out.stl", "out.cnb"}) {
      const CommandResult r = run("convert " + input + " -o " + path(output));
      EXPECT_EQ(r.status, 1) << input << " " << output;
      const std::string last = "cadnurbs convert: " + input + ": " + reason + "\n";
      EXPECT_TRUE(r.err.size() >= last.size() && r.err.substr(r.err.size() - last.size()) == last) << r.err;
      EXPECT_FALSE(fs::exists(path(output))) << input << " " << output;
    }
}

// info on a file without geometry says so instead of printing an inside-out box of +-1.8e308.
TEST_F(Cli, InfoOnAFileWithoutGeometrySaysItHasNoBox) {
  std::ofstream(path("view.wrl")) << "#VRML V2.0 utf8\nViewpoint { position 0 0 10 }\n";
  const CommandResult r = run("info " + path("view.wrl"));
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("  bounding box: none (no geometry)\n"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("e+308"), std::string::npos) << r.out;
}

// door.x3dv (white_dune) trims by GLU's rule: a +-10 square about a 1 x 5 domain around a hole, and a
// circle about a corner of the knob's domain. Both loops are cut to the domain, said once per face, and
// the file converts to every output (it was refused: "leaves the surface's domain by 10 of its size").
// In X_ITE the mesh's silhouette differs from the original's on 0.00056 of a 400 x 300 picture.
TEST_F(Cli, LoopsOutsideTheDomainOfVrmlFilesAreCutAsGluDrawsThem) {
  // To a mesh or .cnb the loops are cut when the file is read, and said; VRML/X3D output keeps the
  // file's scene graph, loops as written (GLU-based viewers cut them as they draw), and says so.
  // door.x3dv's 18 nodes of 9 kinds: 2 Transform, Shape, Appearance, Material, NurbsTrimmedSurface and
  // Coordinate, 3 Contour2D, 2 NurbsCurve2D, 1 ContourPolyline2D; in VRML97 each trimmed surface holds a
  // NurbsSurface that holds its points: 18 again.
  const std::string door = std::string(CADNURBS_SHARED_DIR) + "/corpus/vrml/door.x3dv";
  for (const std::string output : {"door.x3dv", "door.wrl", "door.stl", "door.cnb"}) {
    const CommandResult r = run("convert " + door + " -o " + path(output));
    EXPECT_EQ(r.status, 0) << r.err;
    const bool kept = output.ends_with(".x3dv") || output.ends_with(".wrl");
    const std::string as = kept ? "kept as written: " : "";
    EXPECT_NE(r.err.find(door + ": " + as + "scene/node 0/shape 0: trimming loop 0 leaves the surface's domain by 10 of its size: "
                                "cut to the domain, as GLU-based viewers draw it (1 loop left)\n"),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(door + ": " + as + "scene/node 1/shape 0: trimming loop 0 leaves the surface's domain by 0.902 of its "
                                "size: cut to the domain"),
              std::string::npos)
        << r.err;
    EXPECT_EQ(r.out.find(path(output) + ": the whole scene graph kept: 18 nodes of 9 kinds, 0 ROUTEs, 0 PROTO declarations") !=
                  std::string::npos,
              kept)
        << r.out;
    EXPECT_TRUE(fs::exists(path(output))) << output;
  }
}

TEST_F(Cli, VrmlToX3dKeepsTheWholeSceneGraphAndAMeshSaysWhatItLeavesOut) {
  // fish.wrl (white_dune): 3 NURBS surfaces animated by CoordinateInterpolators, 4 spheres, a PROTO'd
  // CurveAnimation, 9 ROUTEs. To X3D every node and ROUTE is kept; the one ccw FALSE has no X3D form.
  const std::string fish = std::string(CADNURBS_SHARED_DIR) + "/corpus/vrml/fish.wrl";
  const CommandResult x3d = run("convert " + fish + " -o " + path("fish.x3d"));
  ASSERT_EQ(x3d.status, 0) << x3d.err;
  EXPECT_EQ(x3d.err, path("fish.x3d") + ": 1 NurbsSurface ccw dropped: X3D's NURBS surfaces have no ccw\n");
  EXPECT_NE(x3d.out.find(path("fish.x3d") + ": the whole scene graph kept: 47 nodes of 11 kinds, 9 ROUTEs, 1 PROTO declarations\n"),
            std::string::npos)
      << x3d.out;
  const std::string text = read_file(path("fish.x3d"));
  EXPECT_NE(text.find("<ROUTE fromNode='CoordinateInterpolator1' fromField='value_changed' toNode='NurbsSurface1_controlPoint' toField='set_point'/>"),
            std::string::npos);
  EXPECT_NE(text.find("<ExternProtoDeclare name='CurveAnimation'"), std::string::npos);
  // To a mesh, the animation has no place: one line per kind, and the surfaces at the animation's rest.
  const CommandResult stl = run("convert " + fish + " -o " + path("fish.stl"));
  ASSERT_EQ(stl.status, 0) << stl.err;
  EXPECT_NE(stl.err.find(fish + ": 3 CoordinateInterpolator routed to NurbsSurface.controlPoint: taken at the first key of its looping animation (fraction 0)\n"),
            std::string::npos)
      << stl.err;
  EXPECT_NE(stl.err.find(fish + ": 9 ROUTE left out: animation and interaction are not converted: the scene is taken at rest\n"),
            std::string::npos)
      << stl.err;
}

TEST_F(Cli, UnknownOptionIsAUsageError) {
  const CommandResult r = run("convert a.stl -o b.wrl --colour red");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "cadnurbs convert: unknown option '--colour' (see cadnurbs convert --help)\n");
}

TEST_F(Cli, OutputNeverOverwritesTheInput) {
  ASSERT_EQ(run("capping --shape capping-post -o " + path("post.wrl")).status, 0);
  const std::string before = read_file(path("post.wrl"));
  const CommandResult r = run("convert " + path("post.wrl") + " -o " + path("post.wrl"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(read_file(path("post.wrl")), before);
}

TEST_F(Cli, EverySubcommandHasHelp) {
  for (const char* command : {"convert", "info", "capping", "demo"}) {
    const CommandResult r = run(std::string(command) + " --help");
    EXPECT_EQ(r.status, 0) << command;
    EXPECT_EQ(r.out.rfind("usage: cadnurbs " + std::string(command), 0), 0u) << command;
  }
}

TEST_F(Cli, StlToVrmlMeshAndBackKeepsEveryTriangle) {
  const std::string stl = std::string(CADNURBS_SHARED_DIR) + "/corpus/stl/plate_holes.STL";
  ASSERT_EQ(run("convert " + stl + " -o " + path("plate.x3dv")).status, 0);
  const CommandResult r = run("convert " + path("plate.x3dv") + " -o " + path("plate.stl"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(fs::file_size(path("plate.stl")), 84u + 50u * 1252u);
}

TEST_F(Cli, InfoListsTheCappingSurfaces) {
  const CommandResult r = run("info " + std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.x3dv");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("body: NURBS surface, degree 2x2, 21x7 control points, 34 knots, rational, 0 trimming loops"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("lid-start: trimmed NURBS surface, degree 1x1, 2x2 control points, 8 knots, polynomial, 1 trimming loops"),
            std::string::npos)
      << r.out;
}

TEST_F(Cli, MeshConversionWritesIndexedFaceSets) {
  const std::string in = std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.x3dv";
  const CommandResult r = run("convert " + in + " -o " + path("mesh.wrl") + " --mesh --steps 4");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string text = read_file(path("mesh.wrl"));
  EXPECT_NE(text.find("IndexedFaceSet"), std::string::npos);
  EXPECT_EQ(text.find("NurbsSurface"), std::string::npos);
}

TEST_F(Cli, InfoNamesSourceSurfaceTypesAndIntegratesTheTrimmedArea) {
  const CommandResult r = run("info " + std::string(CADNURBS_SHARED_DIR) + "/corpus/step/screw.step");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("face 4: ToroidalSurface as trimmed NURBS surface, degree 2x2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("face 7: ConicalSurface as trimmed NURBS surface"), std::string::npos) << r.out;
  // OCCT's BRepGProp::SurfaceProperties of the source gives 1929.332 mm^2 (tests/brep prints it).
  const auto at = r.out.find("total area: ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_NEAR(std::stod(r.out.substr(at + 12)), 1929.332, 1929.332 * 1e-3);
  EXPECT_NE(r.out.find("unit: mm (source file: mm)"), std::string::npos);
}

TEST_F(Cli, HelpExitsZeroAndNamesEveryConvertOption) {
  const CommandResult r = run("--help");
  EXPECT_EQ(r.status, 0);
  for (const char* option : {"--deviation", "--exact-nurbs", "--units", "--pretty"})
    EXPECT_NE(r.out.find(option), std::string::npos) << option;
  EXPECT_EQ(run("").status, 2);
}

TEST_F(Cli, CompactOutputIsSmallerThanExactNurbsAndGzipFormsReadBack) {
  const std::string step = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/featuretype.STEP";
  const CommandResult compact = run("convert " + step + " -o " + path("part.x3dv"));
  ASSERT_EQ(compact.status, 0) << compact.err;
  EXPECT_NE(compact.out.find("planar faces as exact polygons"), std::string::npos) << compact.out;
  ASSERT_EQ(run("convert " + step + " --exact-nurbs -o " + path("exact.x3dv")).status, 0);
  const std::string exact = read_file(path("exact.x3dv"));
  EXPECT_EQ(exact.find("IndexedFaceSet"), std::string::npos);  // every face a NURBS, as in the source
  EXPECT_LT(fs::file_size(path("part.x3dv")), fs::file_size(path("exact.x3dv")) / 2);
  // gzip'd outputs hold the same text; every form reads back with the same area.
  const auto total_area = [&](const std::string& file) {
    const CommandResult info = run("info " + file);
    EXPECT_EQ(info.status, 0) << info.err;
    return std::stod(info.out.substr(info.out.find("total area: ") + 12));
  };
  const double area = total_area(path("part.x3dv"));
  // info integrates each face to 1e-6 and prints 7 digits: two forms of one part agree to about 2e-6.
  EXPECT_NEAR(total_area(path("exact.x3dv")), area, 2e-6 * area);
  for (const char* ext : {".x3dvz", ".wrz", ".x3dz", ".wrl.gz"}) {
    ASSERT_EQ(run("convert " + step + " -o " + path(std::string("part") + ext)).status, 0) << ext;
    const std::string bytes = read_file(path(std::string("part") + ext));
    ASSERT_GE(bytes.size(), 2u);
    EXPECT_EQ(static_cast<unsigned char>(bytes[0]), 0x1f) << ext;
    EXPECT_NEAR(total_area(path(std::string("part") + ext)), area, 1e-6 * area) << ext;
  }
  EXPECT_TRUE(fs::exists(path("cadnurbs-nurbs-protos.wrl")));  // beside the .wrz
}

TEST_F(Cli, UnitsScaleTheOutputAndAreRecorded) {
  const std::string step = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/screw.step";
  ASSERT_EQ(run("convert " + step + " -o " + path("mm.x3dv")).status, 0);
  ASSERT_EQ(run("convert " + step + " --units kicad -o " + path("kicad.x3dv")).status, 0);
  EXPECT_NE(read_file(path("kicad.x3dv")).find("\"unit kicad\""), std::string::npos);
  const CommandResult mm = run("info " + path("mm.x3dv")), kicad = run("info " + path("kicad.x3dv"));
  const double mm_area = std::stod(mm.out.substr(mm.out.find("total area: ") + 12));
  const double kicad_area = std::stod(kicad.out.substr(kicad.out.find("total area: ") + 12));
  EXPECT_NEAR(kicad_area * 2.54 * 2.54, mm_area, 1e-5 * mm_area);
  EXPECT_NE(kicad.out.find("unit: kicad"), std::string::npos) << kicad.out;
  const CommandResult bad = run("convert " + step + " --units furlong -o " + path("f.x3dv"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "cadnurbs convert: --units: unknown unit 'furlong' (mm, cm, m, in, kicad)\n");
}

TEST_F(Cli, MeshesGoToObjAndTheTessellationIsReported) {
  const std::string step = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/screw.step";
  const CommandResult r = run("convert " + step + " --deviation 0.1 -o " + path("screw.obj"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("0 uncertified triangles, 0 unshared edge uses"), std::string::npos) << r.out;
  const std::string obj = read_file(path("screw.obj"));
  EXPECT_EQ(obj.rfind("# cadnurbs", 0), 0u);
  EXPECT_GT(std::count(obj.begin(), obj.end(), 'f'), 100);
}

TEST_F(Cli, OwnNurbsFileMeshesWatertightBySewing) {
  // screw.step is a closed solid: its .x3dv names no edges, so `convert --mesh` sews them back (issue 9).
  const std::string step = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/screw.step";
  ASSERT_EQ(run("convert " + step + " -o " + path("screw.x3dv")).status, 0);
  const CommandResult r = run("convert " + path("screw.x3dv") + " --mesh -o " + path("screw.stl"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find(": 22 shared edges, 0 open boundary pieces"), std::string::npos) << r.out;
  const Scene mesh = read_scene(path("screw.stl"));
  ASSERT_EQ(mesh.root.shapes.size(), 1u);
  const EdgeCounts edges = count_boundary_edges(weld_exact(std::get<TriangleMesh>(mesh.root.shapes[0].geometry)));
  EXPECT_EQ(edges.boundary, 0);
  EXPECT_EQ(edges.non_manifold, 0);
}

TEST_F(Cli, CheckAreasReportsFacesBeyondTheirAllowance) {
  const std::string step = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/screw.step";
  const CommandResult r = run("convert " + step + " --mesh --check-areas -o " + path("screw.stl"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("0 uncertified triangles, 0 unshared edge uses, 0 faces beyond their area allowance"),
            std::string::npos)
      << r.out;
  const CommandResult plain = run("convert " + step + " --mesh -o " + path("plain.stl"));
  EXPECT_EQ(plain.out.find("area allowance"), std::string::npos) << plain.out;  // only when asked
}
