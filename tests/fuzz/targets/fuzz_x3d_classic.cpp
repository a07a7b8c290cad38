// libFuzzer target over the VRML/X3D reader, seeded with X3D classic files (.x3dv) so that the mutations
// exercise that encoding's parser: parse_vrml tells the encodings (and gzip) apart by content, as it does
// for a file the user gives. It must return or throw FileError; anything else (a crash, a sanitizer
// report, another exception, a slow input, memory past the runner's limits) is a finding.
// Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.x3d_classic).
#include <cstddef>
#include <cstdint>
#include <string>

#include "formats/common/file_io.hpp"
#include "formats/vrml/vrml_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cadnurbs::parse_vrml(bytes, "fuzz.x3dv");
  } catch (const cadnurbs::FileError&) {
  }
  return 0;
}
