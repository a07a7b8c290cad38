#pragma once
// gzip'd files (RFC 1952) through zlib: VRML and X3D have gzip'd forms (.wrz, .wrl.gz, .x3dvz, .x3dz)
// that browsers read, and gzip is how the project measures compressed sizes.
#include <cstddef>
#include <string>

namespace cadnurbs {

// True when `bytes` start with the gzip magic number (1f 8b).
bool is_gzip(const std::string& bytes);

// `bytes` as one gzip member, at zlib's best compression (level 9), with no file name and a zero time
// stamp, so that the same input always gives the same bytes.
std::string gzip(const std::string& bytes);

// The content of gzip'd `bytes` (concatenated members included). Throws FileError "<name>: <reason>" for
// a damaged or truncated stream, and when the content would exceed `max_size` bytes (a small file can
// claim gigabytes).
std::string gunzip(const std::string& bytes, const std::string& name, std::size_t max_size = std::size_t(1) << 31);

}  // namespace cadnurbs
