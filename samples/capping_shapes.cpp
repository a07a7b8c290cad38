#include "samples/capping_shapes.hpp"

#include <stdexcept>

namespace cadnurbs {

namespace {
struct BundledShape {
  const char* name;
  const char* path_file;
  const char* profile_file;
};
constexpr BundledShape kShapes[] = {
    {"capping-90", "capping-90-path.txt", "handrail-profile.txt"},
    {"capping-end", "capping-end-path.txt", "handrail-profile.txt"},
    {"capping-post", "capping-post-path.txt", "post-profile.txt"},
    // The 90-degree corner with a moulded rail, a part as detailed as the thesis's (seed 001, 6.1).
    {"capping-moulded", "capping-90-path.txt", "moulded-profile.txt"},
};
}  // namespace

std::vector<std::string> capping_shape_names() {
  std::vector<std::string> names;
  for (const auto& s : kShapes) names.emplace_back(s.name);
  return names;
}

CappingDefinition bundled_capping(const std::string& name) {
  for (const auto& s : kShapes)
    if (name == s.name) {
      const auto& files = embedded_shape_files();
      return parse_capping(name, files.at(s.path_file), s.path_file, files.at(s.profile_file), s.profile_file);
    }
  std::string known;
  for (const auto& n : capping_shape_names()) known += (known.empty() ? "" : ", ") + n;
  throw std::runtime_error("unknown capping shape '" + name + "' (known: " + known + ")");
}

}  // namespace cadnurbs
