// .cnb round trips: the bundled capping samples (compact .x3dv) and a corpus STEP part, at D = 1 mm and
// 0.01 mm: same counts, same shared-edge numbers, measured deviation within D and within the writer's
// bound; the steps are the coarsest the bound allows; sizes against the .x3dv and its gzip.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iostream>

#include "analysis/compaction/compact_scene.hpp"
#include "analysis/measure/paired_scene_deviation.hpp"
#include "analysis/tessellation/plan_tessellation_hints.hpp"
#include "core/bounding_box.hpp"
#include "core/knot_insertion.hpp"
#include "core/nurbs_surface.hpp"
#include "formats/cnb/cnb_numbers.hpp"
#include "formats/cnb/cnb_quantisation.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "formats/common/gzip.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"
#include "tests/cnb/expect_same_mesh_on_grid.hpp"

namespace cadnurbs {
namespace {

std::string sample_path(const std::string& name) { return std::string(CADNURBS_SOURCE_DIR) + "/samples/" + name; }
const std::string corpus_part = std::string(CADNURBS_SHARED_DIR) + "/corpus/step/dm1-id-214.stp";

const Scene& corpus_scene() {
  static const Scene scene = read_step(corpus_part).scene;
  return scene;
}

// The same counts, but for the trimming curves' spare knots the writer removed (`removed_knots`, counted once
// for geometry that repeats): each takes one knot and one control point with it.
void expect_same_counts(const Scene& a, const Scene& b, long removed_knots) {
  const SceneCounts x = count_entities(a), y = count_entities(b);
  EXPECT_EQ(x.surfaces, y.surfaces);
  EXPECT_EQ(x.trimmed_surfaces, y.trimmed_surfaces);
  EXPECT_EQ(x.curves, y.curves);
  EXPECT_EQ(x.meshes, y.meshes);
  EXPECT_EQ(x.control_points, y.control_points);
  EXPECT_EQ(x.knots, y.knots);
  EXPECT_EQ(x.trim_loops, y.trim_loops);
  EXPECT_LE(y.trim_knots, x.trim_knots);
  EXPECT_EQ(x.trim_knots - y.trim_knots, x.trim_control_points - y.trim_control_points);
  EXPECT_GE(x.trim_knots - y.trim_knots, removed_knots);
  EXPECT_EQ(x.trim_knots == y.trim_knots, removed_knots == 0);
  EXPECT_EQ(x.polygon_meshes, y.polygon_meshes);
  EXPECT_EQ(x.polygons, y.polygons);
  EXPECT_EQ(x.mesh_triangles, y.mesh_triangles);
}

// Every loop's shared-edge numbers, in scene order.
std::vector<TrimEdgeRef> edge_refs(const Scene& scene) {
  std::vector<TrimEdgeRef> refs;
  for_each_shape(scene, [&](const Shape& s, const Eigen::Affine3d&, const Colour&) {
    if (const auto* t = std::get_if<TrimmedSurface>(&s.geometry))
      for (const auto& loop : t->loops) refs.insert(refs.end(), loop.edges.begin(), loop.edges.end());
  });
  return refs;
}

struct RoundTrip {
  std::string bytes;
  Scene decoded;
  CnbWriteReport report;
  PairedDeviation measured;
};

RoundTrip round_trip(const Scene& scene, double deviation, CnbOptions::Coder coder = CnbOptions::Coder::smallest) {
  RoundTrip r;
  CnbOptions options;
  options.max_deviation = deviation;
  options.coder = coder;
  r.bytes = write_cnb(scene, options, &r.report);
  r.decoded = read_cnb(r.bytes, "part.cnb");
  r.measured = paired_scene_deviation(scene, r.decoded);
  return r;
}

void expect_round_trip(const Scene& scene, double deviation, const std::string& what) {
  SCOPED_TRACE(what + " at D = " + std::to_string(deviation));
  const RoundTrip r = round_trip(scene, deviation);
  expect_same_counts(scene, r.decoded, r.report.trim_knots_removed);
  EXPECT_EQ(edge_refs(scene), edge_refs(r.decoded));
  EXPECT_EQ(r.decoded.unit.name, scene.unit.name);
  EXPECT_GT(r.measured.samples, 300);
  EXPECT_LE(r.measured.max(), r.report.deviation_bound());
  EXPECT_LE(r.report.deviation_bound(), deviation);
  // The quantisation is not idle: the measured move is a fair part of the bound.
  EXPECT_GT(r.measured.max(), 0.05 * deviation);
  std::cout << what << " D=" << deviation << ": " << r.bytes.size() << " bytes (payload " << r.report.payload_bytes
            << ", deflate " << r.report.deflate_bytes << ", arithmetic " << r.report.arithmetic_bytes
            << "); measured surfaces " << r.measured.surfaces << ", boundaries " << r.measured.boundaries
            << ", meshes " << r.measured.meshes << "; bound " << r.report.deviation_bound() << "\n";
}

class CappingSample : public ::testing::TestWithParam<std::string> {};

TEST_P(CappingSample, RoundTripWithinDeviation) {
  const Scene scene = read_vrml(sample_path(GetParam() + ".x3dv"));
  for (double d : {1.0, 0.01}) expect_round_trip(scene, d, GetParam());
}

INSTANTIATE_TEST_SUITE_P(Samples, CappingSample, ::testing::Values("capping-90", "capping-end", "capping-post"));

TEST(CnbCorpus, StepPartRoundTripWithinDeviation) {
  const Scene& scene = corpus_scene();
  ASSERT_GT(count_entities(scene).surfaces, 10);
  for (double d : {1.0, 0.01}) expect_round_trip(scene, d, "dm1-id-214.stp");
}

// A second corpus part, with rational B-spline and planar faces.
TEST(CnbCorpus, RationalPartRoundTripWithinDeviation) {
  const Scene scene = read_step(std::string(CADNURBS_SHARED_DIR) + "/corpus/step/io1-tu-203.stp").scene;
  for (double d : {1.0, 0.01}) expect_round_trip(scene, d, "io1-tu-203.stp");
}

// A rational surface with many distinct weights (a fitted or deformed one): its weights are rounded on
// a logarithmic grid, and the surface stays within the bound that allows for it.
TEST(CnbRoundTrip, ManyDistinctWeightsRoundedWithinDeviation) {
  NurbsSurface s;
  s.u_order = s.v_order = 3;
  s.u_count = s.v_count = 6;
  s.u_knots = s.v_knots = {0, 0, 0, 1, 2, 3, 4, 4, 4};
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      s.points.emplace_back(20.0 * i, 20.0 * j, 15.0 * std::sin(i + 0.7 * j));
      s.weights.push_back(0.5 + 0.25 * (1 + std::sin(3.1 * i + 1.3 * j)));
    }
  Scene scene;
  scene.root.shapes.push_back({"warped", TrimmedSurface{s, {domain_loop(s)}}, std::nullopt});
  for (double d : {1.0, 0.01}) {
    const RoundTrip r = round_trip(scene, d);
    EXPECT_EQ(r.report.quantised_weight_nets, 1);
    const auto& back = std::get<TrimmedSurface>(r.decoded.root.shapes[0].geometry).surface;
    double largest_change = 0;
    for (size_t i = 0; i < s.weights.size(); ++i)
      largest_change = std::max(largest_change, std::abs(back.weights[i] / s.weights[i] - 1));
    EXPECT_GT(largest_change, 0.0);
    EXPECT_LE(r.measured.max(), r.report.deviation_bound());
    EXPECT_LE(r.report.deviation_bound(), d);
    EXPECT_GT(r.measured.surfaces, 0.1 * d);
  }
}

// A flat square of 100 mm, its domain the same square.
NurbsSurface square_plate() {
  NurbsSurface plate;
  plate.u_order = plate.v_order = 2;
  plate.u_count = plate.v_count = 2;
  plate.u_knots = plate.v_knots = {0, 0, 100, 100};
  plate.points = {{0, 0, 0}, {100, 0, 0}, {0, 100, 0}, {100, 100, 0}};
  return plate;
}

// A hole in a plate bounded by a pcurve such as a kernel's approximation gives: a closed cubic with 48
// knots at values no short decimal reaches (each written as a float64). The writer removes the knots the
// curve does not need within the part of the trims' budget their grid leaves, and the boundary stays within
// the bound, which includes that part.
TEST(CnbRoundTrip, ApproximatedTrimCurvesLoseTheirSpareKnotsWithinTheBound) {
  const NurbsSurface plate = square_plate();
  NurbsCurve hole;
  hole.dimension = 2;
  hole.order = 4;
  hole.knots = {0, 0, 0, 0, 1, 2, 3, 4, 5, 5, 5, 5};
  for (int i = 0; i < 8; ++i) {
    const double a = i < 7 ? -2 * M_PI * i / 7 : 0;  // clockwise: a hole
    hole.points.emplace_back(50 + 30 * std::cos(a), 50 + 30 * std::sin(a), 0);
  }
  std::vector<double> extra;
  for (int k = 1; k < 50; ++k)
    if (k % 10 != 0) extra.push_back(0.1 * k + 0.01 * std::sqrt(2.0) * std::sin(k));
  const NurbsCurve refined = refine_knots(hole, extra);
  ASSERT_EQ(refined.points.size(), hole.points.size() + extra.size());
  TrimLoop loop;
  loop.segments.emplace_back(refined);
  Scene scene;
  scene.root.shapes.push_back({"plate", TrimmedSurface{plate, {domain_loop(plate), loop}}, std::nullopt});
  for (double d : {1.0, 0.01}) {
    SCOPED_TRACE("D = " + std::to_string(d));
    const RoundTrip r = round_trip(scene, d);
    const auto& back = std::get<TrimmedSurface>(r.decoded.root.shapes[0].geometry);
    const auto& curve = std::get<NurbsCurve>(back.loops[1].segments[0]);
    EXPECT_GE(r.report.trim_knots_removed, 40);
    EXPECT_LE(curve.points.size(), hole.points.size() + 4);
    EXPECT_LE(r.measured.max(), r.report.deviation_bound());
    EXPECT_LE(r.report.deviation_bound(), d);
    EXPECT_GT(r.measured.boundaries, 0.0);
    // 45 float64 knots alone would take 360 bytes.
    EXPECT_LT(r.bytes.size(), 200u);
  }
}

// A hole whose boundary a kernel approximated at degree 7 (as the DTMB bow's, at degree 8): 60 control
// points in 53 spans, their knots no short decimals. Knot removal keeps every span and its float64 knot;
// refit_cubic_within gives up the parametrisation and writes a cubic on whole-number knots, at D = 1 mm.
// (At 0.1 mm the curve must stay within about 1e-4 of its (u,v), and knot removal's degree-7 curve of 37
// points codes smaller: the writer keeps whichever loops cost less.)
TEST(CnbRoundTrip, ApproximatedTrimCurvesAreRefitAsCubicsWithinTheBound) {
  const NurbsSurface plate = square_plate();
  NurbsCurve hole;
  hole.dimension = 2;
  hole.order = 8;
  const int count = 60, spans = count - hole.order + 1;
  hole.knots.assign(hole.order, 0.0);
  for (int i = 1; i < spans; ++i) {
    const double s = static_cast<double>(i) / spans;
    hole.knots.push_back(std::sqrt(2.0) * (s + 0.3 * s * (1 - s)));
  }
  hole.knots.insert(hole.knots.end(), hole.order, std::sqrt(2.0));
  for (int i = 0; i < count; ++i) {
    const double a = i < count - 1 ? -2 * M_PI * i / (count - 1) : 0;  // clockwise: a hole
    hole.points.emplace_back(50 + (30 + 3 * std::sin(3 * a)) * std::cos(a), 50 + 30 * std::sin(a), 0);
  }
  TrimLoop loop;
  loop.segments.emplace_back(hole);
  Scene scene;
  scene.root.shapes.push_back({"plate", TrimmedSurface{plate, {domain_loop(plate), loop}}, std::nullopt});
  const double d = 1.0;
  const RoundTrip r = round_trip(scene, d);
  const auto& back = std::get<TrimmedSurface>(r.decoded.root.shapes[0].geometry);
  const auto& curve = std::get<NurbsCurve>(back.loops[1].segments[0]);
  EXPECT_EQ(curve.order, 4);
  EXPECT_LE(curve.points.size(), 30u);
  for (double k : curve.knots) EXPECT_EQ(k, std::round(k));
  EXPECT_LE(r.measured.max(), r.report.deviation_bound());
  EXPECT_LE(r.report.deviation_bound(), d);
  EXPECT_GT(r.measured.boundaries, 0.0);
  // 54 float64 knots alone would take 432 bytes.
  EXPECT_LT(r.bytes.size(), 160u);
}

// A swept surface: its weights are a profile's (u) times a path's (v), each product rounded to 12
// significant digits as a STEP file writes it, so the products of the factors are not the file's values
// bit for bit. With `break_product`, one weight is off the product by 0.1%.
Scene swept_surface(bool break_product) {
  const double c45 = 0.707106781187;
  const std::vector<double> profile = {1, c45, 1, 0.894427191, 1, c45, 1, 0.948683298051, 1};
  const std::vector<double> path = {1, c45, 1, c45, 1};
  NurbsSurface s;
  s.u_order = s.v_order = 3;
  s.u_count = 9;
  s.v_count = 5;
  s.u_knots = {0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4};
  s.v_knots = {0, 0, 0, 1, 1, 2, 2, 2};
  char digits[32];
  for (int j = 0; j < s.v_count; ++j)
    for (int i = 0; i < s.u_count; ++i) {
      s.points.emplace_back(10.0 * i, 12.0 * j, 6.0 * std::sin(i + 0.7 * j));
      std::snprintf(digits, sizeof digits, "%.12g", profile[i] * path[j]);
      s.weights.push_back(std::stod(digits));
    }
  if (break_product) s.weights[s.index(4, 2)] *= 1.001;
  Scene scene;
  scene.root.shapes.push_back({"swept", TrimmedSurface{s, {domain_loop(s)}}, std::nullopt});
  return scene;
}

// Its weights go into the file as the two factors (9 + 5 values, not 45 rounded ones) and come back within
// the products' rounding; the surface stays within the bound, which allows for that rounding.
TEST(CnbRoundTrip, SweptSurfaceWeightsWrittenAsFactors) {
  const Scene scene = swept_surface(false);
  const auto& weights = std::get<TrimmedSurface>(scene.root.shapes[0].geometry).surface.weights;
  for (double d : {1.0, 0.01}) {
    SCOPED_TRACE("D = " + std::to_string(d));
    const RoundTrip r = round_trip(scene, d);
    EXPECT_EQ(r.report.factored_weight_nets, 1);
    EXPECT_EQ(r.report.quantised_weight_nets, 0);
    const auto& back = std::get<TrimmedSurface>(r.decoded.root.shapes[0].geometry).surface.weights;
    ASSERT_EQ(back.size(), weights.size());
    double largest_change = 0;
    for (size_t i = 0; i < weights.size(); ++i)
      largest_change = std::max(largest_change, std::abs(back[i] / weights[i] - 1));
    EXPECT_GT(largest_change, 0.0);
    EXPECT_LT(largest_change, 1e-10);
    EXPECT_LE(r.measured.max(), r.report.deviation_bound());
    EXPECT_LE(r.report.deviation_bound(), d);
    EXPECT_GT(r.measured.surfaces, 0.1 * d);
    // The same surface with one weight off the product rounds all 45 (mode 2, half the trim share).
    const RoundTrip rounded = round_trip(swept_surface(true), d);
    EXPECT_EQ(rounded.report.factored_weight_nets, 0);
    EXPECT_EQ(rounded.report.quantised_weight_nets, 1);
    EXPECT_LT(r.report.weight_bytes + 20, rounded.report.weight_bytes);
    std::cout << "swept D=" << d << ": " << r.bytes.size() << " bytes with factors (weights " << r.report.weight_bytes
              << " payload bytes), " << rounded.bytes.size() << " rounded (" << rounded.report.weight_bytes << ")\n";
  }
}

// The factors come from the row and column through the largest weight; a net that is no outer product,
// or one of a single value, has none.
TEST(CnbWeightFactors, OuterProductsOnly) {
  // u = (0.5, 2, 1), v = (1, 0.25): the largest weight (2) is not at the first point.
  const std::vector<double> w = {0.5, 2, 1, 0.125, 0.5, 0.25};
  const auto f = cnb::weight_factors(w, 3, 2, 1e-6);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->u, (std::vector<double>{0.5, 2, 1}));
  EXPECT_EQ(f->v, (std::vector<double>{1, 0.25}));
  EXPECT_EQ(f->relative_error, 0.0);
  std::vector<double> off = w;
  off[5] = 0.26;
  EXPECT_FALSE(cnb::weight_factors(off, 3, 2, 1e-6));
  const auto loose = cnb::weight_factors(off, 3, 2, 0.05);
  ASSERT_TRUE(loose);
  EXPECT_NEAR(loose->relative_error, 0.01 / 0.26, 1e-12);
  EXPECT_FALSE(cnb::weight_factors(std::vector<double>(6, 0.7), 3, 2, 1e-6));  // one value: a table of one
  EXPECT_FALSE(cnb::weight_factors({1, 0.5, 1, 0.5}, 2, 2, 1e-6));             // 2 + 2 factors for 4 weights
}

