// libFuzzer target over the STEP pre-check (the lexical pass that runs before OpenCASCADE sees a file):
// every byte string goes to precheck_step, which must return or throw FileError, in time linear in the
// input. Anything else (a crash, a sanitizer report, another exception, a slow input, memory past the
// runner's limits) is a finding. Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.step_precheck).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/common/file_io.hpp"
#include "formats/step/step_precheck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cadnurbs::precheck_step(bytes, "fuzz.step");
  } catch (const cadnurbs::FileError&) {
  }
  return 0;
}
