#include "converters/file_formats.hpp"

#include <filesystem>

#include "analysis/tessellation_hints.hpp"
#include "core/repair_trimming_loops.hpp"
#include "formats/common/file_io.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/iges/iges_writer.hpp"
#include "formats/obj/obj_writer.hpp"
#include "formats/ply/ply_writer.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/step/step_writer.hpp"
#include "formats/stl/stl_reader.hpp"
#include "formats/stl/stl_writer.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"

namespace cadnurbs {

namespace {

std::string lower(std::string s) {
  for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// All meshes of the scene in world coordinates, as one mesh; refuses NURBS.
TriangleMesh flatten_meshes(const Scene& scene, const std::string& path) {
  TriangleMesh all;
  for_each_shape(scene, [&](const Shape& shape, const Eigen::Affine3d& world, const Colour&) {
    TriangleMesh m;
    if (const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry)) m = *mesh;
    else if (const auto* polygons = std::get_if<PolygonMesh>(&shape.geometry)) m = triangulated(*polygons);
    else throw FileError(path + ": shape '" + display_name(shape) + "' is NURBS; this format holds triangles only (use --mesh)");
    for (auto& p : m.positions) p = world * p;
    if (!m.corner_normals.empty())
      for (auto& n : m.corner_normals) n = (world.linear().inverse().transpose() * n).normalized();
    append(all, m);
  });
  return all;
}

BrepTranslation read_brep_step(const std::string& path, bool) { return read_step(path); }
BrepTranslation read_brep_iges(const std::string& path, bool) { return read_iges(path); }

BrepTranslation read_mesh_stl(const std::string& path, bool) {
  BrepTranslation read;
  read.scene.root.name = std::filesystem::path(path).stem().string();
  read.scene.root.shapes.push_back({read.scene.root.name, read_stl(path), std::nullopt});
  return read;
}

BrepTranslation read_any_vrml(const std::string& path, bool homogeneous) {
  BrepTranslation read;
  read.scene = read_vrml(path, homogeneous);
  return read;
}

void write_as_step(const std::string& path, const Scene& scene, const SceneWriteOptions&) { write_step(path, scene); }
void write_as_iges(const std::string& path, const Scene& scene, const SceneWriteOptions&) { write_iges(path, scene); }

void write_as_stl(const std::string& path, const Scene& scene, const SceneWriteOptions&) {
  write_stl(path, flatten_meshes(scene, path), StlEncoding::binary, scene.root.name);
}
void write_as_ply(const std::string& path, const Scene& scene, const SceneWriteOptions&) {
  write_ply(path, flatten_meshes(scene, path), "cadnurbs " + scene.root.name);
}
void write_as_obj(const std::string& path, const Scene& scene, const SceneWriteOptions&) {
  write_obj(path, flatten_meshes(scene, path), "cadnurbs " + scene.root.name);
}

template <VrmlEncoding encoding, bool gzipped>
void write_as_vrml(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  VrmlWriteOptions vrml;
  vrml.encoding = encoding;
  vrml.homogeneous_control_points = options.homogeneous_control_points;
  vrml.significant_digits = options.significant_digits;
  vrml.self_contained = options.self_contained;
  vrml.pretty = options.pretty;
  vrml.viewpoint = options.viewpoint;
  vrml.title = options.title;
  vrml.gzipped = gzipped;
  vrml.display_deviation = options.display_deviation;
  vrml.tessellation_hints = &tessellation_hints;
  write_vrml(path, scene, vrml);
  if (encoding == VrmlEncoding::vrml97 && !options.self_contained) {
    // The EXTERNPROTO URLs name this file beside the output; write it unless it is already there.
    const auto library = std::filesystem::path(path).parent_path() / vrml.protos_url;
    if (!std::filesystem::exists(library) || read_file(library.string()) != nurbs_protos_library())
      write_file_atomically(library.string(), nurbs_protos_library());
  }
}

}  // namespace

const std::vector<FileFormat>& file_formats() {
  using E = VrmlEncoding;
  static const std::vector<FileFormat> formats = {
      {"VRML97 with the blaxxun NURBS nodes", {".wrl"}, false, true, true, read_any_vrml, write_as_vrml<E::vrml97, false>},
      {"VRML97, gzip'd", {".wrz", ".wrl.gz"}, false, true, false, read_any_vrml, write_as_vrml<E::vrml97, true>},
      {"X3D classic", {".x3dv"}, false, true, true, read_any_vrml, write_as_vrml<E::x3d_classic, false>},
      {"X3D classic, gzip'd", {".x3dvz", ".x3dv.gz"}, false, true, false, read_any_vrml,
       write_as_vrml<E::x3d_classic, true>},
      {"X3D XML", {".x3d"}, false, true, true, read_any_vrml, write_as_vrml<E::x3d_xml, false>},
      {"X3D XML, gzip'd", {".x3dz", ".x3d.gz"}, false, true, false, read_any_vrml, write_as_vrml<E::x3d_xml, true>},
      {"STL (ASCII or binary in, binary out)", {".stl"}, true, false, true, read_mesh_stl, write_as_stl},
      {"PLY (binary)", {".ply"}, true, false, false, nullptr, write_as_ply},
      {"Wavefront OBJ", {".obj"}, true, false, false, nullptr, write_as_obj},
      {"STEP", {".step", ".stp"}, false, false, true, read_brep_step, write_as_step},
      {"IGES", {".iges", ".igs"}, false, false, true, read_brep_iges, write_as_iges},
  };
  return formats;
}

const FileFormat* format_of(const std::string& path) {
  const std::string name = lower(std::filesystem::path(path).filename().string());
  const FileFormat* best = nullptr;
  size_t best_length = 0;
  for (const auto& format : file_formats())
    for (const auto& ext : format.extensions)
      if (name.size() > ext.size() && name.compare(name.size() - ext.size(), ext.size(), ext) == 0 &&
          ext.size() > best_length) {
        best = &format;
        best_length = ext.size();
      }
  return best;
}

std::string extension_list(bool inputs) {
  std::string out;
  for (const auto& format : file_formats())
    if (inputs ? format.read != nullptr : format.write != nullptr)
      for (const auto& ext : format.extensions) out += (out.empty() ? "" : ", ") + ext;
  return out;
}

const FileFormat& input_format(const std::string& path) {
  const FileFormat* format = format_of(path);
  if (!format || !format->read)
    throw FileError(path + ": unknown input format '" + file_extension(path) + "' (expected " + extension_list(true) + ")");
  return *format;
}

const FileFormat& output_format(const std::string& path) {
  const FileFormat* format = format_of(path);
  if (!format || !format->write)
    throw FileError(path + ": unknown output format '" + file_extension(path) + "' (expected " + extension_list(false) +
                    ")");
  return *format;
}

BrepTranslation load_scene(const std::string& path, bool homogeneous_control_points) {
  BrepTranslation loaded = input_format(path).read(path, homogeneous_control_points);
  // The one check of trimming loops before any writer or tessellation. STEP/IGES faces (face_count > 0)
  // passed it already, face by face, where a refused face can still be meshed by OCCT.
  if (loaded.face_count == 0)
    for (auto& line : repair_trimming_loops(loaded.scene)) loaded.repairs.push_back(std::move(line));
  return loaded;
}

Scene read_scene(const std::string& path, bool homogeneous_control_points) {
  return load_scene(path, homogeneous_control_points).scene;
}

void write_scene(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  output_format(path).write(path, scene, options);
}

}  // namespace cadnurbs
