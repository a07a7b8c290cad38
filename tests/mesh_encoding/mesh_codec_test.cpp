// Draco and meshopt mesh codecs: round trips keep every triangle with its corners within the
// quantisation bound, the replayed quantisation is what the decoders return, damaged bytes are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"
#include "formats/draco/draco_mesh_codec.hpp"
#include "formats/meshopt/meshopt_mesh_codec.hpp"

namespace cadnurbs {
namespace {

// A wavy 11 x 11 grid, 10 mm apart, 100 mm wide: vertices far apart next to any grid step tested, so
// each decoded vertex has one unambiguous original.
TriangleMesh wavy_grid() {
  TriangleMesh mesh;
  const int n = 11;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      mesh.positions.emplace_back(10.0 * i - 37.3, 10.0 * j + 12.9, 20.0 * std::sin(0.5 * i) * std::cos(0.3 * j) + 5);
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      mesh.triangles.push_back({a, b, d});
      mesh.triangles.push_back({a, d, c});
    }
  return mesh;
}

double largest_extent(const TriangleMesh& mesh) {
  Eigen::Vector3d lo = mesh.positions[0], hi = lo;
  for (const auto& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  return (hi - lo).maxCoeff();
}

int nearest(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  int best = 0;
  for (int i = 1; i < static_cast<int>(mesh.positions.size()); ++i)
    if ((mesh.positions[i] - p).norm() < (mesh.positions[best] - p).norm()) best = i;
  return best;
}

// Every decoded vertex within `bound` of its original, and every decoded triangle an original triangle
// (same orientation) once its corners are mapped back; counts kept.
void expect_same_mesh_within(const TriangleMesh& original, const TriangleMesh& decoded, double bound) {
  ASSERT_EQ(decoded.positions.size(), original.positions.size());
  ASSERT_EQ(decoded.triangles.size(), original.triangles.size());
  std::vector<int> source(decoded.positions.size());
  double worst = 0;
  for (size_t i = 0; i < decoded.positions.size(); ++i) {
    source[i] = nearest(original, decoded.positions[i]);
    worst = std::max(worst, (original.positions[source[i]] - decoded.positions[i]).norm());
  }
  EXPECT_LE(worst, bound);
  std::vector<int> sorted = source;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::unique(sorted.begin(), sorted.end()), sorted.end()) << "two decoded vertices share an original";
  auto canonical = [](std::array<int, 3> t) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    return t;
  };
  std::vector<std::array<int, 3>> want, got;
  for (const auto& t : original.triangles) want.push_back(canonical(t));
  for (const auto& t : decoded.triangles) got.push_back(canonical({source[t[0]], source[t[1]], source[t[2]]}));
  std::sort(want.begin(), want.end());
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, want);
}

