// libFuzzer target over the VRML/X3D reader, seeded with X3D classic files (.x3dv) so that the mutations
// exercise that encoding's parser: parse_vrml tells the encodings (and gzip) apart by content, as it does
// for a file the user gives. It must return or throw FileError, and what it reads must rewrite and read again
// (vrml_fuzz_input.hpp); anything else (a crash, a sanitizer
// report, another exception, a slow input, memory past the runner's limits) is a finding.
// Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.x3d_classic).
#include <cstddef>
#include <cstdint>
#include <string>

#include "tests/fuzz/targets/vrml_fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  fuzz_vrml_input(bytes, "fuzz.x3dv");
  return 0;
}