// The moulded capping's rational sweep (73 x 7 weights from 73 + 7), at 1e-3 of its diagonal.
TEST(CnbRoundTrip, MouldedCappingWeightsWrittenAsFactors) {
  const Scene scene = read_vrml(sample_path("capping-moulded.x3dv"));
  const double d = 1e-3 * scene_bounding_box(scene).diagonal().norm();
  const RoundTrip r = round_trip(scene, d);
  EXPECT_EQ(r.report.factored_weight_nets, 1);
  EXPECT_EQ(r.report.quantised_weight_nets, 0);
  EXPECT_LE(r.measured.max(), r.report.deviation_bound());
  EXPECT_LE(r.report.deviation_bound(), d);
  EXPECT_LT(r.report.weight_bytes, 260u);  // the weights' payload bytes; 1,178 when they were rounded
  std::cout << "capping-moulded D=" << d << ": " << r.bytes.size() << " bytes, weights " << r.report.weight_bytes
            << " payload bytes\n";
}

// The entropy stage changes the bytes, never what they decode to. (write_cnb keeps the smallest of several
// payloads, with and without the trims' spare knots among them, and which is smallest can depend on the
// coder: payloads of one size are the same payload.)
TEST(CnbCorpus, EveryEntropyCoderDecodesToTheSameScene) {
  const Scene& scene = corpus_scene();
  std::vector<RoundTrip> trips;
  for (auto coder : {CnbOptions::Coder::deflate, CnbOptions::Coder::arithmetic, CnbOptions::Coder::arithmetic_prior,
                     CnbOptions::Coder::arithmetic_two_rates})
    trips.push_back(round_trip(scene, 0.01, coder));
  int same_payloads = 0;
  for (size_t i = 0; i < trips.size(); ++i) {
    EXPECT_LE(trips[i].measured.max(), trips[i].report.deviation_bound()) << i;
    for (size_t j = i + 1; j < trips.size(); ++j) {
      EXPECT_NE(trips[i].bytes, trips[j].bytes);
      if (trips[i].report.payload_bytes != trips[j].report.payload_bytes) continue;
      ++same_payloads;
      EXPECT_EQ(paired_scene_deviation(trips[i].decoded, trips[j].decoded).max(), 0.0) << i << " " << j;
      EXPECT_EQ(trips[i].measured.max(), trips[j].measured.max()) << i << " " << j;
    }
  }
  EXPECT_GE(same_payloads, 1);
}

