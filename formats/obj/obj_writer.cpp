#include "formats/obj/obj_writer.hpp"

#include <array>
#include <charconv>
#include <map>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

void append_number(std::string& out, double x) {
  char buffer[32];
  const auto end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;  // shortest that reads back exactly
  out.append(buffer, end);
}

void append_vector(std::string& out, const char* tag, const Eigen::Vector3d& v) {
  out += tag;
  for (int k = 0; k < 3; ++k) {
    out += ' ';
    append_number(out, v[k]);
  }
  out += '\n';
}

}  // namespace

std::string format_obj(const TriangleMesh& mesh, const std::string& comment) {
  validate(mesh, "mesh");
  std::string out = "# ";
  for (char c : comment) out += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  out += '\n';
  for (const auto& p : mesh.positions) append_vector(out, "v", p);
  // Equal corner normals are written once (smooth regions share them).
  std::vector<int> normal_of_corner;
  std::map<std::array<double, 3>, int> index_of;
  for (const auto& n : mesh.corner_normals) {
    const auto [it, inserted] = index_of.try_emplace({n.x(), n.y(), n.z()}, static_cast<int>(index_of.size()));
    if (inserted) append_vector(out, "vn", n);
    normal_of_corner.push_back(it->second);
  }
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    out += 'f';
    for (int k = 0; k < 3; ++k) {
      out += ' ' + std::to_string(mesh.triangles[t][k] + 1);
      if (!normal_of_corner.empty()) out += "//" + std::to_string(normal_of_corner[3 * t + k] + 1);
    }
    out += '\n';
  }
  return out;
}

void write_obj(const std::string& path, const TriangleMesh& mesh, const std::string& comment) {
  write_file_atomically(path, format_obj(mesh, comment));
}

}  // namespace cadnurbs
