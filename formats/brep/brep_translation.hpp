#pragma once
// What a B-rep reader (STEP, IGES) hands back: the scene, and an account of the faces that could not be
// written as trimmed NURBS. No OpenCASCADE types: converters see only this.
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

// A face written as a triangle mesh ("face N (mesh)") because it could not be converted to a trimmed NURBS.
struct FaceFallback {
  std::string node;          // path of the scene node holding it, names joined by "/"
  int face_index = 0;        // N of "face N": 1-based index in its solid's/shell's face map
  std::string surface_type;  // the source surface, e.g. "BSplineSurface", "Plane", "CylindricalSurface"
  std::string reason;        // why the conversion failed (one line)
};

struct BrepTranslation {
  Scene scene;                          // millimetres; scene.source_unit is the file's unit
  std::vector<FaceFallback> fallbacks;  // one per face written as a mesh, in scene order
  // One line per repair of a face's trimming loops (repair_trimming_loops), "PATH face N (TYPE): what";
  // load_scene adds those of any other input.
  std::vector<std::string> repairs;
  // What the user should know about how the file was read, one line each (e.g. which STEP reader read it
  // and why); printed with the repairs.
  std::vector<std::string> notes;
  int face_count = 0;                   // faces in the scene: trimmed NURBS + fallbacks
  // Indexed by TrimEdgeRef::edge: true for a degenerated edge (a pole of a sphere, the apex of a cone),
  // whose 3D image is a single point.
  std::vector<bool> degenerated_edges;
};

}  // namespace cadnurbs