// What the samples lack: a 3D rational curve, a triangle mesh with normals, a rotated and translated
// node, colours and names on nodes and shapes.
TEST(CnbRoundTrip, CurvesMeshesTransformsColoursNames) {
  Scene scene;
  scene.unit = {"inch", 25.4};
  scene.root.name = "assembly";
  scene.root.colour = Colour{0.1, 0.2, 0.3};
  SceneNode placed;
  placed.name = "placed";
  placed.transform = Eigen::Translation3d(10, 20, 30) * Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 2, 3).normalized());
  NurbsCurve rail;
  rail.order = 3;
  rail.knots = {0, 0, 0, 1, 2, 3, 3, 3};
  rail.points = {{0, 0, 0}, {10, 3, 1}, {20, -4, 2}, {30, 5, 3.3333}, {40, 0, 4}};
  rail.weights = {1, 0.7071067811865476, 1, 0.7071067811865476, 1};
  placed.shapes.push_back({"rail", rail, Colour{1, 0.5, 0}});
  TriangleMesh tetrahedron;
  tetrahedron.positions = {{0, 0, 0}, {5.55, 0, 0}, {0, 5.55, 0}, {0, 0, 5.55}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& t : tetrahedron.triangles) {
    const auto& p = tetrahedron.positions;
    const Eigen::Vector3d n = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).normalized();
    for (int k = 0; k < 3; ++k) tetrahedron.corner_normals.push_back(n);
  }
  placed.shapes.push_back({"fallback", tetrahedron, std::nullopt});
  scene.root.children.push_back(placed);

  const RoundTrip r = round_trip(scene, 0.1);
  EXPECT_EQ(r.decoded.unit.name, "inch");
  EXPECT_EQ(r.decoded.unit.millimetres, 25.4);
  EXPECT_EQ(r.decoded.root.name, "assembly");
  ASSERT_TRUE(r.decoded.root.colour);
  EXPECT_NEAR(r.decoded.root.colour->g, 0.2, 0.5 / 65535);
  ASSERT_EQ(r.decoded.root.children.size(), 1u);
  const SceneNode& back = r.decoded.root.children[0];
  EXPECT_EQ(back.name, "placed");
  EXPECT_TRUE(back.transform.matrix() == placed.transform.matrix());
  ASSERT_EQ(back.shapes.size(), 2u);
  EXPECT_EQ(back.shapes[0].name, "rail");
  ASSERT_TRUE(back.shapes[0].colour);
  EXPECT_EQ(back.shapes[0].colour->r, 1.0);
  EXPECT_NEAR(back.shapes[0].colour->g, 0.5, 0.5 / 65535);
  const auto& curve = std::get<NurbsCurve>(back.shapes[0].geometry);
  EXPECT_EQ(curve.knots, rail.knots);
  EXPECT_EQ(curve.weights, rail.weights);
  EXPECT_EQ(back.shapes[1].name, "fallback");
  EXPECT_FALSE(back.shapes[1].colour);
  const auto& mesh = std::get<TriangleMesh>(back.shapes[1].geometry);
  EXPECT_EQ(mesh.triangles, tetrahedron.triangles);
  ASSERT_EQ(mesh.corner_normals.size(), tetrahedron.corner_normals.size());
  for (size_t i = 0; i < mesh.corner_normals.size(); ++i)
    EXPECT_LE((mesh.corner_normals[i] - tetrahedron.corner_normals[i]).cwiseAbs().maxCoeff(), 0.5 / 32767 + 1e-12);
  EXPECT_GT(r.measured.curves, 0.0);
  EXPECT_GT(r.measured.meshes, 0.0);
  EXPECT_LE(r.measured.max(), r.report.deviation_bound());
  EXPECT_LE(r.report.deviation_bound(), 0.1);
}

