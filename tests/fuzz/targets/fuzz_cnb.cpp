// libFuzzer target over the .cnb reader (docs/cnb.md): every byte string goes to read_cnb twice, as it
// is and with its header's coded size and CRC-32 made right. Most mutations only break the CRC, which the
// reader checks before it decodes anything; the second reading takes them past it, to the decoder.
// read_cnb must return or throw FileError (it promises never to allocate more than the remaining bytes can
// hold). Anything else (a crash, a sanitizer report, another exception, a slow input, memory past the
// runner's limits) is a finding. Run by tests/fuzz/run_fuzz.sh (ctest: fuzz.cnb).
#include <zlib.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "formats/cnb/cnb_reader.hpp"
#include "formats/common/file_io.hpp"

namespace {

void read(const std::string& bytes) {
  try {
    (void)cadnurbs::read_cnb(bytes, "fuzz.cnb");
  } catch (const cadnurbs::FileError&) {
  }
}

// `bytes` with the header's coded size (offset 10) and CRC-32 (offset 14, over bytes 0-13 and the coded
// bytes) set to agree with what follows the 18-byte header.
std::string with_header_made_right(std::string bytes) {
  const auto coded = static_cast<std::uint32_t>(bytes.size() - 18);
  for (int k = 0; k < 4; ++k) bytes[10 + k] = static_cast<char>(coded >> (8 * k));
  uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(bytes.data()), 14);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + 18), static_cast<uInt>(coded));
  for (int k = 0; k < 4; ++k) bytes[14 + k] = static_cast<char>(crc >> (8 * k));
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read(bytes);
  if (size >= 18) read(with_header_made_right(bytes));
  return 0;
}
