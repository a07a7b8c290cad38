#include "converters/scene_io.hpp"

#include <filesystem>

#include "formats/common/file_io.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/iges/iges_writer.hpp"
#include "formats/ply/ply_writer.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/step/step_writer.hpp"
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
      throw FileError(path + ": shape '" + shape.name + "' is NURBS; this format holds triangles only (use --mesh)");
    TriangleMesh m = *mesh;
    for (auto& p : m.positions) p = world * p;
    if (!m.corner_normals.empty())
      for (auto& n : m.corner_normals) n = (world.linear().inverse().transpose() * n).normalized();
    append(all, m);
  });
  return all;
}

}  // namespace

bool is_mesh_only_format(const std::string& path) {
  const std::string ext = file_extension(path);
  return ext == ".stl" || ext == ".ply";
}

LoadedScene load_scene(const std::string& path, bool homogeneous_control_points) {
  const std::string ext = file_extension(path);
  auto from_brep = [](BrepTranslation t) {
    return LoadedScene{std::move(t.scene), std::move(t.fallbacks), t.face_count, std::move(t.degenerated_edges)};
  };
  if (ext == ".step" || ext == ".stp") return from_brep(read_step(path));
  if (ext == ".iges" || ext == ".igs") return from_brep(read_iges(path));
  LoadedScene loaded;
  if (ext == ".stl") {
    loaded.scene.root.name = std::filesystem::path(path).stem().string();
    loaded.scene.root.shapes.push_back({loaded.scene.root.name, read_stl(path), std::nullopt});
  } else if (encoding_for_extension(ext)) {
    loaded.scene = read_vrml(path, homogeneous_control_points);
  } else {
    throw FileError(path + ": unknown input format '" + ext +
                    "' (expected .step, .stp, .iges, .igs, .stl, .wrl, .x3dv or .x3d)");
  }
  return loaded;
}

Scene read_scene(const std::string& path, bool homogeneous_control_points) {
  return load_scene(path, homogeneous_control_points).scene;
}

void write_scene(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  const std::string ext = file_extension(path);
  if (ext == ".stl") {
    write_stl(path, flatten_meshes(scene, path), StlEncoding::binary, scene.root.name);
    return;
  }
  if (ext == ".ply") {
    write_ply(path, flatten_meshes(scene, path), "cadnurbs " + scene.root.name);
    return;
  }
  if (ext == ".step" || ext == ".stp") {
    write_step(path, scene);
    return;
  }
  if (ext == ".iges" || ext == ".igs") {
    write_iges(path, scene);
    return;
  }
  const auto encoding = encoding_for_extension(ext);
  if (!encoding) throw FileError(path + ": unknown output format '" + ext + "' (expected .wrl, .x3dv, .x3d, .stl, .ply, .step or .iges)");
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