// Knots written as 17-digit decimals from -a to a: numerators near -2^53 and 2^53, whose difference
// exceeds 2^53 (a KiCad Phoenix connector's pcurve; the reader refused its own file).
TEST(CnbRoundTrip, KnotsSymmetricAboutZeroWithSeventeenDigits) {
  const double a = 0.05950000000000001;  // 5950000000000001 / 10^17 exactly: no shorter decimal
  NurbsCurve curve;
  curve.order = 3;
  curve.knots = {-a, -a, -a, a, a, a};
  curve.points = {{0, 0, 0}, {1, 2, 0}, {2, 0, 1}};
  Scene scene;
  scene.root.shapes.push_back({"curve", curve, std::nullopt});
  const RoundTrip r = round_trip(scene, 0.01);
  EXPECT_EQ(std::get<NurbsCurve>(r.decoded.root.shapes[0].geometry).knots, curve.knots);
}

// Doubling any step would let the bound exceed its share of D: the steps are the coarsest.
TEST(CnbSteps, CoarsestTheBoundAllows) {
  const Scene& scene = corpus_scene();
  for (double d : {1.0, 0.01}) {
    CnbOptions options;
    options.max_deviation = d;
    const double q = cnb::point_step(scene, options);
    const double scale = largest_world_scale(scene);
    EXPECT_NEAR(q * std::sqrt(3.0) / 2.0 * scale, (1 - options.trim_share) * d, 1e-12 * d);
    EXPECT_GT(2 * q * std::sqrt(3.0) / 2.0 * scale, (1 - options.trim_share) * d);
    int faces = 0;
    for_each_shape(scene, [&](const Shape& s, const Eigen::Affine3d& world, const Colour&) {
      const auto* t = std::get_if<TrimmedSurface>(&s.geometry);
      if (!t || surface_derivative_bound(t->surface) == 0) return;
      const double face_scale = transform_scale(world);
      const int e = cnb::trim_step_exponent(t->surface, options, face_scale);
      EXPECT_LE(cnb::trim_bound(t->surface, e, face_scale), options.trim_share * d);
      EXPECT_GT(cnb::trim_bound(t->surface, e + 1, face_scale), options.trim_share * d);
      ++faces;
    });
    EXPECT_GT(faces, 10);
  }
}

