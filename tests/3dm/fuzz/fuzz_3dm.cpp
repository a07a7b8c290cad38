// libFuzzer target over the .3dm reader: any byte string goes to parse_3dm, which must either return or
// throw ArchiveError / FileError (what it promises for a bad file). Anything else (a crash, a sanitizer
// report, another exception, an input slower than -timeout, memory past -rss_limit_mb / -malloc_limit_mb)
// is a finding.
//
// Built with clang++ -fsanitize=fuzzer,address,undefined by tests/3dm/fuzz/CMakeLists.txt and run for a
// bounded time by tests/3dm/fuzz/run_fuzz.sh (ctest: 3dm.fuzz).
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
