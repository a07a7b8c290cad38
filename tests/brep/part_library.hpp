#pragma once
// The 20 parts of the real part library (Debian's kicad-packages3d, fetched by
// scripts/fetch-part-library.sh; the ctest fixture library_fetch runs it first) that the library tests
// use: a spread over the nine families, fixed so that results compare across runs.
#include <string>
#include <vector>

#include "core/scene.hpp"

namespace cadnurbs::test {

// "FAMILY/NAME" of each part.
const std::vector<std::string>& library_parts();

// The part's file with extension `ext` (".step" or ".wrl", KiCad's shipped mesh) in the cache where
// scripts/fetch-part-library.sh puts the library (its own default, or CADNURBS_CACHE).
std::string library_file(const std::string& part, const std::string& ext);

// The part's STEP file read (read_step's scene); throws std::runtime_error naming the file when the
// library has not been fetched.
Scene read_library_step(const std::string& part);

// NAME of "FAMILY/NAME".
std::string library_part_name(const std::string& part);

}  // namespace cadnurbs::test