// A scaled node: the grid shrinks with the scale so that the world deviation stays within D.
TEST(CnbSteps, ScaledNodesKeepTheWorldDeviation) {
  Scene scene = read_vrml(sample_path("capping-90.x3dv"));
  scene.root.transform = Eigen::Affine3d(Eigen::Scaling(3.0));
  const RoundTrip r = round_trip(scene, 1.0);
  EXPECT_LE(r.measured.max(), 1.0);
  EXPECT_GT(r.measured.max(), 0.05);
}

// A step chosen by the caller (CnbOptions::measured_point_step) may be coarser than the worst rounding
// allows: the bound is then the largest move as decoded, through the world transform. A fan on decimal
// corners in a node scaled by 2: on the grid 0.25 only its apex (0.6, 0.25, 0.05) moves, by
// (-0.1, 0, -0.05), so 2·√0.0125 ≈ 0.224 in the world, where the worst rounding would be 0.433.
Scene decimal_fan() {
  TriangleMesh fan;
  fan.positions = {{0, 0, 0}, {1, 0, 0}, {1, 0.5, 0}, {0, 0.5, 0}, {0.6, 0.25, 0.05}};
  fan.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  Scene scene;
  scene.root.transform = Eigen::Affine3d(Eigen::Scaling(2.0));
  scene.root.shapes.push_back({"fan", fan, std::nullopt});
  return scene;
}

