// `cadnurbs normals`: an STL cube welded to 8 vertices, 24 corner normals at 30 degrees, each its face's.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "analysis/scene_triangles.hpp"
#include "converters/file_formats.hpp"
#include "formats/common/file_io.hpp"

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

}  // namespace

TEST(NormalsCommand, ACubeGetsTwentyFourCornerNormalsEachItsFaces) {
  const fs::path dir = fs::temp_directory_path() / ("cadnurbs_normals_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  write_file_atomically((dir / "cube.stl").string(), cube_stl());
  const std::string command = std::string(CADNURBS_EXE) + " normals " + (dir / "cube.stl").string() + " -o " +
                              (dir / "cube.x3dv").string() + " --crease-angle 30 >" + (dir / "out.txt").string();
  ASSERT_EQ(WEXITSTATUS(std::system(command.c_str())), 0);
  const std::string out = read_file((dir / "out.txt").string());
  EXPECT_NE(out.find("36 -> 8 vertices"), std::string::npos) << out;
  EXPECT_NE(out.find("24 distinct corner normals"), std::string::npos) << out;
  const TriangleMesh mesh = scene_triangles(read_scene((dir / "cube.x3dv").string()));
  ASSERT_EQ(mesh.triangles.size(), 12u);
  ASSERT_EQ(mesh.corner_normals.size(), 36u);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& p = mesh.positions;
    const auto& c = mesh.triangles[t];
    const Eigen::Vector3d face = (p[c[1]] - p[c[0]]).cross(p[c[2]] - p[c[0]]).normalized();
    for (int k = 0; k < 3; ++k) EXPECT_NEAR((mesh.corner_normals[3 * t + k] - face).norm(), 0.0, 1e-3) << t;
  }
  fs::remove_all(dir);
}
