#include "converters/file_formats.hpp"

#include <algorithm>
#include <filesystem>

#include "report/smallest_compressed_mesh.hpp"
#include "analysis/tessellation/plan_tessellation_hints.hpp"
#include "analysis/mesh/weld_exact.hpp"
#include "converters/cnb_coding.hpp"
#include "converters/subd_objects_as_nurbs.hpp"
#include "converters/walled_read.hpp"
#include "core/bounding_box.hpp"
#include "core/geometry_error.hpp"
#include "core/repair_trimming_loops.hpp"
#include "formats/3dm/rhino_scene.hpp"
#include "formats/common/file_io.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/draco/draco_mesh_codec.hpp"
#include "formats/gltf/glb_writer.hpp"
#include "formats/iges/iges_reader.hpp"
#include "formats/iges/iges_writer.hpp"
#include "formats/obj/obj_writer.hpp"
#include "formats/ply/ply_writer.hpp"
#include "formats/step/native/read_step_native.hpp"
#include "formats/step/step_reader.hpp"
#include "formats/step/step_writer.hpp"
#include "formats/stl/stl_reader.hpp"
#include "formats/stl/stl_writer.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"
#include "web/page/viewer_page.hpp"

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
    else if (std::holds_alternative<NurbsCurve>(shape.geometry))
      throw FileError(path + ": shape '" + display_name(shape) + "' is a NURBS curve; this format holds triangles only");
    else throw FileError(path + ": shape '" + display_name(shape) + "' is NURBS; this format holds triangles only (use --mesh)");
    for (auto& p : m.positions) p = world * p;
    if (!m.corner_normals.empty())
      for (auto& n : m.corner_normals) n = (world.linear().inverse().transpose() * n).normalized();
    append(all, m);
  });
  return all;
}

// Behind the wall in the cadnurbs command (a crash or hang in OCCT costs a child process), see walled_read.
// Our own reader first (in this process: it is bounded and fuzzed, it needs no wall), OpenCASCADE's for a
// file it cannot read, unless --reader chose one.
BrepTranslation read_brep_step(const std::string& path, const SceneReadOptions& options) {
  const StepReaderChoice choice = options.brep.step_reader;
  if (choice == StepReaderChoice::occt) return read_brep(path, "STEP", options.brep);
  std::string why;
  try {
    return read_step_native(path);
  } catch (const step::OutsideNativeSubset& outside) {
    if (choice == StepReaderChoice::native) throw FileError(path + ": outside the native STEP reader's subset: " + outside.what());
    why = outside.what();
  } catch (const std::exception& error) {
    if (choice == StepReaderChoice::native) throw;
    why = error.what();
    if (why.starts_with(path + ": ")) why.erase(0, path.size() + 2);
  }
  BrepTranslation out = read_brep(path, "STEP", options.brep);
  out.notes.insert(out.notes.begin(), "read by OpenCASCADE: our STEP reader stopped at " + why);
  return out;
}
BrepTranslation read_brep_iges(const std::string& path, const SceneReadOptions& options) {
  return read_brep(path, "IGES", options.brep);
}

BrepTranslation read_mesh_stl(const std::string& path, const SceneReadOptions&) {
  BrepTranslation read;
  read.scene.root.name = std::filesystem::path(path).stem().string();
  read.scene.root.shapes.push_back({read.scene.root.name, read_stl(path), std::nullopt});
  return read;
}

// .3dm: faces written as Rhino's render meshes are fallbacks; faces left out or repaired are reported as
// repairs ("object N face K: ..."); the scene's trims were checked face by face while it was built.
BrepTranslation read_rhino_3dm(const std::string& path, const SceneReadOptions& options) {
  rhino::RhinoScene read = rhino::read_3dm(path);
  BrepTranslation out;
  out.scene = std::move(read.scene);
  out.repairs = std::move(read.warnings);
  for (const auto& meshed : read.meshed_faces)
    out.fallbacks.push_back({meshed.object, meshed.face, "Brep face", meshed.reason + " (Rhino's render mesh used)"});
  out.face_count = read.face_count;
  out.degenerated_edges.assign(read.edge_count, false);
  add_subd_objects_as_nurbs(read.subd_objects, options.subd_deviation, out);
  return out;
}

BrepTranslation read_compact_binary(const std::string& path, const SceneReadOptions&) {
  BrepTranslation read;
  read.scene = read_cnb(read_file(path), path);
  return read;
}

