// libFuzzer target over the IGES pre-check (the lexical pass that runs before OpenCASCADE sees a file):
// every byte string goes to precheck_iges, which must return or throw FileError, in time linear in the
// input. Anything else (a crash, a sanitizer report, another exception, a slow input, memory past the
// runner's limits) is a finding. Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.iges_precheck).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/common/file_io.hpp"
#include "formats/iges/iges_precheck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cadnurbs::precheck_iges(bytes, "fuzz.igs");
  } catch (const cadnurbs::FileError&) {
  }
  return 0;
}
