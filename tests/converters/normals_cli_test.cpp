// `cadnurbs normals`: an STL cube welded to 8 vertices, 24 corner normals at 30 degrees, each its face's;
// malformed STL files refused with one line naming the file and the reason, and nothing written.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <set>
#include <sstream>

#include "analysis/mesh/scene_triangles.hpp"
#include "command_fixture.hpp"
#include "converters/file_formats.hpp"
#include "formats/stl/stl_reader.hpp"
#include "formats/stl/stl_writer.hpp"

namespace fs = std::filesystem;
using namespace cadnurbs;

namespace {

// The unit cube as STL writes it: 12 facets, each with its own three vertices.
std::string cube_stl() {
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  auto corner = [](int i) { return Eigen::Vector3d(i & 1, (i >> 1) & 1, (i >> 2) & 1); };
  std::ostringstream out;
  out << "solid cube\n";
  for (const auto& f : faces)
    for (const auto& t : {std::array<int, 3>{f[0], f[1], f[2]}, std::array<int, 3>{f[0], f[2], f[3]}}) {
      const Eigen::Vector3d n = (corner(t[1]) - corner(t[0])).cross(corner(t[2]) - corner(t[0])).normalized();
      out << " facet normal " << n.x() << " " << n.y() << " " << n.z() << "\n  outer loop\n";
      for (int i : t) out << "   vertex " << corner(i).x() << " " << corner(i).y() << " " << corner(i).z() << "\n";
      out << "  endloop\n endfacet\n";
    }
  out << "endsolid cube\n";
  return out.str();
}

std::string binary_cube_stl() { return format_stl(parse_stl(cube_stl(), "cube"), StlEncoding::binary, "cube"); }

void put_u32(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + i] = static_cast<char>(value >> (8 * i) & 0xff);
}

class NormalsCommand : public test::CommandTest {
 protected:
  // Runs `normals` on `bytes` saved as `name`: expects a non-zero exit, stderr exactly one line
  // "cadnurbs normals: <path>: <reason>", and no file in the folder but the input and the captured output.
  void expect_refused(const std::string& name, const std::string& bytes, const std::string& reason) {
    write_file_atomically(path(name), bytes);
    const test::CommandResult r = run("normals " + path(name) + " -o " + path("out.x3dv"));
    EXPECT_NE(r.status, 0) << name;
    EXPECT_EQ(r.err, "cadnurbs normals: " + path(name) + ": " + reason + "\n");
    std::set<std::string> files;
    for (const auto& entry : fs::directory_iterator(dir_)) files.insert(entry.path().filename().string());
    EXPECT_EQ(files, (std::set<std::string>{name, "stdout.txt", "stderr.txt"})) << name;
    fs::remove(path(name));
  }
};

TEST_F(NormalsCommand, ACubeGetsTwentyFourCornerNormalsEachItsFaces) {
  write_file_atomically(path("cube.stl"), cube_stl());
  const test::CommandResult r = run("normals " + path("cube.stl") + " -o " + path("cube.x3dv") + " --crease-angle 30");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("36 corners at 8 distinct points, welded at"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("to 8 vertices"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1 component (1 closed), 0 triangles flipped"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("24 distinct corner normals"), std::string::npos) << r.out;
  const TriangleMesh mesh = scene_triangles(read_scene(path("cube.x3dv")));
  ASSERT_EQ(mesh.triangles.size(), 12u);
  ASSERT_EQ(mesh.corner_normals.size(), 36u);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& p = mesh.positions;
    const auto& c = mesh.triangles[t];
    const Eigen::Vector3d face = (p[c[1]] - p[c[0]]).cross(p[c[2]] - p[c[0]]).normalized();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((mesh.corner_normals[3 * t + k] - face).norm(), 0.0, 1e-3) << t;
  }
}

// Two triangles turned inside out and the whole cube turned inside out: the written faces point outward.
TEST_F(NormalsCommand, InsideOutTrianglesAreTurnedOutward) {
  TriangleMesh cube = parse_stl(cube_stl(), "cube");
  for (auto& t : cube.triangles) std::swap(t[1], t[2]);
  std::swap(cube.triangles[4][1], cube.triangles[4][2]);
  std::swap(cube.triangles[9][1], cube.triangles[9][2]);
  write_stl(path("cube.stl"), cube, StlEncoding::binary, "cube");
  const test::CommandResult r = run("normals " + path("cube.stl") + " -o " + path("out.stl"));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("1 component (1 closed), 10 triangles flipped"), std::string::npos) << r.out;
  const TriangleMesh mesh = read_stl(path("out.stl"));
  ASSERT_EQ(mesh.triangles.size(), 12u);
  for (const auto& c : mesh.triangles) {
    const auto& p = mesh.positions;
    const Eigen::Vector3d outward = (p[c[0]] + p[c[1]] + p[c[2]]) / 3 - Eigen::Vector3d(0.5, 0.5, 0.5);
    EXPECT_GT((p[c[1]] - p[c[0]]).cross(p[c[2]] - p[c[0]]).dot(outward), 0);
  }
}

TEST_F(NormalsCommand, RefusesTruncatedBinary) {
  const std::string cube = binary_cube_stl();
  ASSERT_EQ(cube.size(), 684u);
  expect_refused("cut.stl", cube.substr(0, 684 - 20),
                 "binary STL truncated at byte 664: triangle 12 of 12 is incomplete (the file should be 684 bytes)");
}

TEST_F(NormalsCommand, RefusesTriangleCountBeyondTheFile) {
  std::string cube = binary_cube_stl();
  put_u32(cube, 80, 1000);
  expect_refused("short.stl", cube,
                 "binary STL header counts 1000 triangles but the file holds 12 (the file should be 50084 bytes, "
                 "it is 684)");
}

TEST_F(NormalsCommand, RefusesNaNCoordinate) {
  std::string cube = binary_cube_stl();
  const std::size_t at = 84 + 50 * 2 + 12 + 12;  // triangle 3, vertex 2, x
  put_u32(cube, at, std::bit_cast<std::uint32_t>(std::numeric_limits<float>::quiet_NaN()));
  expect_refused("nan.stl", cube, "byte " + std::to_string(at) + ": vertex 2 of triangle 3 of 12 is not finite");
  std::string text = cube_stl();
  text.replace(text.find("vertex 0 0 0"), 12, "vertex 0 nan 0");
  expect_refused("nan_ascii.stl", text, "line 4: vertex 1 of facet 1 is not finite");
}

TEST_F(NormalsCommand, RefusesZeroTriangles) {
  std::string empty(84, ' ');
  put_u32(empty, 80, 0);
  expect_refused("empty.stl", empty, "no triangles to give normals to");
  expect_refused("empty_ascii.stl", "solid x\nendsolid x", "no triangles to give normals to");
}

}  // namespace
