#pragma once
// What the browser module (web/module) hands to JavaScript: a part read from a file's bytes, and its
// certified mesh as flat arrays that WebGL draws as they are. The native build compiles the same code, so
// that the module's triangles can be compared with native ones (tests/web).
#include <cstdint>
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs {

// A .cnb file (told by its magic number) or a VRML97/X3D file, classic or XML, plain or gzip'd (told apart
// by content, as parse_vrml does). Throws FileError "<name>: ..." as read_cnb and parse_vrml do.
Scene read_scene_bytes(const std::string& bytes, const std::string& name);

// The same, with what the file says of its accuracy: a .cnb states the bound within which every point of it
// lies from the part it was written from (its header's deviation bound); VRML and X3D state none (0).
struct PartFile {
  Scene scene;
  double deviation_bound = 0;
};
PartFile read_part_bytes(const std::string& bytes, const std::string& name);

// The diagonal of the scene's bounding box (control points and vertices, placed); 0 for an empty scene.
// Deviations asked of certified_scene_arrays are fractions of it.
double scene_diagonal(const Scene& scene);

// A scene's certified mesh (certified_scene_mesh, its faces sewn as `convert --mesh` sews a file of
// faces), flattened: one vertex per position and normal, in world coordinates (the nodes' transforms
// applied, a mirroring one turning its triangles round). Meshes the file holds keep their normals, or get
// crease normals at crease_angle where they have none.
struct SceneArrays {
  std::vector<double> positions;             // 3 per vertex
  std::vector<float> normals;                // 3 per vertex, unit (zero where a vertex's triangles have no area)
  std::vector<uint32_t> indices;             // 3 per triangle, counter-clockwise seen from outside
  std::vector<uint32_t> face_first_triangle; // per face (shape with triangles), its first triangle; then the count
  std::vector<float> face_colours;           // 3 per face: red, green, blue in 0..1
  double certified_deviation = 0;            // largest certified bound over the faces' triangles
  long uncertified_triangles = 0;            // as TessellationReport says
  bool sewn = false;                         // whether the faces were sewn before meshing
};

constexpr double default_crease_angle = 0.5;  // radians; about 29 degrees

// Refuses max_deviation <= 0 (std::invalid_argument); throws GeometryError naming a face that cannot be
// tessellated.
SceneArrays certified_scene_arrays(const Scene& scene, double max_deviation,
                                   double crease_angle = default_crease_angle);

}  // namespace cadnurbs
