#pragma once
// Reading any supported input into a Scene and writing a Scene to the format its extension names.
// The one place that knows which format module handles which extension.
#include <string>

#include "core/scene.hpp"
#include "formats/brep/brep_translation.hpp"
#include "formats/vrml/vrml_writer.hpp"

namespace cadnurbs {

struct SceneWriteOptions {
  bool homogeneous_control_points = true;
  int significant_digits = 0;  // 0: automatic (fewest digits within the tolerance)
  bool self_contained = false;  // VRML97: paste the NURBS PROTOs instead of EXTERNPROTO
  std::optional<Viewpoint> viewpoint;
  std::string title;
};

// A scene as read, with the faces a B-rep reader had to write as meshes.
struct LoadedScene {
  Scene scene;
  std::vector<FaceFallback> fallbacks;  // STEP/IGES only
  int face_count = 0;                   // STEP/IGES: faces in the source
  std::vector<bool> degenerated_edges;  // STEP/IGES: by TrimEdgeRef::edge
};

// .step/.stp, .iges/.igs, .stl (ASCII or binary), .wrl, .x3dv, .x3d. Throws FileError/GeometryError
// with a one-line message.
LoadedScene load_scene(const std::string& path, bool homogeneous_control_points = true);

// load_scene(...).scene.
Scene read_scene(const std::string& path, bool homogeneous_control_points = true);

// .wrl, .x3dv, .x3d, .step/.stp, .iges/.igs take the scene as it is; .stl and .ply take meshes only
// (NURBS must be tessellated first). Refuses an unknown extension. Writes atomically. For a VRML97 file that is not
// self-contained, also writes the PROTO library beside it when it is missing.
void write_scene(const std::string& path, const Scene& scene, const SceneWriteOptions& options);

// True when the extension is one write_scene accepts, and whether it needs meshes only.
bool is_mesh_only_format(const std::string& path);

}  // namespace cadnurbs
