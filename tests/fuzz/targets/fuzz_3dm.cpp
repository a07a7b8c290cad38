// libFuzzer target over the .3dm reader: any byte string goes to parse_3dm, which must either return or
// throw ArchiveError / FileError (what it promises for a bad file). Anything else (a crash, a sanitizer
// report, another exception, a slow input, memory past the runner's limits) is a finding.
// Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.3dm).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "formats/3dm/rhino_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cadnurbs::rhino::parse_3dm(bytes, "fuzz.3dm");
  } catch (const cadnurbs::FileError&) {
    // ArchiveError is a FileError: the reader refused the input, as it should.
  }
  return 0;
}
