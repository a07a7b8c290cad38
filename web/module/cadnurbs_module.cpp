// The browser module's C interface over web/api/scene_arrays: plain pointers and counts, no state of its
// own; web/module/cadnurbs.mjs wraps it for JavaScript. Every failure returns null and writes its one-line
// message into the caller's `error` buffer.
#include <emscripten/emscripten.h>

#include <cstring>
#include <exception>
#include <string>

#include "web/api/scene_arrays.hpp"

using cadnurbs::PartFile;
using cadnurbs::SceneArrays;

namespace {

void tell(char* error, size_t error_size, const char* what) {
  if (error_size == 0) return;
  std::strncpy(error, what, error_size - 1);
  error[error_size - 1] = '\0';
}

// make()'s result, or null with the exception's message in `error` (`doing` names the step otherwise).
template <class Make>
auto guarded(char* error, size_t error_size, const char* doing, Make&& make) -> decltype(make()) {
  try {
    return make();
  } catch (const std::exception& e) {
    tell(error, error_size, e.what());
  } catch (...) {
    tell(error, error_size, (std::string("unknown failure while ") + doing).c_str());
  }
  return nullptr;
}

}  // namespace

extern "C" {

// The part in `size` bytes at `bytes` (.cnb, VRML97 or X3D), `name` naming it in messages.
EMSCRIPTEN_KEEPALIVE PartFile* cn_read(const char* bytes, size_t size, const char* name, char* error, size_t error_size) {
  return guarded(error, error_size, "reading",
                 [&] { return new PartFile(cadnurbs::read_part_bytes(std::string(bytes, size), name)); });
}

EMSCRIPTEN_KEEPALIVE void cn_scene_free(PartFile* part) { delete part; }

// scene_diagonal (web/api/scene_arrays.hpp).
EMSCRIPTEN_KEEPALIVE double cn_scene_diagonal(const PartFile* part) { return cadnurbs::scene_diagonal(part->scene); }

// The bound the file states on its own deviation from the part it was written from (0: none stated).
EMSCRIPTEN_KEEPALIVE double cn_scene_file_deviation_bound(const PartFile* part) { return part->deviation_bound; }

// The certified mesh of the part's scene within `deviation` (the scene's units).
EMSCRIPTEN_KEEPALIVE SceneArrays* cn_mesh(const PartFile* part, double deviation, char* error, size_t error_size) {
  return guarded(error, error_size, "meshing",
                 [&] { return new SceneArrays(cadnurbs::certified_scene_arrays(part->scene, deviation)); });
}

EMSCRIPTEN_KEEPALIVE void cn_mesh_free(SceneArrays* mesh) { delete mesh; }

// Where and how long each of the mesh's arrays is (counts of elements: doubles, floats, integers).
EMSCRIPTEN_KEEPALIVE const double* cn_mesh_positions(const SceneArrays* m) { return m->positions.data(); }
EMSCRIPTEN_KEEPALIVE const float* cn_mesh_normals(const SceneArrays* m) { return m->normals.data(); }
EMSCRIPTEN_KEEPALIVE size_t cn_mesh_vertex_count(const SceneArrays* m) { return m->positions.size() / 3; }
EMSCRIPTEN_KEEPALIVE const uint32_t* cn_mesh_indices(const SceneArrays* m) { return m->indices.data(); }
EMSCRIPTEN_KEEPALIVE size_t cn_mesh_triangle_count(const SceneArrays* m) { return m->indices.size() / 3; }
EMSCRIPTEN_KEEPALIVE const uint32_t* cn_mesh_face_first_triangle(const SceneArrays* m) {
  return m->face_first_triangle.data();
}
EMSCRIPTEN_KEEPALIVE const float* cn_mesh_face_colours(const SceneArrays* m) { return m->face_colours.data(); }
EMSCRIPTEN_KEEPALIVE size_t cn_mesh_face_count(const SceneArrays* m) { return m->face_colours.size() / 3; }
EMSCRIPTEN_KEEPALIVE double cn_mesh_certified_deviation(const SceneArrays* m) { return m->certified_deviation; }
EMSCRIPTEN_KEEPALIVE double cn_mesh_uncertified_triangles(const SceneArrays* m) {
  return static_cast<double>(m->uncertified_triangles);
}
EMSCRIPTEN_KEEPALIVE int cn_mesh_sewn(const SceneArrays* m) { return m->sewn ? 1 : 0; }

}  // extern "C"
