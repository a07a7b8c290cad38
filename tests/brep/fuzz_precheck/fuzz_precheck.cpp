// libFuzzer target over the STEP and IGES pre-checks: every byte string goes to both, which must either
// return or throw FileError (what they promise for a bad file). Anything else (a crash, a sanitizer
// report, another exception, an input slower than -timeout, memory past -rss_limit_mb) is a finding.
//
// Built with clang++ -fsanitize=fuzzer,address,undefined by tests/brep/fuzz_precheck/CMakeLists.txt and
// run for a bounded time by tests/brep/fuzz_precheck/run_fuzz.sh (ctest: brep.fuzz_precheck).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/common/file_io.hpp"
#include "formats/iges/iges_precheck.hpp"
#include "formats/step/step_precheck.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cadnurbs::precheck_step(bytes, "fuzz.step");
  } catch (const cadnurbs::FileError&) {
  }
  try {
    (void)cadnurbs::precheck_iges(bytes, "fuzz.igs");
  } catch (const cadnurbs::FileError&) {
  }
  return 0;
}
