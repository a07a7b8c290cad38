// libFuzzer target over the .cnb reader (docs/cnb.md): every byte string goes to read_cnb twice, as it
// is and with its header made right (version 1: the coded size and the CRC-32; versions 2 to 5: the CRC-32). Most mutations only break the CRC, which the
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

// `bytes` with a version 1 header's coded size (offset 10) and CRC-32 (offset 14, over bytes 0-13 and the
// coded bytes) set to agree with what follows the 18-byte header.
std::string with_version_1_header_made_right(std::string bytes) {
  const auto coded = static_cast<std::uint32_t>(bytes.size() - 18);
  for (int k = 0; k < 4; ++k) bytes[10 + k] = static_cast<char>(coded >> (8 * k));
  uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(bytes.data()), 14);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + 18), static_cast<uInt>(coded));
  for (int k = 0; k < 4; ++k) bytes[14 + k] = static_cast<char>(crc >> (8 * k));
  return bytes;
}

// `bytes` with a version 2 to 5 header's CRC-32 (after the payload size's varuint at byte 6, over all before
// it and the coded bytes after it) set to agree; unchanged when the header does not fit.
std::string with_version_2_header_made_right(std::string bytes) {
  size_t at = 6;
  while (at < bytes.size() && at < 11 && (static_cast<std::uint8_t>(bytes[at]) & 0x80)) ++at;
  const size_t crc_at = at + 1;
  if (crc_at + 4 > bytes.size()) return bytes;
  uLong crc = crc32(0L, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(crc_at));
  crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + crc_at + 4), static_cast<uInt>(bytes.size() - crc_at - 4));
  for (int k = 0; k < 4; ++k) bytes[crc_at + k] = static_cast<char>(crc >> (8 * k));
  return bytes;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  read(bytes);
  if (size > 4 && bytes[4] == 1 && size >= 18) read(with_version_1_header_made_right(bytes));
  if (size > 4 && (bytes[4] >= 2 && bytes[4] <= 5)) read(with_version_2_header_made_right(bytes));
  return 0;
}
