// Tests of the STL reader and writer against the shared corpus (files written by other programs)
// and against numbers computed outside this code.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/geometry_error.hpp"
#include "core/worker_threads.hpp"
#include "formats/common/file_io.hpp"
#include "formats/stl/stl_reader.hpp"
#include "formats/stl/stl_writer.hpp"

namespace cadnurbs {
namespace {

namespace fs = std::filesystem;

std::string corpus(const std::string& file) { return std::string(CADNURBS_SHARED_DIR) + "/corpus/stl/" + file; }

// The message of the FileError thrown by `parse`, or "" when nothing is thrown.
template <class F>
std::string file_error(F parse) {
  try {
    parse();
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

// A fresh temporary directory per test, removed afterwards.
class StlFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (fs::temp_directory_path() / "cadnurbs_stl_test.XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir_ = pattern;
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

// Positions of `b` equal those of `a` after rounding both to float32, bit for bit.
void expect_same_float_positions(const TriangleMesh& a, const TriangleMesh& b) {
  ASSERT_EQ(a.triangles.size(), b.triangles.size());
  for (std::size_t t = 0; t < a.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      for (int i = 0; i < 3; ++i) {
        const float fa = static_cast<float>(a.positions[a.triangles[t][k]][i]);
        const float fb = static_cast<float>(b.positions[b.triangles[t][k]][i]);
        ASSERT_EQ(std::bit_cast<std::uint32_t>(fa), std::bit_cast<std::uint32_t>(fb))
            << "triangle " << t << " corner " << k << " axis " << i << ": " << fa << " vs " << fb;
      }
}

// ---------------------------------------------------------------------------------------------
// Corpus files: triangle counts from /work/shared/corpus/MANIFEST.tsv.

struct CorpusCase {
  const char* file;
  std::size_t triangles;
};

void PrintTo(const CorpusCase& c, std::ostream* out) { *out << c.file << " (" << c.triangles << " triangles)"; }

class StlCorpus : public ::testing::TestWithParam<CorpusCase> {};

TEST_P(StlCorpus, ReadsManifestTriangleCount) {
  const TriangleMesh mesh = read_stl(corpus(GetParam().file));
  EXPECT_EQ(mesh.triangles.size(), GetParam().triangles);
  EXPECT_EQ(mesh.positions.size(), 3 * GetParam().triangles);  // not welded
  // Every corpus file carries facet normals, so the reader keeps them.
  EXPECT_EQ(mesh.corner_normals.size(), 3 * GetParam().triangles);
  EXPECT_NO_THROW(validate(mesh, GetParam().file));
}

INSTANTIATE_TEST_SUITE_P(Manifest, StlCorpus,
                         ::testing::Values(CorpusCase{"featuretype.STL", 3476}, CorpusCase{"1002_tray_bottom.STL", 4520},
                                           CorpusCase{"plate_holes.STL", 1252}, CorpusCase{"bottle_ascii.stl", 1240},
                                           CorpusCase{"TR12J_OCC.stl", 26966}, CorpusCase{"motor.stl", 13506},
                                           CorpusCase{"fan.stl", 1792}, CorpusCase{"simple_mesh_binary.stl", 49950}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(StlRead, BinaryWithSolidHeaderIsReadAsBinary) {
  const std::string bytes = read_file(corpus("plate_holes.STL"));
  ASSERT_EQ(bytes.substr(0, 5), "solid");  // the trap: an ASCII-looking header
  EXPECT_EQ(parse_stl(bytes, "plate_holes.STL").triangles.size(), 1252u);
}

// Numbers from mawk over the ASCII text, independent of this reader:
//   awk '$1=="vertex"{n++; for(i=2;i<=4;i++){v=$i+0; if(n==1||v<mn[i])mn[i]=v; if(n==1||v>mx[i])mx[i]=v}}
//        END{printf "%d\n%.17g %.17g %.17g\n%.17g %.17g %.17g\n", n, mn[2],mn[3],mn[4],mx[2],mx[3],mx[4]}'
//       1002_tray_bottom.STL
// gave 13560 vertices, min (0, 0, -355.60000000000002), max (355.60000000000002, 3.1749999999999998, 0).
TEST(StlRead, AsciiBoundingBoxMatchesAwk) {
  const TriangleMesh mesh = read_stl(corpus("1002_tray_bottom.STL"));
  ASSERT_EQ(mesh.positions.size(), 13560u);
  Eigen::Vector3d lo = mesh.positions[0], hi = mesh.positions[0];
  for (const auto& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  EXPECT_DOUBLE_EQ(lo.x(), 0.0);
  EXPECT_DOUBLE_EQ(lo.y(), 0.0);
  EXPECT_DOUBLE_EQ(lo.z(), -355.60000000000002);
  EXPECT_DOUBLE_EQ(hi.x(), 355.60000000000002);
  EXPECT_DOUBLE_EQ(hi.y(), 3.1749999999999998);
  EXPECT_DOUBLE_EQ(hi.z(), 0.0);
}

// Numbers from Python's struct module over the binary file, independent of this reader:
//   d = open('TR12J_OCC.stl','rb').read(); n = struct.unpack('<I', d[80:84])[0]
//   vs = [struct.unpack('<3f', d[84+50*i+12+12*k : 84+50*i+24+12*k]) for i in range(n) for k in range(3)]
// gave min (-244.5, -256.0, 0.0), max (261.5, 244.5, 320.5).
TEST(StlRead, BinaryBoundingBoxMatchesPython) {
  const TriangleMesh mesh = read_stl(corpus("TR12J_OCC.stl"));
  Eigen::Vector3d lo = mesh.positions[0], hi = mesh.positions[0];
  for (const auto& p : mesh.positions) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  EXPECT_EQ(lo, Eigen::Vector3d(-244.5, -256.0, 0.0));
  EXPECT_EQ(hi, Eigen::Vector3d(261.5, 244.5, 320.5));
}

TEST(StlRead, ZeroFacetNormalsMeanNoNormals) {
  const std::string text =
      "solid t\n facet normal 0 0 0\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n"
      "  endloop\n endfacet\nendsolid t\n";
  const TriangleMesh mesh = parse_stl(text, "t.stl");
  EXPECT_EQ(mesh.triangles.size(), 1u);
  EXPECT_TRUE(mesh.corner_normals.empty());
}

TEST(StlRead, SuppliedNormalsAreNormalizedAndZeroOnesRecomputed) {
  // Facet 1 has a non-unit normal; facet 2 has none (zero) and lies in the plane x = 0.
  const std::string text =
      "  SOLID t\r\n FACET NORMAL 0 0 2\r\n  OUTER LOOP\r\n   VERTEX 0 0 0\r\n   VERTEX 1 0 0\r\n   VERTEX 0 1 0\r\n"
      "  ENDLOOP\r\n ENDFACET\r\n facet normal 0 0 0\n outer loop\n vertex 0 0 0\n vertex 0 1 0\n vertex 0 0 1\n"
      " endloop\n endfacet\nendsolid\nsolid second\nendsolid second\n";
  const TriangleMesh mesh = parse_stl(text, "t.stl");
  ASSERT_EQ(mesh.corner_normals.size(), 6u);
  EXPECT_EQ(mesh.corner_normals[0], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(mesh.corner_normals[2], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(mesh.corner_normals[3], Eigen::Vector3d(1, 0, 0));  // (0,1,0) x (0,0,1)
}

// ---------------------------------------------------------------------------------------------
// Round trips

// Values that stress float printing: tenths, thirds, -0, tiny, huge, subnormal, 7+ digits.
TriangleMesh awkward_mesh() {
  const double v[] = {0.1,     1.0 / 3.0, -0.0, 1e-30, std::numeric_limits<float>::max(),
                      std::numeric_limits<float>::denorm_min(), 123456.789, std::numbers::pi, -2.5e-7};
  TriangleMesh mesh;
  for (int t = 0; t < 9; ++t) {
    for (int k = 0; k < 3; ++k) mesh.positions.emplace_back(v[t], v[(t + k + 1) % 9], v[(t + 2 * k + 5) % 9]);
    mesh.triangles.push_back({3 * t, 3 * t + 1, 3 * t + 2});
  }
  return mesh;
}

TEST_F(StlFiles, AsciiRoundTripIsExact) {
  for (const TriangleMesh& mesh : {awkward_mesh(), read_stl(corpus("1002_tray_bottom.STL"))}) {
    write_stl(path("a.stl"), mesh, StlEncoding::ascii, "round trip");
    const TriangleMesh back = read_stl(path("a.stl"));
    EXPECT_EQ(back.triangles.size(), mesh.triangles.size());
    expect_same_float_positions(mesh, back);
  }
}

TEST_F(StlFiles, BinaryRoundTripIsExact) {
  for (const TriangleMesh& mesh : {awkward_mesh(), read_stl(corpus("TR12J_OCC.stl"))}) {
    write_stl(path("b.stl"), mesh, StlEncoding::binary, "round trip");
    const std::string bytes = read_file(path("b.stl"));
    EXPECT_EQ(bytes.size(), 84 + 50 * mesh.triangles.size());
    EXPECT_EQ(bytes.substr(0, 20), "cadnurbs round trip ");
    const TriangleMesh back = parse_stl(bytes, "b.stl");
    EXPECT_EQ(back.triangles.size(), mesh.triangles.size());
    expect_same_float_positions(mesh, back);
  }
}

TEST(StlWrite, BinaryHeaderNeverStartsWithSolid) {
  const std::string bytes = format_stl(awkward_mesh(), StlEncoding::binary, "solid looking name that is long enough "
                                                                            "to be cut at eighty bytes, really it is");
  EXPECT_EQ(bytes.substr(0, 9), "cadnurbs ");
  EXPECT_EQ(bytes.substr(9, 5), "solid");
  EXPECT_EQ(bytes.size(), 84u + 50u * 9u);
}

TEST(StlWrite, FacetNormalIsUnitCrossProductOrZero) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};  // the second is degenerate
  const std::string text = format_stl(mesh, StlEncoding::ascii, "n");
  EXPECT_NE(text.find("facet normal 0 0 1\n"), std::string::npos) << text;
  EXPECT_NE(text.find("facet normal 0 0 0\n"), std::string::npos) << text;
  const TriangleMesh back = parse_stl(format_stl(mesh, StlEncoding::binary, "n"), "n.stl");
  ASSERT_EQ(back.corner_normals.size(), 6u);
  EXPECT_EQ(back.corner_normals[0], Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(back.corner_normals[3], Eigen::Vector3d::Zero());
}

TEST(StlWrite, RefusesCoordinatesBeyondFloat) {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1e39, 0, 0}, {0, 1, 0}};
  mesh.triangles = {{0, 1, 2}};
  EXPECT_THROW(format_stl(mesh, StlEncoding::binary, "big"), GeometryError);
}

// ---------------------------------------------------------------------------------------------
// Refused files

TEST_F(StlFiles, TruncatedBinaryNamesByteAndTriangle) {
  for (const char* file : {"featuretype.STL", "plate_holes.STL"}) {  // the second has a 'solid' header
    const std::string bytes = read_file(corpus(file));
    const std::size_t cut = 84 + 50 * 100 + 17;  // inside triangle 101
    write_file_atomically(path("cut.stl"), bytes.substr(0, cut));
    const std::string message = file_error([&] { read_stl(path("cut.stl")); });
    const std::string count = file == std::string("featuretype.STL") ? "3476" : "1252";
    EXPECT_EQ(message, path("cut.stl") + ": binary STL truncated at byte 5101: triangle 101 of " + count +
                           " is incomplete (the file should be " + std::to_string(84 + 50 * std::stoul(count)) +
                           " bytes)");
  }
}

TEST_F(StlFiles, MangledAsciiNamesLineAndFacet) {
  // bottle_ascii.stl: line 1 is "solid", each facet takes 7 lines, so facet 3 is lines 16-22 and
  // its second vertex is on line 19.
  std::istringstream in(read_file(corpus("bottle_ascii.stl")));
  std::string text, line;
  for (int n = 1; std::getline(in, line); ++n) {
    if (n == 19) {
      ASSERT_NE(line.find("vertex"), std::string::npos) << line;
      line.replace(line.find("vertex"), 6, "vertx");
    }
    text += line + "\n";
  }
  write_file_atomically(path("mangled.stl"), text);
  EXPECT_EQ(file_error([&] { read_stl(path("mangled.stl")); }),
            path("mangled.stl") + ": line 19: expected 'vertex' in facet 3, found 'vertx'");
}

TEST_F(StlFiles, TruncatedAsciiIsRefused) {
  const std::string bytes = read_file(corpus("bottle_ascii.stl"));
  // Cut after a whole line in the middle of the file, as an interrupted copy would.
  write_file_atomically(path("short.stl"), bytes.substr(0, bytes.rfind('\n', bytes.size() / 2) + 1));
  const std::string message = file_error([&] { read_stl(path("short.stl")); });
  EXPECT_NE(message.find(": line "), std::string::npos) << message;
  EXPECT_NE(message.find("found end of file"), std::string::npos) << message;
}

TEST_F(StlFiles, EmptyFileIsRefused) {
  write_file_atomically(path("empty.stl"), "");
  EXPECT_EQ(file_error([&] { read_stl(path("empty.stl")); }),
            path("empty.stl") + ": empty file (0 bytes), not an STL file");
}

TEST(StlErrors, SizeMismatchThatIsNotAsciiGivesExpectedSize) {
  std::string bytes = format_stl(awkward_mesh(), StlEncoding::binary, "x");  // 534 bytes
  bytes += "junk";
  EXPECT_EQ(file_error([&] { parse_stl(bytes, "x.stl"); }),
            "x.stl: binary STL has 4 bytes after triangle 9 of 9 (the file should be 534 bytes, it is 538)");
  EXPECT_EQ(file_error([&] { parse_stl("not an stl", "x.stl"); }),
            "x.stl: not ASCII STL (no 'solid' at the start) and too short for binary STL (10 bytes, the header "
            "alone is 84)");
}

TEST(StlErrors, NonFiniteCoordinatesNameTheTriangle) {
  const std::string text =
      "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex nan 0 0\n   vertex 0 1 0\n"
      "  endloop\n endfacet\nendsolid t\n";
  EXPECT_EQ(file_error([&] { parse_stl(text, "t.stl"); }), "t.stl: line 5: vertex 2 of facet 1 is not finite");

  TriangleMesh mesh = awkward_mesh();
  std::string bytes = format_stl(mesh, StlEncoding::binary, "x");
  const float inf = std::numeric_limits<float>::infinity();
  const std::size_t offset = 84 + 50 * 1 + 12 + 12 * 2 + 4;  // triangle 2, vertex 3, y
  for (int b = 0; b < 4; ++b) bytes[offset + b] = static_cast<char>(std::bit_cast<std::uint32_t>(inf) >> (8 * b));
  EXPECT_EQ(file_error([&] { parse_stl(bytes, "x.stl"); }), "x.stl: byte 170: vertex 3 of triangle 2 of 9 is not finite");
}

// A binary file of 2^17 facets or more is read in parts by worker threads: the same mesh (positions
// numbered in order of first occurrence across the parts), normals and first error as one thread reads.
TEST_F(StlFiles, LargeBinaryReadInPartsIsTheMeshReadInOneGo) {
  const int n = 321;  // 320 x 320 quads: 204,800 facets, three parts of 2^16 or more
  TriangleMesh grid;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) grid.positions.emplace_back(i, j, std::sin(0.37 * i) * std::cos(0.23 * j));
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j;
      grid.triangles.push_back({a, a + n, a + n + 1});
      grid.triangles.push_back({a, a + n + 1, a + 1});
    }
  write_stl(path("grid.stl"), grid, StlEncoding::binary, "grid");
  auto same = [](const TriangleMesh& a, const TriangleMesh& b) {
    return a.positions == b.positions && a.triangles == b.triangles && a.corner_normals == b.corner_normals;
  };
  for (const bool merge : {false, true}) {
    set_worker_threads(1);
    const TriangleMesh one = read_stl(path("grid.stl"), {.merge_equal_points = merge});
    EXPECT_EQ(one.positions.size(), merge ? grid.positions.size() : 3 * grid.triangles.size());
    for (const int threads : {2, 3, 8}) {
      set_worker_threads(threads);
      EXPECT_TRUE(same(read_stl(path("grid.stl"), {.merge_equal_points = merge}), one)) << threads << " threads";
    }
  }
  std::string bytes = read_file(path("grid.stl"));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (const std::size_t triangle : {150000, 90000})  // in the third part and in the second
    for (int b = 0; b < 4; ++b)
      bytes[84 + 50 * triangle + 12 + b] = static_cast<char>(std::bit_cast<std::uint32_t>(nan) >> (8 * b));
  write_file_atomically(path("poisoned.stl"), bytes);
  for (const int threads : {1, 3}) {
    set_worker_threads(threads);
    EXPECT_EQ(file_error([&] { read_stl(path("poisoned.stl")); }),
              path("poisoned.stl") + ": byte 4500096: vertex 1 of triangle 90001 of 204800 is not finite")
        << threads << " threads";
  }
  set_worker_threads(0);
}

TEST(StlErrors, NonNumberIsRefused) {
  const std::string text = "solid t\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0x\n";
  EXPECT_EQ(file_error([&] { parse_stl(text, "t.stl"); }),
            "t.stl: line 4: expected a number for vertex 1 in facet 1, found '0x'");
}

}  // namespace
}  // namespace cadnurbs
