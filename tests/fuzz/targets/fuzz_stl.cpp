// libFuzzer target over the STL reader (ASCII and binary, told apart by content): every byte string goes
// to parse_stl, as a soup and with equal corners merged (the two ways cadnurbs reads STL). It must return
// or throw FileError; anything else (a crash, a sanitizer report, another exception, a slow input, memory
// past the runner's limits) is a finding. Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.stl).
#include <cstddef>
#include <cstdint>
#include <string>

#include "formats/common/file_io.hpp"
#include "formats/stl/stl_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cadnurbs::parse_stl(bytes, "fuzz.stl");
  } catch (const cadnurbs::FileError&) {
  }
  try {
    (void)cadnurbs::parse_stl(bytes, "fuzz.stl", {.facet_normals = false, .merge_equal_points = true});
  } catch (const cadnurbs::FileError&) {
  }
  return 0;
}