TEST(CnbSteps, AMeasuredStepBoundsThePointsByTheirLargestMove) {
  const Scene scene = decimal_fan();
  EXPECT_NEAR(cnb::largest_point_move(scene, 0.25), 2 * std::sqrt(0.0125), 1e-12);
  EXPECT_NEAR(cnb::largest_point_move(scene, 0.05), 0.0, 1e-15);  // (0.6 is 12 steps to a rounding)
  EXPECT_EQ(cnb::collapsed_faces(scene, 0.25), 0);
  EXPECT_EQ(cnb::collapsed_faces(scene, 1.0), 2);  // the apex rounds onto (1, 0, 0)

  CnbOptions options;
  options.max_deviation = 0.4;  // the worst rounding allows a step of 0.139
  options.free_mesh_points = false;  // each vertex where rounding puts it: compared by position below
  ASSERT_LT(cnb::point_step(scene, options), 0.25);
  options.measured_point_step = 0.25;
  CnbWriteReport report;
  const std::string bytes = write_cnb(scene, options, &report);
  EXPECT_EQ(report.point_step, 0.25);
  EXPECT_NEAR(report.point_bound, 2 * std::sqrt(0.0125), 1e-12);
  EXPECT_LE(report.deviation_bound(), 0.4);
  const Scene decoded = read_cnb(bytes, "fan.cnb");
  expect_same_mesh_on_grid(std::get<TriangleMesh>(scene.root.shapes[0].geometry),
                           std::get<TriangleMesh>(decoded.root.shapes[0].geometry), 0.25);

  // On 0.3 the corner (1, 0.5) moves to (0.9, 0.6): 2·√0.02 ≈ 0.283 in the world, above (1 - 0.4)·0.4.
  options.measured_point_step = 0.3;
  const double step = static_cast<float>(0.3);
  try {
    write_cnb(scene, options);
    FAIL() << "a step that moves points beyond their share was written";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "cnb: on a grid of step " + std::to_string(step) + " points move up to " +
                                         std::to_string(cnb::largest_point_move(scene, step)) +
                                         ", more than their share of D (0.240000)");
  }
}

