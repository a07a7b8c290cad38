// The native twin of the browser module's meshing, for compare_with_native.mjs:
//   native_scene_arrays FILE FRACTION OUT
// reads FILE (.cnb, VRML97, X3D) with read_scene_bytes, meshes it within FRACTION of its bounding box's
// diagonal (certified_scene_arrays) and writes OUT, little-endian: "CNSA", then uint32 vertex, triangle and
// face counts, float64 diagonal, deviation and certified deviation, then the positions (float64), indices
// (uint32), faces' first triangles (uint32, faces + 1) and normals (float32). Exit 1 with the message on
// failure.
#include <cstdint>
#include <cstdio>
#include <exception>
#include <fstream>
#include <string>

#include "formats/common/file_io.hpp"
#include "web/api/scene_arrays.hpp"

using namespace cadnurbs;

namespace {

template <class T>
void put(std::ofstream& out, const T& value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

template <class T>
void put_all(std::ofstream& out, const std::vector<T>& values) {
  out.write(reinterpret_cast<const char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(T)));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: native_scene_arrays FILE FRACTION OUT\n");
    return 2;
  }
  try {
    const Scene scene = read_scene_bytes(read_file(argv[1]), argv[1]);
    const double diagonal = scene_diagonal(scene);
    const double deviation = std::stod(argv[2]) * diagonal;
    const SceneArrays arrays = certified_scene_arrays(scene, deviation);
    std::ofstream out(argv[3], std::ios::binary);
    out.write("CNSA", 4);
    put(out, static_cast<uint32_t>(arrays.positions.size() / 3));
    put(out, static_cast<uint32_t>(arrays.indices.size() / 3));
    put(out, static_cast<uint32_t>(arrays.face_colours.size() / 3));
    put(out, diagonal);
    put(out, deviation);
    put(out, arrays.certified_deviation);
    put_all(out, arrays.positions);
    put_all(out, arrays.indices);
    put_all(out, arrays.face_first_triangle);
    put_all(out, arrays.normals);
    if (!out) throw std::runtime_error(std::string(argv[3]) + ": cannot write");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  return 0;
}
