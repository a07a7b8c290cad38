#pragma once
// The one table from file-name extensions to the readers and writers in formats/. convert, info,
// capping and demo look formats up here, and their help texts print the lists made from it.
#include <string>
#include <vector>

#include "converters/walled_read.hpp"
#include "core/repair_trimming_loops.hpp"
#include "core/scene.hpp"
#include "formats/brep/brep_translation.hpp"
#include "formats/vrml/vrml_write_options.hpp"

namespace cadnurbs {

// How a scene is written; each writer uses the fields that concern it.
struct SceneWriteOptions {
  bool homogeneous_control_points = true;
  int significant_digits = 0;   // 0: automatic (fewest digits within the tolerance)
  bool self_contained = false;  // VRML97: paste the NURBS PROTOs instead of EXTERNPROTO
  bool pretty = false;          // VRML/X3D: indent nodes, one field per line
  // VRML/X3D NURBS: > 0 writes tessellation counts with which uniform-grid viewers draw every face
  // within about this deviation (analysis/tessellation/plan_tessellation_hints), in the scene's units.
  double display_deviation = 0.0;
  std::optional<Viewpoint> viewpoint;
  std::string title;
  // Formats that quantise positions (.glb, .drc): how far a decoded vertex may move (model units); the
  // writer takes the coarsest quantisation within it. 0: the writer's default resolution.
  double quantisation_budget = 0.0;
  std::string compression = "draco";  // .glb: none, draco or meshopt (--compress)
};

// How a file is read; each reader uses the fields that concern it.
struct SceneReadOptions {
  bool homogeneous_control_points = true;  // VRML/X3D: control points are w·P (false: --euclidean)
  BrepReadOptions brep;                    // STEP/IGES: behind the wall or not, and its limits
  double subd_deviation = 0;  // .3dm SubD: how far its fitted NURBS patches may be (0: 1e-4 of its diagonal)
};

struct FileFormat {
  std::string name;                     // "X3D classic, gzip'd"
  std::vector<std::string> extensions;  // lower case with the dot; the first is the usual one
  bool meshes_only = false;             // holds triangles only: NURBS must be tessellated first
  bool compact = false;                 // VRML/X3D NURBS output: gets the compact, exact rewrites
  bool in_samples = false;              // the bundled samples (samples/, `capping`) come in it
  // null when the format is not read / not written. Readers return what they read (the B-rep
  // readers' account of fallen-back faces included); writers write atomically.
  BrepTranslation (*read)(const std::string& path, const SceneReadOptions& options) = nullptr;
  void (*write)(const std::string& path, const Scene& scene, const SceneWriteOptions& options) = nullptr;
  bool quantises = false;  // its writer moves positions (SceneWriteOptions::quantisation_budget)
  // What its trimming loops far outside a surface's domain mean: a fault, or GLU's rule (VRML/X3D).
  LoopsOutsideDomain loops_outside_domain = LoopsOutsideDomain::refuse;
  // A quantising NURBS format (.cnb, .html): writes the .cnb coding convert made (cnb_coding, with its
  // report) as this format holds it, atomically. null for the others.
  void (*write_coded)(const std::string& path, const std::string& cnb_bytes) = nullptr;
};

// Every format, inputs and outputs.
const std::vector<FileFormat>& file_formats();

// The text encoding of a VRML/X3D format of the table and whether it is the gzip'd form; nullopt for
// the other formats. For commands that rewrite VRML/X3D text themselves (fit-path).
struct VrmlTextForm {
  VrmlEncoding encoding;
  bool gzipped;
};
std::optional<VrmlTextForm> vrml_text_form(const FileFormat& format);

// For a VRML97 file at `path` that declares NURBS nodes by EXTERNPROTO: writes the PROTO library beside
// it (as `protos_url`) unless the same library is already there.
void write_nurbs_protos_beside(const std::string& path, const std::string& protos_url);

// The format whose extension ends `path` (case-insensitive; the longest match wins, so ".wrl.gz" beats
// ".gz"), or null.
const FileFormat* format_of(const std::string& path);

// The format that reads (or writes) `path`. Throws FileError "<path>: unknown input format '<ext>'
// (expected .step, ...)" naming the extensions that would do.
const FileFormat& input_format(const std::string& path);
const FileFormat& output_format(const std::string& path);

// The input format of extension `name` ("step", ".step", "STL"), for --from. Throws FileError
// "unknown input format 'x' (expected ...)" when no input format has it.
const FileFormat& named_input_format(const std::string& name);

// "a, b, c" of every extension that is read (inputs) or written (outputs).
std::string extension_list(bool inputs);

// input_format(path).read: the scene and, from STEP/IGES, the faces that fell back to meshes. Throws
// FileError/GeometryError with a one-line message.
BrepTranslation load_scene(const std::string& path, const SceneReadOptions& options = {});

// load_scene with the format given rather than taken from the name (content_format.hpp tells it).
BrepTranslation load_scene_as(const std::string& path, const FileFormat& format, const SceneReadOptions& options = {});

// load_scene(...).scene.
Scene read_scene(const std::string& path, const SceneReadOptions& options = {});

// output_format(path).write. Formats that hold meshes only refuse NURBS (tessellate first). For a VRML97
// file that is not self-contained, also writes the PROTO library beside it when it is missing.
void write_scene(const std::string& path, const Scene& scene, const SceneWriteOptions& options);

}  // namespace cadnurbs