// The .x3dv as `convert` writes it: compact (or --exact-nurbs), with tessellation hints for 1e-3 of the
// diagonal, as the sample files are.
std::string x3dv_as_convert_writes(const Scene& scene) {
  VrmlWriteOptions options;
  options.display_deviation = 1e-3 * scene_bounding_box(scene).diagonal().norm();
  options.tessellation_hints = &plan_tessellation_hints;
  return format_vrml(scene, options);
}

// capping samples (the compact .x3dv shipped) and the corpus part (compact as convert makes it, and every
// face as its source NURBS): the .cnb against the .x3dv and its gzip, at D = 1 mm and 0.01 mm.
TEST(CnbSizes, SmallerThanGzippedX3dv) {
  struct Part {
    std::string name;
    Scene scene;
    std::string x3dv;
  };
  std::vector<Part> parts;
  for (const std::string name : {"capping-90", "capping-end", "capping-post"})
    parts.push_back({name, read_vrml(sample_path(name + ".x3dv")), read_file(sample_path(name + ".x3dv"))});
  const Scene& exact = corpus_scene();
  const Scene compact = compact_scene(exact, 1e-6 * scene_bounding_box(exact).diagonal().norm());
  parts.push_back({"dm1-id-214 compact", compact, x3dv_as_convert_writes(compact)});
  parts.push_back({"dm1-id-214 exact", exact, x3dv_as_convert_writes(exact)});
  for (const auto& part : parts) {
    const size_t gzipped = gzip(part.x3dv).size();
    for (double d : {1.0, 0.01}) {
      const RoundTrip r = round_trip(part.scene, d);
      std::cout << part.name << " D=" << d << " mm: .cnb " << r.bytes.size() << " bytes (deflate " << r.report.deflate_bytes
                << ", arithmetic " << r.report.arithmetic_bytes << "; payload " << r.report.payload_bytes << "), .x3dv "
                << part.x3dv.size() << ", .x3dv.gz " << gzipped << "; measured " << r.measured.max() << ", bound "
                << r.report.deviation_bound() << "\n";
      EXPECT_LT(r.bytes.size(), gzipped) << part.name << " at D = " << d;
    }
  }
}

}  // namespace
}  // namespace cadnurbs
