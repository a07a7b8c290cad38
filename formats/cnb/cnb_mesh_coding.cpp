// Triangle and polygon meshes: vertices on the grid q predicted from the previous vertex, indices as
// differences from the previous index.
#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "formats/cnb/cnb_geometry.hpp"
#include "formats/cnb/cnb_numbers.hpp"

namespace cadnurbs::cnb {

namespace {

void write_positions(ByteWriter& out, const std::vector<Eigen::Vector3d>& positions, double q) {
  out.varuint(positions.size(), Field::count);
  std::array<int64_t, 3> previous{0, 0, 0};
  for (const auto& p : positions)
    for (int k = 0; k < 3; ++k) {
      const int64_t c = on_grid(p[k], q);
      out.varsint(c - previous[k], Field::point);
      previous[k] = c;
    }
}

std::vector<Eigen::Vector3d> read_positions(ByteReader& in, double q) {
  const size_t n = in.count(3);
  std::vector<Eigen::Vector3d> positions(n);
  std::array<int64_t, 3> previous{0, 0, 0};
  for (auto& p : positions)
    for (int k = 0; k < 3; ++k) {
      const size_t at = in.offset();
      previous[k] += in.varsint(Field::point);
      if (std::abs(static_cast<double>(previous[k])) > 0x1p52) in.fail("vertex coordinate outside the grid's range", at);
      p[k] = static_cast<double>(previous[k]) * q;
    }
  return positions;
}

void write_index(ByteWriter& out, int index, int& previous) {
  out.varsint(static_cast<int64_t>(index) - previous, Field::index);
  previous = index;
}

int read_index(ByteReader& in, size_t vertex_count, int& previous) {
  const size_t at = in.offset();
  const int64_t index = previous + in.varsint(Field::index);
  if (index < 0 || static_cast<uint64_t>(index) >= vertex_count)
    in.fail("vertex index " + std::to_string(index) + " outside the " + std::to_string(vertex_count) + " vertices", at);
  previous = static_cast<int>(index);
  return previous;
}

}  // namespace

void write_triangle_mesh(ByteWriter& out, const TriangleMesh& mesh, double q) {
  write_positions(out, mesh.positions, q);
  out.varuint(mesh.triangles.size(), Field::count);
  int previous = 0;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) write_index(out, t[k], previous);
  out.byte(mesh.corner_normals.empty() ? 0 : 1, Field::structure);
  for (const auto& n : mesh.corner_normals)
    for (int k = 0; k < 3; ++k) out.varsint(std::lround(std::clamp(n[k], -1.0, 1.0) * 32767.0), Field::raw);
}

TriangleMesh read_triangle_mesh(ByteReader& in, double q) {
  TriangleMesh mesh;
  mesh.positions = read_positions(in, q);
  const size_t n = in.count(3);
  mesh.triangles.resize(n);
  int previous = 0;
  for (auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) t[k] = read_index(in, mesh.positions.size(), previous);
  const size_t flag_at = in.offset();
  const uint8_t normals = in.byte(Field::structure);
  if (normals > 1) in.fail("normals flag " + std::to_string(normals) + " is neither 0 nor 1", flag_at);
  if (normals) {
    if (n > in.left() / 9) in.fail(std::to_string(3 * n) + " corner normals cannot fit in the " + std::to_string(in.left()) + " bytes left");
    mesh.corner_normals.resize(3 * n);
    for (auto& normal : mesh.corner_normals)
      for (int k = 0; k < 3; ++k) {
        const size_t at = in.offset();
        const int64_t v = in.varsint(Field::raw);
        if (v < -32767 || v > 32767) in.fail("normal component " + std::to_string(v) + " outside -32767..32767", at);
        normal[k] = static_cast<double>(v) / 32767.0;
      }
  }
  return mesh;
}

void write_polygon_mesh(ByteWriter& out, const PolygonMesh& mesh, double q) {
  write_positions(out, mesh.positions, q);
  out.varuint(mesh.polygons.size(), Field::count);
  int previous = 0;
  for (const auto& polygon : mesh.polygons) {
    out.varuint(polygon.size() - 3, Field::count);
    for (int i : polygon) write_index(out, i, previous);
  }
}

PolygonMesh read_polygon_mesh(ByteReader& in, double q) {
  PolygonMesh mesh;
  mesh.positions = read_positions(in, q);
  const size_t n = in.count(4);
  mesh.polygons.resize(n);
  int previous = 0;
  for (auto& polygon : mesh.polygons) {
    const size_t at = in.offset();
    const uint64_t corners = in.varuint(Field::count) + 3;
    if (corners < 3 || corners > in.left()) in.fail(std::to_string(corners) + " corners cannot fit in the " + std::to_string(in.left()) + " bytes left", at);
    polygon.resize(corners);
    for (int& i : polygon) i = read_index(in, mesh.positions.size(), previous);
  }
  return mesh;
}

}  // namespace cadnurbs::cnb
