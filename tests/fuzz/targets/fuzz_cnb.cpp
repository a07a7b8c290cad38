// libFuzzer target over the .cnb reader (docs/cnb.md): every byte string goes to read_cnb, which must
// return or throw FileError (it promises never to allocate more than the remaining bytes can hold).
// Anything else (a crash, a sanitizer report, another exception, a slow input, memory past the runner's
// limits) is a finding. Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.cnb).
#include <cstddef>
#include <cstdint>
#include <string>

#include "formats/cnb/cnb_reader.hpp"
#include "formats/common/file_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    (void)cadnurbs::read_cnb(bytes, "fuzz.cnb");
  } catch (const cadnurbs::FileError&) {
  }
  return 0;
}