std::vector<Eigen::Vector3d> sorted_positions(std::vector<Eigen::Vector3d> p) {
  std::sort(p.begin(), p.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return p;
}

TEST(DracoMeshCodec, RoundTripKeepsTrianglesWithinHalfAStep) {
  const TriangleMesh mesh = wavy_grid();
  for (int bits : {8, 12, 16}) {
    for (int speed : {0, 5, 10}) {
      SCOPED_TRACE("bits " + std::to_string(bits) + " speed " + std::to_string(speed));
      const TriangleMesh decoded = decode_draco_mesh(encode_draco_mesh(mesh, bits, speed), "grid.drc");
      // Draco's grid: one step for all axes, the largest extent / (2^bits - 1); plus a few float roundings
      // of coordinates below 128.
      const double step = largest_extent(mesh) / ((1 << bits) - 1);
      expect_same_mesh_within(mesh, decoded, std::sqrt(3.0) * (step / 2 + 4 * 128 * std::ldexp(1.0, -24)));
      // The replay is what Draco decodes, bit for bit.
      EXPECT_EQ(sorted_positions(decoded.positions), sorted_positions(draco_quantised_positions(mesh, bits)));
    }
  }
}

TEST(DracoMeshCodec, SequentialEncodingKeepsOrder) {
  const TriangleMesh mesh = wavy_grid();
  const TriangleMesh decoded = decode_draco_mesh(encode_draco_mesh(mesh, 11, 10), "grid.drc");
  EXPECT_EQ(decoded.positions, draco_quantised_positions(mesh, 11));
  EXPECT_EQ(decoded.triangles, mesh.triangles);
}

TEST(DracoMeshCodec, RefusesDamagedBytes) {
  const std::string bytes = encode_draco_mesh(wavy_grid(), 12, 0);
  try {
    decode_draco_mesh("solid this is an STL, not Draco", "part.drc");
    FAIL() << "no error";
  } catch (const FileError& e) {
    EXPECT_STREQ(e.what(), "part.drc: not a Draco mesh (Not a Draco file.)");
  }
  for (size_t keep : {size_t(3), size_t(20), bytes.size() / 2, bytes.size() - 1})
    EXPECT_THROW(decode_draco_mesh(bytes.substr(0, keep), "part.drc"), FileError) << "kept " << keep;
}

TEST(DracoMeshCodec, RefusesBadArguments) {
  EXPECT_THROW(encode_draco_mesh(wavy_grid(), 0, 0), GeometryError);
  EXPECT_THROW(encode_draco_mesh(wavy_grid(), 31, 0), GeometryError);
  EXPECT_THROW(encode_draco_mesh(wavy_grid(), 12, 11), GeometryError);
  EXPECT_THROW(encode_draco_mesh(TriangleMesh{}, 12, 0), GeometryError);
}

TEST(MeshoptMeshCodec, RoundTripKeepsTrianglesWithinHalfAStep) {
  const TriangleMesh mesh = wavy_grid();
  for (int bits : {6, 12, 16, 20}) {
    SCOPED_TRACE("bits " + std::to_string(bits));
    const std::string bytes = encode_meshopt_mesh(mesh, bits);
    const TriangleMesh decoded = decode_meshopt_mesh(bytes, "grid.mo");
    const double step = largest_extent(mesh) / ((1 << bits) - 1);
    expect_same_mesh_within(mesh, decoded, std::sqrt(3.0) * step / 2 * (1 + 1e-12));
    EXPECT_EQ(sorted_positions(decoded.positions), sorted_positions(meshopt_quantised_positions(mesh, bits)));
  }
}

TEST(MeshoptMeshCodec, RefusesDamagedBytes) {
  const std::string bytes = encode_meshopt_mesh(wavy_grid(), 12);
  auto message = [](const std::string& b) {
    try {
      decode_meshopt_mesh(b, "part.mo");
    } catch (const FileError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(bytes.substr(0, 49)), "part.mo: too short for a meshopt mesh header");
  EXPECT_EQ(message("XNMO" + bytes.substr(4)), "part.mo: not a cadnurbs meshopt mesh (no CNMO signature)");
  std::string version = bytes;
  version[4] = 2;
  EXPECT_EQ(message(version), "part.mo: meshopt mesh version 2 is not supported");
  std::string many = bytes;
  many[9] = static_cast<char>(0x7f);  // vertex count's top byte: two billion vertices
  EXPECT_EQ(message(many), "part.mo: vertex count exceeds what its stream can hold");
  std::string step = bytes;
  for (int i = 38; i < 46; ++i) step[i] = static_cast<char>(0xff);  // a NaN
  EXPECT_EQ(message(step), "part.mo: grid origin, step or far corner is not finite, or the step is not positive");
  EXPECT_EQ(message(bytes.substr(0, 60)), "part.mo: vertex stream runs past the end");
  // Meshopt's own decoders: a cut index stream, and a vertex stream missing its tail.
  EXPECT_EQ(message(bytes.substr(0, bytes.size() - 10)), "part.mo: damaged index stream (meshoptimizer error -2)");
  EXPECT_NE(message(bytes.substr(0, bytes.size() - 1)), "no error");
}

// No checksums in either format, so a flipped bit may decode to another mesh; what must never happen is a
// crash, another exception, or a mesh with missing vertices or non-finite positions.
TEST(MeshCodecs, EveryBitFlipIsRefusedOrDecodesToAValidMesh) {
  const TriangleMesh mesh = wavy_grid();
  for (const bool draco : {true, false}) {
    SCOPED_TRACE(draco ? "draco" : "meshopt");
    const std::string bytes = draco ? encode_draco_mesh(mesh, 12, 0) : encode_meshopt_mesh(mesh, 12);
    int refused = 0;
    for (size_t i = 0; i < bytes.size(); ++i)
      for (int bit = 0; bit < 8; ++bit) {
        std::string damaged = bytes;
        damaged[i] = static_cast<char>(damaged[i] ^ (1 << bit));
        try {
          const TriangleMesh m = draco ? decode_draco_mesh(damaged, "flip") : decode_meshopt_mesh(damaged, "flip");
          EXPECT_NO_THROW(validate(m, "decoded")) << "byte " << i << " bit " << bit;
        } catch (const FileError&) {
          ++refused;
        }
      }
    EXPECT_GT(refused, 0);
  }
}

}  // namespace
}  // namespace cadnurbs
