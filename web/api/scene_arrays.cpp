#include "web/api/scene_arrays.hpp"

#include <stdexcept>

#include "analysis/certified_mesh/certified_scene_mesh.hpp"
#include "analysis/normals/crease_normals.hpp"
#include "core/bounding_box.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {

namespace {

struct Reader {
  bool (*matches)(const std::string& bytes);
  PartFile (*read)(const std::string& bytes, const std::string& name);
};

bool cnb_magic(const std::string& bytes) { return bytes.compare(0, 4, "\x89" "CNB") == 0; }
bool anything(const std::string&) { return true; }
PartFile read_cnb_bytes(const std::string& bytes, const std::string& name) {
  CnbFileFacts facts;
  Scene scene = read_cnb(bytes, name, &facts);
  return {std::move(scene), facts.deviation_bound};
}
PartFile read_vrml_bytes(const std::string& bytes, const std::string& name) { return {parse_vrml(bytes, name), 0}; }

// In order; the last takes what the others do not (parse_vrml names what it cannot read).
constexpr Reader readers[] = {{cnb_magic, read_cnb_bytes}, {anything, read_vrml_bytes}};

// Appends one face's triangles, a vertex per position and distinct corner normal.
void append_face(SceneArrays& out, const TriangleMesh& mesh, const Eigen::Affine3d& world, const Colour& colour) {
  const Eigen::Matrix3d normal_map = world.linear().inverse().transpose();
  const bool mirrored = world.linear().determinant() < 0;
  // For each mesh vertex, the (normal, output vertex) pairs made so far: a vertex has few distinct normals.
  std::vector<std::vector<std::pair<Eigen::Vector3d, uint32_t>>> made(mesh.positions.size());
  auto output_vertex = [&](int v, const Eigen::Vector3d& normal) {
    for (const auto& [n, index] : made[v])
      if (n == normal) return index;
    const uint32_t index = static_cast<uint32_t>(out.positions.size() / 3);
    const Eigen::Vector3d p = world * mesh.positions[v];
    const Eigen::Vector3d n = (normal_map * normal).normalized();
    for (int k = 0; k < 3; ++k) {
      out.positions.push_back(p[k]);
      out.normals.push_back(normal.squaredNorm() > 0 ? static_cast<float>(n[k]) : 0.0f);
    }
    made[v].emplace_back(normal, index);
    return index;
  };
  out.face_first_triangle.push_back(static_cast<uint32_t>(out.indices.size() / 3));
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    uint32_t corner[3];
    for (int k = 0; k < 3; ++k) corner[k] = output_vertex(mesh.triangles[t][k], mesh.corner_normals[3 * t + k]);
    if (mirrored) std::swap(corner[1], corner[2]);
    out.indices.insert(out.indices.end(), corner, corner + 3);
  }
  out.face_colours.insert(out.face_colours.end(), {static_cast<float>(colour.r), static_cast<float>(colour.g),
                                                   static_cast<float>(colour.b)});
}

}  // namespace

PartFile read_part_bytes(const std::string& bytes, const std::string& name) {
  for (const Reader& reader : readers)
    if (reader.matches(bytes)) return reader.read(bytes, name);
  throw std::logic_error("read_part_bytes: no reader");  // the last reader takes anything
}

Scene read_scene_bytes(const std::string& bytes, const std::string& name) { return read_part_bytes(bytes, name).scene; }

double scene_diagonal(const Scene& scene) {
  const Eigen::AlignedBox3d box = scene_bounding_box(scene);
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

SceneArrays certified_scene_arrays(const Scene& scene, double max_deviation, double crease_angle) {
  if (!(max_deviation > 0)) throw std::invalid_argument("certified_scene_arrays: the deviation must be positive");
  const CertifiedMesh certified = certified_scene_mesh(scene, max_deviation, EdgeSource::file);
  SceneArrays out;
  out.certified_deviation = certified.report.certified_deviation;
  out.uncertified_triangles = certified.report.uncertified_triangles;
  out.sewn = certified.sewn;
  for_each_shape(certified.meshes, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour& colour) {
    const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry);
    if (!mesh || mesh->triangles.empty()) return;
    if (mesh->corner_normals.empty())
      append_face(out, with_crease_normals(*mesh, crease_angle), world, colour);
    else
      append_face(out, *mesh, world, colour);
  });
  out.face_first_triangle.push_back(static_cast<uint32_t>(out.indices.size() / 3));
  return out;
}

}  // namespace cadnurbs
