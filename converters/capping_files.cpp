#include "converters/capping_files.hpp"

#include <filesystem>

#include "converters/file_formats.hpp"
#include "formats/common/file_io.hpp"

namespace cadnurbs {

std::vector<std::string> capping_extensions() {
  std::vector<std::string> extensions;
  for (const auto& format : file_formats())
    if (format.in_samples && format.write) extensions.push_back(format.extensions.front());
  return extensions;
}

void write_capping(const CappingDefinition& capping, const std::string& path, double max_chord_deviation,
                   bool with_lids) {
  Scene scene = capping_nurbs(capping);
  if (!with_lids) scene.root.shapes.resize(1);  // the body comes first
  if (output_format(path).meshes_only) scene.root.shapes = {{capping.name, capping_mesh(capping, max_chord_deviation), std::nullopt}};
  SceneWriteOptions options;
  options.title = capping.name;
  write_scene(path, scene, options);
}

std::vector<std::string> write_capping_set(const CappingDefinition& capping, const std::string& dir,
                                           double max_chord_deviation) {
  std::filesystem::create_directories(dir);
  std::vector<std::string> written;
  for (const auto& ext : capping_extensions()) {
    const std::string path = (std::filesystem::path(dir) / (capping.name + ext)).string();
    write_capping(capping, path, max_chord_deviation);
    written.push_back(path);
  }
  return written;
}

}  // namespace cadnurbs
