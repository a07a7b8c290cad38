#include "converters/scene_io.hpp"

#include <filesystem>

#include "formats/common/file_io.hpp"
#include "formats/stl/stl_reader.hpp"
#include "formats/stl/stl_writer.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {

namespace {

// All meshes of the scene in world coordinates, as one mesh; refuses NURBS.
TriangleMesh flatten_meshes(const Scene& scene, const std::string& path) {
  TriangleMesh all;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry);
    if (!mesh)
      throw FileError(path + ": shape '" + shape.name + "' is NURBS; STL holds triangles only (use --mesh)");
    TriangleMesh m = *mesh;
    for (auto& p : m.positions) p = world * p;
    m.corner_normals.clear();
    append(all, m);
  });
  return all;
}

}  // namespace

bool is_mesh_only_format(const std::string& path) { return file_extension(path) == ".stl"; }

Scene read_scene(const std::string& path, bool homogeneous_control_points) {
  const std::string ext = file_extension(path);
  if (ext == ".stl") {
    Scene scene;
    scene.root.name = std::filesystem::path(path).stem().string();
    scene.root.shapes.push_back({scene.root.name, read_stl(path), std::nullopt});
    return scene;
  }
  if (encoding_for_extension(ext)) return read_vrml(path, homogeneous_control_points);
  throw FileError(path + ": unknown input format '" + ext + "' (expected .stl, .wrl, .x3dv or .x3d)");
}

void write_scene(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  const std::string ext = file_extension(path);
  if (ext == ".stl") {
    write_stl(path, flatten_meshes(scene, path), StlEncoding::binary, scene.root.name);
    return;
  }
  const auto encoding = encoding_for_extension(ext);
  if (!encoding) throw FileError(path + ": unknown output format '" + ext + "' (expected .wrl, .x3dv, .x3d or .stl)");
  VrmlWriteOptions vrml;
  vrml.encoding = *encoding;
  vrml.homogeneous_control_points = options.homogeneous_control_points;
  vrml.significant_digits = options.significant_digits;
  vrml.self_contained = options.self_contained;
  vrml.viewpoint = options.viewpoint;
  vrml.title = options.title;
  write_vrml(path, scene, vrml);
  if (*encoding == VrmlEncoding::vrml97 && !options.self_contained) {
    // The EXTERNPROTO URLs name this file beside the output; write it unless it is already there.
    const auto library = std::filesystem::path(path).parent_path() / vrml.protos_url;
    if (!std::filesystem::exists(library) || read_file(library.string()) != nurbs_protos_library())
      write_file_atomically(library.string(), nurbs_protos_library());
  }
}

}  // namespace cadnurbs
