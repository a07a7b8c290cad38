// The smallest Draco and meshopt meshes of the 90-degree capping within D: decoded and measured within
// D, at the coarsest bits the budget allows, and smaller than the plain indexed mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "report/smallest_compressed_mesh.hpp"
#include "core/geometry_error.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

const Scene& capping_90() {
  static const Scene scene = read_vrml(CADNURBS_SOURCE_DIR "/samples/capping-90.x3dv");
  return scene;
}

void check_capping(double d) {
  const std::vector<MeshEncodingFigures> figures =
      encode_mesh_within(capping_90(), d, {MeshCodec::draco, MeshCodec::meshopt});
  ASSERT_EQ(figures.size(), 2u);
  for (const MeshEncodingFigures& f : figures) {
    const MeshCodec codec = f.codec;
    SCOPED_TRACE(std::string(mesh_codec_name(codec)) + " D=" + std::to_string(d));
    std::printf("  capping-90 D=%-4g %-7s raw %7ld B  gzip %7ld B  bits %2d  f %.2f  certified %.4g  displacement "
                "%.4g (budget %.4g)  bound %.4g  measured %.4g  vertices %ld  triangles %ld\n",
                d, mesh_codec_name(codec), f.raw_bytes, f.gzip_bytes, f.position_bits, f.fraction,
                f.certified_deviation, f.displacement, f.displacement_budget, f.deviation_bound, f.measured.overall.max,
                f.vertices, f.triangles);
    EXPECT_LE(f.measured.overall.max, d);
    EXPECT_GT(f.measured.overall.samples, 0);
    EXPECT_LE(f.deviation_bound, d);
    EXPECT_DOUBLE_EQ(f.certified_deviation, f.fraction * d);
    EXPECT_EQ(f.raw_bytes, static_cast<long>(f.bytes.size()));

    // The coarsest bits: the same tessellation one bit coarser moves some vertex beyond the budget.
    const TriangleMesh& mesh = f.certified_mesh;
    EXPECT_EQ(static_cast<long>(mesh.triangles.size()), f.triangles);
    EXPECT_EQ(static_cast<long>(mesh.positions.size()), f.vertices);
    EXPECT_DOUBLE_EQ(quantisation_displacement(mesh, codec, f.position_bits), f.displacement);
    EXPECT_LE(f.displacement, f.displacement_budget);
    ASSERT_GT(f.position_bits, 1);
    EXPECT_GT(quantisation_displacement(mesh, codec, f.position_bits - 1), f.displacement_budget);

    // For the report: the bits the worst case of a cubic grid (step * sqrt(3) / 2) would have needed.
    Eigen::Vector3d lo = mesh.positions[0], hi = lo;
    for (const auto& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    int worst_case_bits = 1;
    while (std::sqrt(3.0) / 2 * (hi - lo).maxCoeff() / ((1 << worst_case_bits) - 1) > f.displacement_budget)
      ++worst_case_bits;
    std::printf("    bits from the worst case of the grid: %d (exact displacement at %d bits: %.4g)\n", worst_case_bits,
                f.position_bits - 1, quantisation_displacement(mesh, codec, f.position_bits - 1));

    // Smaller than the indexed mesh as 32-bit floats and indices.
    const long indexed = 4 * (3 * f.vertices + 3 * f.triangles);
    const long compared = codec == MeshCodec::draco ? f.raw_bytes : f.gzip_bytes;
    std::printf("    indexed mesh as floats %ld B: %.1f x the %s figure\n", indexed, double(indexed) / compared,
                mesh_codec_name(codec));
    EXPECT_LT(compared, indexed);
  }
}

TEST(MeshEncoding, Capping90Within1mm) { check_capping(1.0); }

TEST(MeshEncoding, Capping90Within0_1mm) { check_capping(0.1); }

TEST(MeshEncoding, CornersAHairApartAreWeldedSoThatAQuantisationPasses) {
  // A unit square of two triangles and a sliver between corner D and D', 1e-14 apart (as in KiCad's
  // Phoenix connectors, where a loop passes one point twice): the sliver collapses at every bit count,
  // so no quantisation passes until the hair-apart corners are welded; the move is the 1e-14.
  const TriangleMesh mesh{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 1 + 1e-14, 1e-14}},
                          {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}},
                          {}};
  for (MeshCodec codec : {MeshCodec::draco, MeshCodec::meshopt}) {
    SCOPED_TRACE(mesh_codec_name(codec));
    EXPECT_EQ(coarsest_quantisation(mesh, codec, 0.01).bits, 0);
    double moved = -1;
    const TriangleMesh welded = with_hair_apart_corners_welded(mesh, codec, 0.01, &moved);
    EXPECT_EQ(welded.positions.size(), 4u);
    EXPECT_EQ(welded.triangles.size(), 2u);
    EXPECT_NEAR(moved, std::sqrt(2.0) * 1e-14, 1e-16);
    EXPECT_GT(coarsest_quantisation(welded, codec, 0.01).bits, 0);
    // A mesh with nothing to weld comes back as it was.
    const TriangleMesh square{{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}, {}};
    EXPECT_EQ(with_hair_apart_corners_welded(square, codec, 0.01, &moved).positions, square.positions);
    EXPECT_EQ(moved, 0.0);
  }
}

TEST(MeshEncoding, RefusesMeshesAndBadArguments) {
  EXPECT_THROW(encode_mesh_within(capping_90(), 0, MeshCodec::draco), GeometryError);
  MeshEncodingOptions options;
  options.fractions = {1.0};
  EXPECT_THROW(encode_mesh_within(capping_90(), 1, MeshCodec::draco, options), GeometryError);
  Scene meshes;
  meshes.root.shapes.push_back({"plate", TriangleMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {}}, std::nullopt});
  try {
    encode_mesh_within(meshes, 1, MeshCodec::meshopt);
    FAIL() << "no error";
  } catch (const GeometryError& e) {
    EXPECT_STREQ(e.what(), "mesh encoding: shape 'plate' is a mesh, with no exact surface to measure the encoding against");
  }
}

}  // namespace
}  // namespace cadnurbs
