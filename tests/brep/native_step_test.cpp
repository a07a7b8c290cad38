// Our own STEP reader (formats/step/native) against OpenCASCADE's reading of the same file, on every STEP
// file of the shared corpus: either the native reader refuses it, with the reason this table expects, or
// its scene passes expect_same_as_occt (native_comparison.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <map>

#include "corpus_manifest.hpp"
#include "analysis/measure/trimmed_surface_area.hpp"
#include "core/repair_trimming_loops.hpp"
#include "formats/step/native/read_step_native.hpp"
#include "native_comparison.hpp"

namespace cadnurbs::test {
namespace {

// Corpus files the native reader hands to OpenCASCADE, and the start of the reason it gives.
const std::map<std::string, std::string>& expected_refusals() {
  static const std::map<std::string, std::string> table = {
      // OpenCASCADE makes a part whose shape holds curve sets besides its B-rep an assembly of its items,
      // each component named after its XCAF label: not matched natively.
      {"step/as1_pe_203.stp", "#769 GEOMETRIC_SET: an item besides the B-rep"},
      {"step/io1-tu-203.stp", "#1203 GEOMETRIC_CURVE_SET: an item besides the B-rep"},
      {"step/splinecage.stp", "#12 GEOMETRIC_CURVE_SET: an item besides the B-rep"},
      // Faces whose trimming curves cannot be fitted (native_face).
      {"step/goteborg.step", "#36 ADVANCED_FACE: trim curve does not follow its edge"},
      // Bands bounded by two whole circles and no seam edge (long tier).
      {"step/11752.stp", "#101 ADVANCED_FACE: a loop wraps 1 times around the surface without closing"},
  };
  return table;
}

// Corpus files where OpenCASCADE's areas are the approximate ones, with the slack its face areas need.
// dm1-id-214: flat discs on QUASI_UNIFORM_SURFACEs bounded by exact rational circles; ours equal pi r^2 to
// 2e-14 (DiscsOnAffinePatchesAreExact below), OCCT's are 6.5e-6 off.
const std::map<std::string, double>& occt_area_slack() {
  // Ventilator (long tier): OCCT's areas are up to 6e-3 off; its face 11, a hexagon less a disc bounded by
  // two LINE-and-CIRCLE loops, is 0.6 % too large in OCCT's reading and exact in ours (test below).
  // linkrods (long tier): OCCT trims its B-spline faces by the file's PCURVEs, ours by the 3D edges
  // inverted onto the surface: the areas differ by up to 9.1e-6 (face 27, measured by `cadnurbs info`),
  // less than face 27 and its mirror twin face 26 differ from each other in either reading (1.7e-5).
  static const std::map<std::string, double> table = {
      {"step/dm1-id-214.stp", 1e-5}, {"step/Ventilator.stp", 1e-2}, {"step/linkrods.step", 2e-5}};
  return table;
}

class NativeStepCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(NativeStepCorpus, SameAsOpenCascade) {
  const std::string relative = GetParam();
  const std::string path = corpus_file(relative);
  const auto refusal = expected_refusals().find(relative);
  BrepTranslation native;
  try {
    native = read_step_native(path);
  } catch (const step::OutsideNativeSubset& outside) {
    ASSERT_NE(refusal, expected_refusals().end()) << "refused: " << outside.what();
    EXPECT_EQ(std::string(outside.what()).rfind(refusal->second, 0), 0u) << outside.what();
    std::printf("| %-28s | refused: %s |\n", relative.c_str(), outside.what());
    return;
  }
  ASSERT_EQ(refusal, expected_refusals().end()) << "read natively, though the table expects a refusal";
  const auto slack = occt_area_slack().find(relative);
  expect_same_as_occt(native, path, relative, slack == occt_area_slack().end() ? 1e-6 : slack->second);
}

INSTANTIATE_TEST_SUITE_P(Corpus, NativeStepCorpus, ::testing::ValuesIn(corpus_paths({"step/"})),
                         [](const auto& info) { return corpus_test_name(info.param); });

// dm1-id-214's discs (radius 5 and 7.5 mm, given in inches) lie on bilinear B-spline patches that are
// affine maps of their planes: their trimming circles are mapped exactly, so their areas are pi r^2.
TEST(NativeStepCorpusExact, DiscsOnAffinePatchesAreExact) {
  const BrepTranslation native = read_step_native(corpus_file("step/dm1-id-214.stp"));
  std::vector<double> areas;
  std::function<void(const SceneNode&)> collect = [&](const SceneNode& node) {
    for (const auto& shape : node.shapes)
      if (const auto* face = std::get_if<TrimmedSurface>(&shape.geometry);
          face && face->surface.u_order == 2 && face->surface.v_order == 2)  // the flat patches
        areas.push_back(trimmed_surface_area(*face, 1e-12));
    for (const auto& child : node.children) collect(child);
  };
  collect(native.scene.root);
  const double pi = 3.14159265358979323846;
  for (double radius : {5.0, 7.5}) {
    const double exact = pi * radius * radius;
    double nearest = 1e300;
    for (double a : areas) nearest = std::min(nearest, std::abs(a - exact));
    EXPECT_LE(nearest, 1e-12 * exact) << "no face of area pi " << radius << "^2";
  }
}

// Ventilator's face 11: a plane bounded by a hexagon of LINEs and a circle of radius 7.45 mm in two
// arcs: its area is the hexagon's (shoelace over its vertices) less pi r^2.
TEST(NativeStepCorpusExact, VentilatorsHexagonLessADisc) {
  const BrepTranslation native = read_step_native(corpus_file("step/Ventilator.stp"));
  const SceneNode* part = &native.scene.root;
  while (part->shapes.empty() && !part->children.empty()) part = &part->children.front();
  ASSERT_GT(part->shapes.size(), 10u);
  const std::vector<Eigen::Vector2d> hexagon = {
      {-4.98087795914, -8.26518933577}, {4.69186074854, -8.43261185614}, {9.64878646194, -0.153035328813},
      {4.9569257134, 8.27957652733},    {-4.69186074854, 8.43261185614}, {-9.64878646194, 0.153035328813}};
  double twice = 0;
  for (std::size_t i = 0; i < hexagon.size(); ++i) {
    const auto& a = hexagon[i];
    const auto& b = hexagon[(i + 1) % hexagon.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  const double radius = std::hypot(3.5717202626, 6.53799008608);
  const double exact = 0.5 * twice - 3.14159265358979323846 * radius * radius;
  const auto& face = std::get<TrimmedSurface>(part->shapes[10].geometry);
  EXPECT_NEAR(trimmed_surface_area(face, 1e-12), exact, 1e-10 * exact);
}

// Parts of the library (Debian's kicad-packages3d, fetched by scripts/fetch-part-library.sh) the corpus
// lacks: the three made of several products placed by NEXT_ASSEMBLY_USAGE_OCCURRENCEs, and solids with
// voids (BREP_WITH_VOIDS). Skipped when the library has not been fetched.
std::string library_step(const std::string& relative) {
  std::string cache;
  if (const char* c = std::getenv("CADNURBS_CACHE")) cache = c;
  else if (const char* x = std::getenv("XDG_CACHE_HOME")) cache = std::string(x) + "/cadnurbs";
  else cache = std::string(std::getenv("HOME") ? std::getenv("HOME") : "") + "/.cache/cadnurbs";
  return cache + "/kicad-packages3d-6.0.10-1/" + relative;
}

class NativeStepLibrary : public ::testing::TestWithParam<std::string> {};

TEST_P(NativeStepLibrary, SameAsOpenCascade) {
  const std::string path = library_step(GetParam());
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not fetched (scripts/fetch-part-library.sh)";
  expect_same_as_occt(read_step_native(path), path, std::filesystem::path(path).filename().string());
}

INSTANTIATE_TEST_SUITE_P(Library, NativeStepLibrary,
                         ::testing::Values("Package_DFN_QFN.3dshapes/Texas_R-PUQFN-N12.step",
                                           "Package_DFN_QFN.3dshapes/QFN-76-1EP_9x9mm_P0.4mm_EP5.81x6.31mm.step",
                                           "Package_DIP.3dshapes/DIP-32_W7.62mm.step",
                                           "Inductor_THT.3dshapes/L_CommonMode_Vertical_L22mm_W20mm_Px10.5mm_Py13.5mm_ProdTech_PDUUAT16.step",
                                           "LED_THT.3dshapes/LED_D20.0mm.step",
                                           // lead wires: extruded whole circles, bounded by a seam edge
                                           "Inductor_THT.3dshapes/L_Axial_L20.0mm_D8.0mm_P5.08mm_Vertical.step",
                                           // end caps revolved from a 213 mm arc through the axis
                                           "Inductor_THT.3dshapes/L_Axial_L6.6mm_D2.7mm_P10.16mm_Horizontal_Vishay_IM-2.step",
                                           "Inductor_THT.3dshapes/L_Radial_D12.0mm_P5.00mm_Fastron_11P.step",
                                           "Connector_Phoenix_MC.3dshapes/PhoenixContact_MC_1,5_2-G-3.5_1x02_P3.50mm_Horizontal.step",
                                           "Connector_Phoenix_MC.3dshapes/PhoenixContact_MCV_1,5_2-G-3.81_1x02_P3.81mm_Vertical.step",
                                           "Connector_PinHeader_2.54mm.3dshapes/PinHeader_2x01_P2.54mm_Vertical.step",
                                           "Connector_PinHeader_2.54mm.3dshapes/PinHeader_1x01_P2.54mm_Horizontal.step",
                                           "LED_THT.3dshapes/LED_Rectangular_W3.9mm_H1.9mm.step",
                                           "Package_BGA.3dshapes/Texas_DSBGA-6_0.9x1.4mm_Layout2x3_P0.5mm.step",
                                           "Package_BGA.3dshapes/WLP-4_0.86x0.86mm_P0.4mm.step",
                                           "Package_DFN_QFN.3dshapes/AMS_QFN-4-1EP_2x2mm_P0.95mm.step",
                                           "Package_DIP.3dshapes/DIP-4_W7.62mm_Socket.step",
                                           "Package_QFP.3dshapes/LQFP-32_5x5mm_P0.5mm.step",
                                           "Resistor_THT.3dshapes/R_Box_L13.0mm_W4.0mm_P9.00mm.step",
                                           // leads of two half-cylinders thinner than D: each half-circle
                                           // must stay two chords, or both halves mesh to one quad
                                           "Resistor_THT.3dshapes/R_Axial_Power_L38.0mm_W6.4mm_P45.72mm.step",
                                           // a lens cylinder tangent to the cut plane: the plane's hole
                                           // touches its outer loop at a vertex (one mesh node)
                                           "LED_THT.3dshapes/LED_D3.0mm_Horizontal_O1.27mm_Z2.0mm.step"),
                         [](const auto& info) { return corpus_test_name(info.param); });

// KiCad's QFP parts keep edges up to 6e-4 mm off faces 0.1 mm across. OpenCASCADE's pcurves there are
// approximations: its areas differ from ours by up to 4.6e-3, and where the exact area is known it is
// OCCT that is off (face 73, a 0.35 x 0.075 mm rectangle bounded by four LINEs: ours to 1e-13, OCCT's
// 2.1e-5 too large). Everything else is compared as on the other parts.
TEST(NativeStepLibraryQfp, ExactWhereOpenCascadeApproximates) {
  const std::string path = library_step("Package_QFP.3dshapes/LQFP-36_7x7mm_P0.65mm.step");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not fetched (scripts/fetch-part-library.sh)";
  const BrepTranslation native = read_step_native(path);
  const SceneNode* part = &native.scene.root;
  while (part->shapes.empty() && !part->children.empty()) part = &part->children.front();
  ASSERT_GT(part->shapes.size(), 73u);
  const auto& rectangle = std::get<TrimmedSurface>(part->shapes[72].geometry);
  EXPECT_NEAR(trimmed_surface_area(rectangle, 1e-10), 0.35 * 0.075, 1e-13 * 0.35 * 0.075);
  expect_same_as_occt(native, path, "LQFP-36_7x7mm_P0.65mm.step", 5e-3);
}

// KiCad's Bourns toroids: a winding's B-spline edge curls round in a small loop of its own, so faces
// bounded by it cross themselves (repair_trimming_loops cuts the small lobe off), and two of its vertices
// lie 0.0119 mm off their curves (moved onto, said). OpenCASCADE reads the part's 408 faces in 15 s; the
// face whose loop loses a lobe of 3 % of its area is 4.947741e-4 mm^2 in OpenCASCADE's reading
// (`cadnurbs info --reader occt`), and its area is compared with that.
TEST(NativeStepLibraryBourns, SmallLoopsCutOffAndVerticesMovedOntoCurves) {
  const std::string path =
      library_step("Inductor_THT.3dshapes/L_CommonMode_Toroid_Vertical_L39.4mm_W20.3mm_Px15.24mm_Py22.86mm_Bourns_8100.step");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " not fetched (scripts/fetch-part-library.sh)";
  BrepTranslation native = read_step_native(path);
  EXPECT_EQ(native.face_count, 408);
  int lobes = 0, moved = 0;
  for (const auto& line : native.repairs) {
    if (line.find("crossed itself") != std::string::npos) ++lobes;
    if (line.find(": a vertex 0.0119 mm off the curve: its end moved onto it") != std::string::npos) ++moved;
  }
  EXPECT_EQ(lobes, 18);
  EXPECT_EQ(moved, 2);
  const std::string face72 = "solid 2 face 72 (Plane): trimming loop 0 crossed itself at (12.7, -31.2): a lobe of 0.0314";
  EXPECT_TRUE(std::any_of(native.repairs.begin(), native.repairs.end(),
                          [&](const std::string& line) { return line.find(face72) != std::string::npos; }));
  // Every loop is simple now: a second repair has nothing to do.
  EXPECT_TRUE(repair_trimming_loops(native.scene).empty());
  const SceneNode& solid = native.scene.root.children.at(1);
  ASSERT_EQ(solid.source_entity, "solid 2");
  const auto& face = std::get<TrimmedSurface>(solid.shapes.at(71).geometry);
  EXPECT_NEAR(trimmed_surface_area(face, 1e-10), 4.947741e-4, 1e-4 * 4.947741e-4);
}

}  // namespace
}  // namespace cadnurbs::test
