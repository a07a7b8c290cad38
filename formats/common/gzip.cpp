#include "formats/common/gzip.hpp"

#include <zlib.h>

#include <stdexcept>

#include "formats/common/file_io.hpp"

namespace cadnurbs {

namespace {

// zlib's windowBits for a gzip wrapper (RFC 1952) instead of zlib's own.
constexpr int gzip_window = 15 + 16;
constexpr std::size_t chunk = 1 << 16;

}  // namespace

bool is_gzip(const std::string& bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::string gzip(const std::string& bytes) {
  z_stream stream{};
  if (deflateInit2(&stream, Z_BEST_COMPRESSION, Z_DEFLATED, gzip_window, 9, Z_DEFAULT_STRATEGY) != Z_OK)
    throw std::runtime_error("gzip: zlib could not start");
  std::string out;
  out.resize(deflateBound(&stream, static_cast<uLong>(bytes.size())) + 32);
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  stream.next_out = reinterpret_cast<Bytef*>(out.data());
  stream.avail_out = static_cast<uInt>(out.size());
  const int status = deflate(&stream, Z_FINISH);
  const std::size_t written = stream.total_out;
  deflateEnd(&stream);
  if (status != Z_STREAM_END) throw std::runtime_error("gzip: zlib could not compress");
  out.resize(written);
  return out;
}

std::string gunzip(const std::string& bytes, const std::string& name, std::size_t max_size) {
  z_stream stream{};
  if (inflateInit2(&stream, gzip_window) != Z_OK) throw FileError(name + ": zlib could not start");
  stream.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  stream.avail_in = static_cast<uInt>(bytes.size());
  std::string out;
  int status = Z_OK;
  while (true) {
    if (out.size() >= max_size) {
      inflateEnd(&stream);
      throw FileError(name + ": gzip'd content exceeds " + std::to_string(max_size) + " bytes");
    }
    const std::size_t before = out.size();
    out.resize(before + chunk);
    stream.next_out = reinterpret_cast<Bytef*>(out.data() + before);
    stream.avail_out = static_cast<uInt>(chunk);
    status = inflate(&stream, Z_NO_FLUSH);
    out.resize(before + chunk - stream.avail_out);
    if (status == Z_STREAM_END) {
      // Another member may follow (gzip files may be concatenated).
      if (stream.avail_in == 0) break;
      if (inflateReset(&stream) != Z_OK) break;
      continue;
    }
    if (status != Z_OK) break;
    if (stream.avail_in == 0 && stream.avail_out != 0) {
      status = Z_BUF_ERROR;  // input ended inside the stream
      break;
    }
  }
  inflateEnd(&stream);
  if (status != Z_STREAM_END) throw FileError(name + ": damaged or truncated gzip data");
  if (out.size() > max_size) throw FileError(name + ": gzip'd content exceeds " + std::to_string(max_size) + " bytes");
  return out;
}

}  // namespace cadnurbs