BrepTranslation read_any_vrml(const std::string& path, const SceneReadOptions& options) {
  SceneFromNodes vrml = read_vrml_scene(path, options.homogeneous_control_points);
  BrepTranslation read;
  read.scene = std::move(vrml.scene);
  read.notes = std::move(vrml.notes);
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

// .cnb: each body coded the cheapest way (NURBS or certified mesh) within the budget (the deviation asked
// for); without one, within 1e-6 of the diagonal, the precision the text writers keep.
std::string cnb_bytes(const Scene& scene, const SceneWriteOptions& options) {
  const auto box = scene_bounding_box(scene);
  const double budget = options.quantisation_budget > 0 ? options.quantisation_budget
                                                        : 1e-6 * (box.isEmpty() ? 1.0 : box.diagonal().norm());
  return cnb_coding(scene, budget).bytes;
}
void write_coded_cnb(const std::string& path, const std::string& bytes) { write_file_atomically(path, bytes); }
void write_as_cnb(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  write_coded_cnb(path, cnb_bytes(scene, options));
}

// .html: one self-contained page showing the part (web/page): its .cnb, as write_as_cnb writes it, with the
// WebAssembly module and the viewer inlined; it works from a file:// URL with no network.
void write_coded_html(const std::string& path, const std::string& bytes) {
  write_file_atomically(path, viewer_page(bytes, std::filesystem::path(path).stem().string()));
}
void write_as_html(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  write_coded_html(path, cnb_bytes(scene, options));
}

// The quantisation resolutions a writer tries, coarsest first, stopping at the first within the budget.
constexpr int kCoarsestBits = 4;

// `node` without its triangle meshes whose every triangle has two corners at one position (a tiny face that a
// coarse .cnb grid collapsed): they draw nothing, and Draco refuses a mesh of only such triangles.
void drop_collapsed_meshes(SceneNode& node) {
  std::erase_if(node.shapes, [](const Shape& shape) {
    const auto* mesh = std::get_if<TriangleMesh>(&shape.geometry);
    return mesh && std::ranges::all_of(mesh->triangles, [&](const std::array<int, 3>& t) {
             const auto& p = mesh->positions;
             return p[t[0]] == p[t[1]] || p[t[1]] == p[t[2]] || p[t[2]] == p[t[0]];
           });
  });
  for (auto& child : node.children) drop_collapsed_meshes(child);
}

void write_as_glb(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  const auto compression = glb_compression_named(options.compression);
  if (!compression)
    throw FileError(path + ": unknown --compress '" + options.compression + "' (none, draco, meshopt)");
  GlbOptions glb;
  glb.compression = *compression;
  Scene drawn = scene;
  if (glb.compression == GlbCompression::draco) drop_collapsed_meshes(drawn.root);
  std::string bytes;
  if (glb.compression == GlbCompression::none || options.quantisation_budget <= 0) {
    bytes = write_glb(drawn, glb);
  } else {
    const int finest = glb.compression == GlbCompression::meshopt ? 16 : 30;
    for (glb.position_bits = kCoarsestBits; glb.position_bits <= finest; ++glb.position_bits) {
      GlbReport report;
      bytes = write_glb(drawn, glb, &report);
      if (report.max_position_error <= options.quantisation_budget) break;
    }
    if (glb.position_bits > finest)
      throw FileError(path + ": " + std::to_string(finest) + "-bit positions still move by more than " +
                      std::to_string(options.quantisation_budget) + " (use --compress none)");
  }
  write_file_atomically(path, bytes);
}

// Draco's own mesh file: all faces as one mesh in world coordinates, welded, positions on the coarsest
// grid that moves no vertex by more than the budget and collapses no triangle (report/smallest_compressed_mesh's
// rule, Draco's quantisation replayed exactly).
void write_as_drc(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  const TriangleMesh mesh = weld_exact(flatten_meshes(scene, path));
  int bits = 14;
  if (options.quantisation_budget > 0) {
    bits = coarsest_quantisation(mesh, MeshCodec::draco, options.quantisation_budget).bits;
    if (bits == 0) throw FileError(path + ": no Draco quantisation keeps the mesh within the allowed deviation");
  }
  write_file_atomically(path, encode_draco_mesh(mesh, bits, 0));
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
  vrml.tessellation_hints = &plan_tessellation_hints;
  write_vrml(path, scene, vrml);
  if (encoding == VrmlEncoding::vrml97 && !options.self_contained) write_nurbs_protos_beside(path, vrml.protos_url);
}

}  // namespace

void write_nurbs_protos_beside(const std::string& path, const std::string& protos_url) {
  // The EXTERNPROTO URLs name this file beside the output.
  const auto library = std::filesystem::path(path).parent_path() / protos_url;
  if (!std::filesystem::exists(library) || read_file(library.string()) != nurbs_protos_library())
    write_file_atomically(library.string(), nurbs_protos_library());
}

std::optional<VrmlTextForm> vrml_text_form(const FileFormat& format) {
  using E = VrmlEncoding;
  for (const auto& [write, form] : std::initializer_list<std::pair<decltype(FileFormat::write), VrmlTextForm>>{
           {write_as_vrml<E::vrml97, false>, {E::vrml97, false}},
           {write_as_vrml<E::vrml97, true>, {E::vrml97, true}},
           {write_as_vrml<E::x3d_classic, false>, {E::x3d_classic, false}},
           {write_as_vrml<E::x3d_classic, true>, {E::x3d_classic, true}},
           {write_as_vrml<E::x3d_xml, false>, {E::x3d_xml, false}},
           {write_as_vrml<E::x3d_xml, true>, {E::x3d_xml, true}}})
    if (format.write == write) return form;
  return std::nullopt;
}

