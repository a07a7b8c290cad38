#include "formats/3dm/compressed_buffer.hpp"

#include <zlib.h>

#include <algorithm>

#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {
namespace {

// zlib's deflate never compresses better than about 1032:1 (RFC 1950/1951 limits); a declared size beyond
// this multiple of the stored stream cannot be genuine.
constexpr std::size_t kMaxDeflateRatio = 1032;

std::string inflate_stream(ArchiveReader& reader, std::string_view stream, std::size_t size, const std::string& what) {
  z_stream z{};
  if (inflateInit(&z) != Z_OK) reader.fail(what + ": zlib cannot start inflating");
  std::string out;
  // Grow with what the stream really yields rather than trusting the declared size up front.
  out.reserve(std::min<std::size_t>(size, stream.size() * 8 + 4096));
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(stream.data()));
  z.avail_in = static_cast<uInt>(stream.size());
  char block[65536];
  int status = Z_OK;
  while (status == Z_OK) {
    z.next_out = reinterpret_cast<Bytef*>(block);
    z.avail_out = sizeof block;
    status = inflate(&z, Z_NO_FLUSH);
    const std::size_t produced = sizeof block - z.avail_out;
    if (out.size() + produced > size) {
      inflateEnd(&z);
      reader.fail(what + ": inflates to more than its declared " + std::to_string(size) + " bytes");
    }
    out.append(block, produced);
    if (status == Z_BUF_ERROR && produced > 0) status = Z_OK;  // more output room needed, not an error
  }
  inflateEnd(&z);
  if (status != Z_STREAM_END) reader.fail(what + ": corrupt zlib stream (zlib status " + std::to_string(status) + ")");
  if (out.size() != size)
    reader.fail(what + ": inflates to " + std::to_string(out.size()) + " bytes, declared " + std::to_string(size));
  return out;
}

}  // namespace

std::string read_compressed_buffer(ArchiveReader& reader, std::size_t expected_size, const std::string& what) {
  const std::uint32_t size = reader.u32();
  if (size == 0) return {};
  if (size != expected_size)
    reader.fail(what + ": declared size " + std::to_string(size) + " bytes, expected " + std::to_string(expected_size));
  const std::uint32_t crc = reader.u32();
  const std::uint8_t method = reader.u8();
  std::string out;
  if (method == 0) {
    out = std::string(reader.raw(size));
  } else if (method == 1) {
    reader.begin_chunk(tcode::kAnonymousChunk);
    const std::string_view stream = reader.raw(reader.bytes_left());
    if (size / kMaxDeflateRatio > stream.size())
      reader.fail(what + ": " + std::to_string(stream.size()) + " compressed bytes cannot inflate to " +
                  std::to_string(size));
    out = inflate_stream(reader, stream, size, what);
    reader.end_chunk();
  } else {
    reader.fail(what + ": unknown compression method " + std::to_string(method));
  }
  const auto computed = static_cast<std::uint32_t>(::crc32(0, reinterpret_cast<const Bytef*>(out.data()), static_cast<uInt>(out.size())));
  if (computed != crc) reader.fail(what + ": CRC mismatch of the inflated bytes");
  return out;
}

void skip_compressed_buffer(ArchiveReader& reader) {
  const std::uint32_t size = reader.u32();
  if (size == 0) return;
  reader.u32();  // CRC
  const std::uint8_t method = reader.u8();
  if (method == 0) {
    reader.skip(size);
  } else if (method == 1) {
    reader.begin_chunk(tcode::kAnonymousChunk);
    reader.end_chunk();
  } else {
    reader.fail("compressed buffer: unknown compression method " + std::to_string(method));
  }
}

}  // namespace cadnurbs::rhino
