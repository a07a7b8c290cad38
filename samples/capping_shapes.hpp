#pragma once
// The bundled capping shapes: name -> path and profile files from samples/shapes/ (embedded).
#include <map>
#include <string>
#include <vector>

#include "samples/capping.hpp"

namespace cadnurbs {

// File name -> text of every file in samples/shapes/ the build embeds.
const std::map<std::string, std::string>& embedded_shape_files();

// Names of the bundled shapes ("capping-90", "capping-end", "capping-post", "capping-moulded").
std::vector<std::string> capping_shape_names();

// The bundled shape `name`, or a std::runtime_error listing the known names.
CappingDefinition bundled_capping(const std::string& name);

}  // namespace cadnurbs