const std::vector<FileFormat>& file_formats() {
  using E = VrmlEncoding;
  static const std::vector<FileFormat> formats = {
      {"VRML97 with the blaxxun NURBS nodes", {".wrl"}, false, true, true, read_any_vrml, write_as_vrml<E::vrml97, false>, false, LoopsOutsideDomain::cut},
      {"VRML97, gzip'd", {".wrz", ".wrl.gz"}, false, true, false, read_any_vrml, write_as_vrml<E::vrml97, true>, false, LoopsOutsideDomain::cut},
      {"X3D classic", {".x3dv"}, false, true, true, read_any_vrml, write_as_vrml<E::x3d_classic, false>, false, LoopsOutsideDomain::cut},
      {"X3D classic, gzip'd", {".x3dvz", ".x3dv.gz"}, false, true, false, read_any_vrml,
       write_as_vrml<E::x3d_classic, true>, false, LoopsOutsideDomain::cut},
      {"X3D XML", {".x3d"}, false, true, true, read_any_vrml, write_as_vrml<E::x3d_xml, false>, false, LoopsOutsideDomain::cut},
      {"X3D XML, gzip'd", {".x3dz", ".x3d.gz"}, false, true, false, read_any_vrml, write_as_vrml<E::x3d_xml, true>, false, LoopsOutsideDomain::cut},
      {"STL (ASCII or binary in, binary out)", {".stl"}, true, false, true, read_mesh_stl, write_as_stl},
      {"PLY (binary)", {".ply"}, true, false, false, nullptr, write_as_ply},
      {"Wavefront OBJ", {".obj"}, true, false, false, nullptr, write_as_obj},
      {"STEP", {".step", ".stp"}, false, false, true, read_brep_step, write_as_step},
      {"IGES", {".iges", ".igs"}, false, false, true, read_brep_iges, write_as_iges},
      {"Rhino 3DM (openNURBS archive, Rhino 1-8)", {".3dm"}, false, false, false, read_rhino_3dm, nullptr},
      {"glTF 2.0 binary (Draco, meshopt or no compression)", {".glb"}, true, false, false, nullptr, write_as_glb, true},
      {"Draco mesh", {".drc"}, true, false, false, nullptr, write_as_drc, true},
      {"cadnurbs compact binary NURBS (docs/cnb.md)", {".cnb"}, false, true, false, read_compact_binary, write_as_cnb, true,
       LoopsOutsideDomain::refuse, write_coded_cnb},
      {"web page showing the part (its .cnb and the viewer inlined; works offline)", {".html"}, false, true, false, nullptr,
       write_as_html, true, LoopsOutsideDomain::refuse, write_coded_html},
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

const FileFormat& named_input_format(const std::string& name) {
  const std::string extension = name.empty() || name.front() == '.' ? name : "." + name;
  const FileFormat* format = format_of("x" + extension);
  if (extension.size() < 2 || !format || !format->read)
    throw FileError("unknown input format '" + name + "' (expected " + extension_list(true) + ")");
  return *format;
}

const FileFormat& output_format(const std::string& path) {
  const FileFormat* format = format_of(path);
  if (!format || !format->write)
    throw FileError(path + ": unknown output format '" + file_extension(path) + "' (expected " + extension_list(false) +
                    ")");
  return *format;
}

BrepTranslation load_scene(const std::string& path, const SceneReadOptions& options) {
  regular_file_size(path);  // a directory, device or FIFO is refused by type, whatever reads the format
  return load_scene_as(path, input_format(path), options);
}

BrepTranslation load_scene_as(const std::string& path, const FileFormat& format, const SceneReadOptions& options) {
  regular_file_size(path);
  BrepTranslation loaded = format.read(path, options);
  // The one check of trimming loops before any writer or tessellation. STEP/IGES faces (face_count > 0)
  // passed it already, face by face, where a refused face can still be meshed by OCCT.
  if (loaded.face_count == 0) {
    try {
      for (auto& line : repair_trimming_loops(loaded.scene, format.loops_outside_domain)) loaded.repairs.push_back(std::move(line));
    } catch (const GeometryError& e) {
      throw FileError(path + ": " + e.what());  // the message names the input, as every reader's does
    }
  }
  return loaded;
}

Scene read_scene(const std::string& path, const SceneReadOptions& options) { return load_scene(path, options).scene; }

void write_scene(const std::string& path, const Scene& scene, const SceneWriteOptions& options) {
  output_format(path).write(path, scene, options);
}

}  // namespace cadnurbs
