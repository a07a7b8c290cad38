#pragma once
// Reading the openNURBS binary archive a .3dm file is: little-endian primitives inside nested chunks.
// A chunk is a typecode (uint32) and a value (int32 in archive versions 1-4, int64 from 50 on). With
// TCODE_SHORT in the typecode the value is the data and there is no body; otherwise the value is the
// length of the body that follows, and with TCODE_CRC set the body's last 4 bytes are the CRC-32 (zlib's)
// of the bytes before them. Facts from openNURBS's opennurbs_archive.cpp and opennurbs_3dm.h.
//
// Every read is bounded by the innermost open chunk (and the file): a length or count that would read past
// it is refused before anything is allocated, so no input can make the reader allocate more than the
// file's size or loop without consuming bytes.
#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "formats/common/file_io.hpp"

namespace cadnurbs::rhino {

// A .3dm file that cannot be read; what() is one line:
// "<file>: chunk 0x<typecode, 8 hex digits> at offset <byte offset of its header>: <reason>"
// (or "<file>: offset <n>: <reason>" outside any chunk).
class ArchiveError : public FileError {
 public:
  using FileError::FileError;
};

// A class id as the file stores it: Data1 (uint32), Data2, Data3 (uint16), Data4[8], little-endian.
struct Uuid {
  std::array<std::uint8_t, 16> bytes{};
  bool operator==(const Uuid&) const = default;
  // "4ED7D4DD-E947-11D3-BFE5-0010830122F0" (upper case), the form openNURBS's sources write.
  std::string text() const;
};
// Parses the text form (either case). Throws std::invalid_argument on anything else.
Uuid uuid_from_text(std::string_view text);

struct ChunkHeader {
  std::uint32_t typecode = 0;
  std::int64_t value = 0;       // short chunk: the data; otherwise the body's length in bytes
  std::size_t offset = 0;       // of the typecode's first byte in the file
  std::size_t body_begin = 0;   // first byte after the header
  std::size_t body_end = 0;     // body_begin + value (body_begin for a short chunk)
  bool is_short() const { return (typecode & 0x80000000u) != 0; }
  bool has_crc() const { return !is_short() && (typecode & 0x8000u) != 0; }
};

class ArchiveReader {
 public:
  // `bytes` must outlive the reader. `archive_version` is the start section's (1..5, 50, 60, 70, 80); it
  // fixes the chunk length's size. Reading starts at `offset`.
  ArchiveReader(std::string_view bytes, std::string name_for_errors, int archive_version, std::size_t offset = 0);

  int archive_version() const { return version_; }
  const std::string& name() const { return name_; }
  std::size_t offset() const { return at_; }
  std::size_t bytes_left() const;  // to the end of the innermost open chunk (or the file)

  // Primitives. Each throws ArchiveError ("... needs N bytes, M left") when it would pass the limit.
  std::uint8_t u8();
  bool boolean();  // one byte; any non-zero is true
  std::int16_t i16();
  std::uint16_t u16();
  std::int32_t i32();
  std::uint32_t u32();
  std::int64_t i64();
  double f64();
  Uuid uuid();
  Eigen::Vector2d point2();
  Eigen::Vector3d point3();
  std::string_view raw(std::size_t n);  // n bytes, in place
  void skip(std::size_t n);
  // ON_String: int32 length counting a terminating zero, then that many bytes; returned without the zero.
  std::string string();
  // ON_wString: int32 length counting a terminating zero, then UTF-16 code units; returned as UTF-8.
  std::string wide_string();
  // An int32 element count for an array of `element_size`-byte elements that follows; refused when
  // negative or when count * element_size > bytes_left() (checked before the caller allocates).
  std::size_t count(std::size_t element_size);
  std::vector<double> doubles(std::size_t n);

  // Chunks. begin_chunk reads a header and, unless short, makes its end the limit until end_chunk.
  // Refused: a body longer than what is left of the enclosing chunk or file; a length < 0.
  // A short chunk is complete once begun: it opens nothing, so it takes no end_chunk. A CRC chunk's CRC
  // covers its own bytes only, not the chunks nested in it: step over a nested chunk with
  // begin_chunk/end_chunk, never with skip(), or its parent's CRC check fails.
  ChunkHeader begin_chunk();
  // The same, refusing ("expected chunk 0x..., found 0x...") any other typecode.
  ChunkHeader begin_chunk(std::uint32_t expected_typecode);
  // openNURBS's BeginRead3dmChunk(tcode, &major, &minor): the chunk, then two int32 versions in its body.
  std::pair<int, int> begin_versioned_chunk(std::uint32_t expected_typecode);
  // Leaves the innermost open chunk: checks its CRC when it has one ("CRC mismatch"), then moves to its
  // end whatever was left unread (so readers may ignore trailing data newer versions add). As in
  // openNURBS, the CRC is checked only when the chunk's data was read to its end (what was skipped may
  // hold nested chunks, which the CRC leaves out).
  void end_chunk();
  // The header at the current offset, without moving; refused like begin_chunk.
  ChunkHeader peek_chunk() const;
  // The one-byte chunk version openNURBS objects write first in their data: major * 16 + minor.
  std::pair<int, int> chunk_version();
  int open_chunks() const { return static_cast<int>(open_.size()); }

  // Throws ArchiveError naming the innermost open chunk (typecode and header offset) and `reason`.
  [[noreturn]] void fail(const std::string& reason) const;

 private:
  std::size_t limit() const;
  void need(std::size_t n, const char* what) const;
  ChunkHeader read_header_at(std::size_t at) const;

  std::string_view bytes_;
  std::string name_;
  int version_ = 0;
  std::size_t at_ = 0;
  std::vector<ChunkHeader> open_;
  // Per open chunk: the CRC-32 of its own bytes in [body_begin, crc_from) (nested chunks left out).
  struct RunningCrc {
    std::uint32_t crc = 0;
    std::size_t from = 0;
  };
  std::vector<RunningCrc> crc_;
};

}  // namespace cadnurbs::rhino
