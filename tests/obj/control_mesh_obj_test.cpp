// The Loop control mesh OBJ: tags and bit-exact positions survive a write and a read; plain OBJ reads as an
// untagged control mesh; each refusal names the file and line.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>

#include "core/geometry_error.hpp"
#include "formats/common/file_io.hpp"
#include "formats/obj/control_mesh_obj.hpp"
#include "formats/obj/obj_writer.hpp"
#include "formats/stl/stl_reader.hpp"

namespace cadnurbs {
namespace {

bool same_bits(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0;
}

void expect_same_positions(const std::vector<Eigen::Vector3d>& read, const std::vector<Eigen::Vector3d>& written) {
  ASSERT_EQ(read.size(), written.size());
  for (size_t i = 0; i < read.size(); ++i)
    EXPECT_TRUE(same_bits(read[i], written[i])) << "position " << i << ": " << read[i].transpose();
}

// A unit-ish cube (outward counter-clockwise triangles) whose top square and one vertical edge are creases,
// with two corners; coordinates chosen to be awkward in decimal (-0, a subnormal, 0.1 + 0.2, 1/3).
SubdivisionControlMesh tagged_cube() {
  SubdivisionControlMesh m;
  const double one = std::nextafter(1.0, 2.0), third = 1.0 / 3.0;
  m.positions = {{-0.0, 0, 1e-310}, {one, 0, 0}, {one, 0.1 + 0.2, 0}, {0, 0.1 + 0.2, 0},
                 {0, 0, third},     {one, 0, third}, {one, 0.1 + 0.2, third}, {-6.02214076e23, 0.1 + 0.2, third}};
  m.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                 {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
  m.crease_edges = {{5, 6}, {4, 7}, {1, 5}, {4, 5}, {6, 7}};  // not sorted: the reader sorts
  m.corner_vertices = {3, 0};
  return m;
}

std::string error_of(const std::string& text) {
  try {
    parse_control_mesh_obj(text, "m.obj");
  } catch (const FileError& e) {
    return e.what();
  }
  return "no error";
}

std::string writer_error_of(const SubdivisionControlMesh& mesh) {
  try {
    format_control_mesh_obj(mesh);
  } catch (const GeometryError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ControlMeshObj, TaggedMeshReadsBackIdentically) {
  const SubdivisionControlMesh m = tagged_cube();
  const std::string text = format_control_mesh_obj(m);
  EXPECT_TRUE(text.starts_with("# cadnurbs Loop control mesh, format 1 ")) << text;
  // The five creases form one chain: from the odd vertex 1 up to 5, round the top square, back to 5.
  EXPECT_NE(text.find("\nl 2 6 7 8 5 6\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("\nl "), text.rfind("\nl "));  // one "l" line only
  EXPECT_NE(text.find("\np 4 1\n"), std::string::npos) << text;

  const SubdivisionControlMesh back = parse_control_mesh_obj(text, "cube.obj");
  expect_same_positions(back.positions, m.positions);
  EXPECT_TRUE(std::signbit(back.positions[0].x()));  // -0 kept
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.crease_edges, (std::vector<std::array<int, 2>>{{1, 5}, {4, 5}, {4, 7}, {5, 6}, {6, 7}}));
  EXPECT_EQ(back.corner_vertices, (std::vector<int>{0, 3}));
  // Read order is canonical, so a mesh read back writes a file that reads back to itself.
  const std::string again = format_control_mesh_obj(back);
  EXPECT_EQ(format_control_mesh_obj(parse_control_mesh_obj(again, "again.obj")), again);
}

TEST(ControlMeshObj, WrittenFileReadsBackIdentically) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "cadnurbs_control_mesh_obj_test.obj";
  const SubdivisionControlMesh m = tagged_cube();
  write_control_mesh_obj(path.string(), m);
  const SubdivisionControlMesh back = read_control_mesh_obj(path.string());
  std::filesystem::remove(path);
  expect_same_positions(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.crease_edges.size(), 5u);
  EXPECT_EQ(back.corner_vertices, (std::vector<int>{0, 3}));
}

TEST(ControlMeshObj, EveryFiniteDoubleRoundTripsBitForBit) {
  std::mt19937_64 random(11);
  SubdivisionControlMesh m;
  while (m.positions.size() < 3000) {
    Eigen::Vector3d p;
    for (int k = 0; k < 3; ++k)
      do p[k] = std::bit_cast<double>(random());
      while (!std::isfinite(p[k]));
    m.positions.push_back(p);
  }
  m.triangles = {{0, 1, 2}, {2, 1, 2999}};
  m.crease_edges = {{1, 2}};
  const SubdivisionControlMesh back = parse_control_mesh_obj(format_control_mesh_obj(m), "random.obj");
  expect_same_positions(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_EQ(back.crease_edges, m.crease_edges);
}

TEST(ControlMeshObj, ReadsNegativeAndForwardIndicesAndSkipsAttributes) {
  const std::string text =
      "mtllib parts.mtl\r\n"
      "o part\n"
      "v 0 0 0\n"
      "v 1 0 0 0.5 0.5 0.5\n"  // a colour after the point
      "v +1 1 0\n"
      "vt 0 0\n"
      "vn 0 0 1\n"
      "g side\n"
      "usemtl red\n"
      "s off\n"
      "f -3/1/1 -2//1 -1/1   # the last three vertices\n"
      "f 1 3 4\n"  // vertex 4 is defined below
      "v 0 1 0\n"
      "l -4/1 -3 -2 -4\n"  // closed loop round the first triangle: 1-2, 2-3, 1-3
      "l 3 1\n"             // 1-3 again: dropped
      "p -1 -1 2\n";
  const SubdivisionControlMesh m = parse_control_mesh_obj(text, "plain.obj");
  ASSERT_EQ(m.positions.size(), 4u);
  EXPECT_EQ(m.positions[2], Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(m.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_EQ(m.crease_edges, (std::vector<std::array<int, 2>>{{0, 1}, {0, 2}, {1, 2}}));
  EXPECT_EQ(m.corner_vertices, (std::vector<int>{1, 3}));
}

TEST(ControlMeshObj, PlainObjFromFormatObjReadsAsAnUntaggedControlMesh) {
  const TriangleMesh stl = read_stl(CADNURBS_SOURCE_DIR "/samples/capping-90.stl");
  ASSERT_FALSE(stl.corner_normals.empty());  // so the faces are written "f a//n b//n c//n"
  const std::string text = format_obj(stl, "capping-90");
  ASSERT_NE(text.find("//"), std::string::npos);
  const SubdivisionControlMesh m = parse_control_mesh_obj(text, "capping-90.obj");
  expect_same_positions(m.positions, stl.positions);
  EXPECT_EQ(m.triangles, stl.triangles);
  EXPECT_GT(m.triangles.size(), 1000u);
  EXPECT_TRUE(m.crease_edges.empty());
  EXPECT_TRUE(m.corner_vertices.empty());
}

constexpr const char* kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";  // lines 1-3

TEST(ControlMeshObj, RefusalsNameTheFileAndLine) {
  const std::string t = kTriangle;
  EXPECT_EQ(error_of(t + "f 1 2 9\n"), "m.obj: line 4: vertex index 9 is out of range (the file has 3 vertices)");
  EXPECT_EQ(error_of(t + "f 1 2 3\nf -1 -2 -4\n"),
            "m.obj: line 5: vertex index -4 is out of range (3 vertices before it)");
  EXPECT_EQ(error_of(t + "f 0 1 2\n"), "m.obj: line 4: vertex index 0 is not valid (OBJ counts vertices from 1)");
  EXPECT_EQ(error_of(t + "f 1 2 x/1\n"), "m.obj: line 4: vertex index 'x' is not an integer");
  EXPECT_EQ(error_of(t + "v 1 1 0\nl 1 2 4\nf 1 2 3\n"),
            "m.obj: line 5: crease edge 2-4 is not an edge of any triangle");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 nan 0\n"), "m.obj: line 2: vertex 2: coordinate 'nan' is not finite");
  EXPECT_EQ(error_of("v 0 0 -inf\n"), "m.obj: line 1: vertex 1: coordinate '-inf' is not finite");
  EXPECT_EQ(error_of("v 0 1,5 0\n"), "m.obj: line 1: vertex 1: coordinate '1,5' is not a number");
  EXPECT_EQ(error_of("v 0 0 1e999\n"), "m.obj: line 1: vertex 1: coordinate '1e999' is out of the range of double");
  EXPECT_EQ(error_of("v 0 0\n"), "m.obj: line 1: a vertex needs 3 coordinates, found 2");
  EXPECT_EQ(error_of(t + "l 1 2\n"), "m.obj: no triangles (a Loop control mesh needs at least one face 'f a b c')");
  EXPECT_EQ(error_of(""), "m.obj: no triangles (a Loop control mesh needs at least one face 'f a b c')");
  EXPECT_EQ(error_of(t + "v 1 1 0\nf 1 2 4 3\n"),
            "m.obj: line 5: face with 4 corners: a Loop control mesh has triangles only (triangulate it first)");
  EXPECT_EQ(error_of(t + "f 1 2\n"), "m.obj: line 4: face with 2 corners: a face needs 3");
  EXPECT_EQ(error_of(t + "f 1 2 -2\n"), "m.obj: line 4: face uses vertex 2 twice");
  EXPECT_EQ(error_of(t + "f 1 2 3\nl 1\n"), "m.obj: line 5: a line element needs at least 2 vertices, found 1");
  EXPECT_EQ(error_of(t + "f 1 2 3\np\n"), "m.obj: line 5: a point element needs at least 1 vertex");
  EXPECT_EQ(error_of(t + "curv 0 1 1 2\n"),
            "m.obj: line 4: element 'curv' is not supported (a Loop control mesh has v, f, l and p)");
  EXPECT_EQ(error_of("# cadnurbs Loop control mesh, format 2 (l: crease edges)\n" + t + "f 1 2 3\n"),
            "m.obj: line 1: cadnurbs Loop control mesh format '2' is not format 1, the one this reader knows");
}

TEST(ControlMeshObj, WriterRefusesWhatCouldNotReadBack) {
  SubdivisionControlMesh m = tagged_cube();
  m.crease_edges.push_back({0, 6});  // the cube's space diagonal
  EXPECT_EQ(writer_error_of(m), "Loop control mesh: crease edge 5 {0, 6} is not an edge of any triangle");
  m = tagged_cube();
  m.crease_edges[0] = {6, 5};
  EXPECT_EQ(writer_error_of(m), "Loop control mesh: crease edge 0 {6, 5} is not written with a < b");
  m = tagged_cube();
  m.crease_edges.push_back({4, 5});
  EXPECT_EQ(writer_error_of(m), "Loop control mesh: a crease edge is listed twice");
  m = tagged_cube();
  m.corner_vertices.push_back(8);
  EXPECT_EQ(writer_error_of(m), "Loop control mesh: corner 8 is out of range");
  m = tagged_cube();
  m.positions[3].y() = NAN;
  EXPECT_EQ(writer_error_of(m), "Loop control mesh: position 3 is not finite");
  m = tagged_cube();
  m.triangles.clear();
  m.crease_edges.clear();
  EXPECT_EQ(writer_error_of(m), "Loop control mesh: no triangles");
}

}  // namespace
}  // namespace cadnurbs
