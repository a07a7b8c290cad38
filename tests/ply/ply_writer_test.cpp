#include <gtest/gtest.h>

#include <cstring>

#include "core/geometry_error.hpp"
#include "formats/ply/ply_writer.hpp"

using namespace cadnurbs;

namespace {
TriangleMesh two_triangles(bool normals) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  if (normals) m.corner_normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0, 1}, {0, 0.4, 0.9}};
  return m;
}
float float_at(const std::string& s, size_t offset) {
  float f;
  std::memcpy(&f, s.data() + offset, 4);
  return f;
}
}  // namespace

TEST(PlyWriter, SharedCornersShareAVertex) {
  const std::string ply = format_ply(two_triangles(false), "test");
  const size_t body = ply.find("end_header\n") + 11;
  EXPECT_NE(ply.find("element vertex 4\n"), std::string::npos);
  EXPECT_NE(ply.find("element face 2\n"), std::string::npos);
  EXPECT_EQ(ply.size(), body + 4 * 12 + 2 * 13);
  EXPECT_EQ(float_at(ply, body + 3 * 12 + 8), 0.5f);  // z of the fourth vertex
}

TEST(PlyWriter, DifferingCornerNormalsSplitTheVertex) {
  const std::string ply = format_ply(two_triangles(true), "");
  // Vertex 3 has one corner; vertices 0 and 2 agree on (0,0,1) in both triangles, except corner
  // (t1, k2) = vertex 3 with its own normal: 4 vertices. Make vertex 2 disagree to force a split.
  EXPECT_NE(ply.find("element vertex 4\n"), std::string::npos);
  TriangleMesh m = two_triangles(true);
  m.corner_normals[4] = {1, 0, 0};  // vertex 2 in triangle 1
  EXPECT_NE(format_ply(m, "").find("element vertex 5\n"), std::string::npos);
  EXPECT_NE(format_ply(m, "").find("property float nx\n"), std::string::npos);
}

TEST(PlyWriter, RefusesAnIndexOutOfRange) {
  TriangleMesh m = two_triangles(false);
  m.triangles[1][2] = 9;
  EXPECT_THROW(format_ply(m, ""), GeometryError);
}
