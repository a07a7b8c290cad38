// Writes the browser test's files for one sample (tests/gltf/CMakeLists.txt):
//   gltf_sample_files IN DEVIATION OUT_DIR STEM
// IN (any file formats/vrml reads) tessellated within DEVIATION (scene units) is written as
//   STEM-none.glb, STEM-draco.glb, STEM-meshopt.glb   (write_glb, 14 position bits)
//   STEM-mesh.stl                                     (the same triangles, millimetres, +Z up: the reference)
//   STEM-mirrored-meshopt.glb                         (negative control: the part mirrored, y -> -y)
//   STEM-unscaled-draco.glb                           (negative control: the scene unit taken for metres)
// and prints each file's size. Exit status 1 with a message on any error.
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "analysis/mesh/scene_triangles.hpp"
#include "analysis/tessellation/tessellate_to_deviation.hpp"
#include "core/length_unit.hpp"
#include "formats/common/file_io.hpp"
#include "formats/gltf/glb_writer.hpp"
#include "formats/stl/stl_writer.hpp"
#include "formats/vrml/vrml_reader.hpp"

using namespace cadnurbs;

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: gltf_sample_files IN DEVIATION OUT_DIR STEM\n");
    return 2;
  }
  try {
    const Scene meshes = tessellate_to_deviation(read_vrml(argv[1]), std::stod(argv[2]));
    const std::filesystem::path out = argv[3];
    std::filesystem::create_directories(out);
    const std::string stem = argv[4];
    const auto write = [&](const std::string& name, const std::string& bytes) {
      write_file_atomically((out / (stem + name)).string(), bytes);
      std::printf("%s%s %zu bytes\n", stem.c_str(), name.c_str(), bytes.size());
    };
    for (const auto& [name, compression] : {std::pair{"none", GlbCompression::none},
                                            std::pair{"draco", GlbCompression::draco},
                                            std::pair{"meshopt", GlbCompression::meshopt}}) {
      GlbReport report;
      write(std::string("-") + name + ".glb", write_glb(meshes, {.compression = compression}, &report));
      std::printf("  %ld vertices, %ld triangles, %ld primitives, max position error %.3g %s\n", report.vertices,
                  report.triangles, report.primitives, report.max_position_error, meshes.unit.name.c_str());
    }
    write("-mesh.stl", format_stl(scene_triangles(in_unit(meshes, *length_unit_named("mm"))), StlEncoding::binary, stem));

    Scene mirrored = meshes;
    mirrored.root.transform = Eigen::Scaling(1.0, -1.0, 1.0) * mirrored.root.transform;
    write("-mirrored-meshopt.glb", write_glb(mirrored, {.compression = GlbCompression::meshopt}));
    Scene unscaled = meshes;
    unscaled.unit = *length_unit_named("m");
    write("-unscaled-draco.glb", write_glb(unscaled, {.compression = GlbCompression::draco}));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "gltf_sample_files: %s\n", e.what());
    return 1;
  }
  return 0;
}
