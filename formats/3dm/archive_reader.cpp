#include "formats/3dm/archive_reader.hpp"

#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {
namespace {

std::string chunk_context(const std::string& name, std::uint32_t typecode, std::size_t offset) {
  char text[64];
  std::snprintf(text, sizeof text, ": chunk 0x%08X at offset %zu: ", typecode, offset);
  return name + text;
}

[[noreturn]] void fail_in_chunk(const std::string& name, std::uint32_t typecode, std::size_t offset,
                                const std::string& reason) {
  throw ArchiveError(chunk_context(name, typecode, offset) + reason);
}

template <class T>
T load_le(const char* p) {
  // The archive is little-endian; so are the machines cadnurbs builds on (checked below).
  T value;
  std::memcpy(&value, p, sizeof value);
  return value;
}
static_assert(std::endian::native == std::endian::little, "the .3dm reader assumes a little-endian host");

// 4-byte chunk values of short chunks are signed except for these (ON_IsUnsignedChunkTypecode).
bool short_value_is_unsigned(std::uint32_t typecode) {
  return typecode == tcode::kRgb || typecode == tcode::kRgbDisplay ||
         typecode == tcode::kPropertiesOpennurbsVersion || typecode == tcode::kObjectRecordType;
}

std::uint32_t crc32_of(std::uint32_t crc, std::string_view bytes) {
  // zlib takes a uInt length; feed large spans in pieces.
  while (!bytes.empty()) {
    const std::size_t n = std::min<std::size_t>(bytes.size(), 1u << 30);
    crc = static_cast<std::uint32_t>(
        ::crc32(crc, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(n)));
    bytes.remove_prefix(n);
  }
  return crc;
}

void append_utf8(std::string& out, std::uint32_t code_point) {
  if (code_point < 0x80) {
    out += static_cast<char>(code_point);
  } else if (code_point < 0x800) {
    out += static_cast<char>(0xC0 | (code_point >> 6));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else if (code_point < 0x10000) {
    out += static_cast<char>(0xE0 | (code_point >> 12));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code_point >> 18));
    out += static_cast<char>(0x80 | ((code_point >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code_point >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code_point & 0x3F));
  }
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// The text form lists Data1, Data2, Data3 as numbers (most significant digit first) and Data4 as bytes;
// the file stores the numbers little-endian. For each text byte position, the byte index in the file.
constexpr std::array<int, 16> kTextOrder = {3, 2, 1, 0, 5, 4, 7, 6, 8, 9, 10, 11, 12, 13, 14, 15};

}  // namespace

std::string Uuid::text() const {
  static const char* digits = "0123456789ABCDEF";
  std::string out;
  for (int i = 0; i < 16; ++i) {
    if (i == 4 || i == 6 || i == 8 || i == 10) out += '-';
    const std::uint8_t b = bytes[static_cast<std::size_t>(kTextOrder[static_cast<std::size_t>(i)])];
    out += digits[b >> 4];
    out += digits[b & 0xF];
  }
  return out;
}

Uuid uuid_from_text(std::string_view text) {
  Uuid id;
  if (text.size() != 36) throw std::invalid_argument("not a uuid: " + std::string(text));
  int byte = 0;
  for (std::size_t i = 0; i < text.size();) {
    if (i == 8 || i == 13 || i == 18 || i == 23) {
      if (text[i] != '-') throw std::invalid_argument("not a uuid: " + std::string(text));
      ++i;
      continue;
    }
    const int high = hex_digit(text[i]), low = hex_digit(text[i + 1]);
    if (high < 0 || low < 0) throw std::invalid_argument("not a uuid: " + std::string(text));
    id.bytes[static_cast<std::size_t>(kTextOrder[static_cast<std::size_t>(byte++)])] =
        static_cast<std::uint8_t>(high * 16 + low);
    i += 2;
  }
  return id;
}

ArchiveReader::ArchiveReader(std::string_view bytes, std::string name_for_errors, int archive_version,
                             std::size_t offset)
    : bytes_(bytes), name_(std::move(name_for_errors)), version_(archive_version), at_(offset) {
  if (at_ > bytes_.size()) fail("start offset past the end of the file");
}

std::size_t ArchiveReader::limit() const {
  if (open_.empty()) return bytes_.size();
  const ChunkHeader& c = open_.back();
  return c.has_crc() ? c.body_end - 4 : c.body_end;
}

std::size_t ArchiveReader::bytes_left() const { return limit() - at_; }

void ArchiveReader::fail(const std::string& reason) const {
  if (open_.empty()) throw ArchiveError(name_ + ": offset " + std::to_string(at_) + ": " + reason);
  fail_in_chunk(name_, open_.back().typecode, open_.back().offset, reason);
}

void ArchiveReader::need(std::size_t n, const char* what) const {
  if (n > bytes_left())
    fail(std::string(what) + " needs " + std::to_string(n) + " bytes, " + std::to_string(bytes_left()) + " left");
}

std::uint8_t ArchiveReader::u8() {
  need(1, "byte");
  return static_cast<std::uint8_t>(bytes_[at_++]);
}
bool ArchiveReader::boolean() { return u8() != 0; }

#define CADNURBS_RHINO_PRIMITIVE(NAME, TYPE, WHAT)  \
  TYPE ArchiveReader::NAME() {                      \
    need(sizeof(TYPE), WHAT);                       \
    const TYPE value = load_le<TYPE>(bytes_.data() + at_); \
    at_ += sizeof(TYPE);                            \
    return value;                                   \
  }
CADNURBS_RHINO_PRIMITIVE(i16, std::int16_t, "int16")
CADNURBS_RHINO_PRIMITIVE(u16, std::uint16_t, "uint16")
CADNURBS_RHINO_PRIMITIVE(i32, std::int32_t, "int32")
CADNURBS_RHINO_PRIMITIVE(u32, std::uint32_t, "uint32")
CADNURBS_RHINO_PRIMITIVE(i64, std::int64_t, "int64")
CADNURBS_RHINO_PRIMITIVE(f64, double, "double")
#undef CADNURBS_RHINO_PRIMITIVE

Uuid ArchiveReader::uuid() {
  need(16, "uuid");
  Uuid id;
  std::memcpy(id.bytes.data(), bytes_.data() + at_, 16);
  at_ += 16;
  return id;
}

Eigen::Vector2d ArchiveReader::point2() {
  need(16, "2D point");
  const double x = f64();
  return {x, f64()};
}

Eigen::Vector3d ArchiveReader::point3() {
  need(24, "3D point");
  const double x = f64();
  const double y = f64();
  return {x, y, f64()};
}

std::string_view ArchiveReader::raw(std::size_t n) {
  need(n, "data");
  const std::string_view out = bytes_.substr(at_, n);
  at_ += n;
  return out;
}

void ArchiveReader::skip(std::size_t n) {
  need(n, "skip");
  at_ += n;
}

std::string ArchiveReader::string() {
  const std::uint32_t n = u32();  // elements including the terminating zero
  need(n, "string");
  std::string out(bytes_.substr(at_, n));
  at_ += n;
  const std::size_t zero = out.find('\0');
  if (zero != std::string::npos) out.resize(zero);
  return out;
}

std::string ArchiveReader::wide_string() {
  const std::uint32_t n = u32();  // UTF-16 code units including the terminating zero
  if (n > bytes_left() / 2) need(std::size_t{n} * 2, "wide string");
  std::string out;
  for (std::uint32_t i = 0; i < n; ++i) {
    std::uint32_t unit = u16();
    if (unit == 0) {  // the terminator (and anything after a stray zero) is not text
      at_ += std::size_t{n - 1 - i} * 2;
      break;
    }
    if (unit >= 0xD800 && unit < 0xDC00 && i + 1 < n) {
      const std::uint16_t next = load_le<std::uint16_t>(bytes_.data() + at_);
      if (next >= 0xDC00 && next < 0xE000) {
        at_ += 2;
        ++i;
        unit = 0x10000 + ((unit - 0xD800) << 10) + (next - 0xDC00u);
      } else {
        unit = 0xFFFD;
      }
    } else if (unit >= 0xD800 && unit < 0xE000) {
      unit = 0xFFFD;  // an unpaired surrogate
    }
    append_utf8(out, unit);
  }
  return out;
}

std::size_t ArchiveReader::count(std::size_t element_size) {
  const std::int32_t n = i32();
  if (n < 0) fail("negative count " + std::to_string(n));
  if (element_size > 0 && static_cast<std::size_t>(n) > bytes_left() / element_size)
    fail("count " + std::to_string(n) + " of " + std::to_string(element_size) + "-byte elements needs " +
         std::to_string(static_cast<std::size_t>(n) * element_size) + " bytes, " + std::to_string(bytes_left()) +
         " left");
  return static_cast<std::size_t>(n);
}

std::vector<double> ArchiveReader::doubles(std::size_t n) {
  if (n > bytes_left() / sizeof(double))
    fail(std::to_string(n) + " doubles need " + std::to_string(n) + " * 8 bytes, " + std::to_string(bytes_left()) +
         " left");
  std::vector<double> out(n);
  if (n > 0) std::memcpy(out.data(), bytes_.data() + at_, n * sizeof(double));
  at_ += n * sizeof(double);
  return out;
}

ChunkHeader ArchiveReader::read_header_at(std::size_t at) const {
  const std::size_t end = limit();
  const std::size_t value_size = version_ < 50 ? 4 : 8;
  const std::size_t left = at <= end ? end - at : 0;
  if (left < 4 + value_size) {
    const std::string reason = "chunk header needs " + std::to_string(4 + value_size) + " bytes, " +
                               std::to_string(left) + " left";
    if (open_.empty()) throw ArchiveError(name_ + ": offset " + std::to_string(at) + ": " + reason);
    fail_in_chunk(name_, open_.back().typecode, open_.back().offset, reason);
  }
  ChunkHeader h;
  h.offset = at;
  h.typecode = load_le<std::uint32_t>(bytes_.data() + at);
  if (value_size == 8) {
    h.value = load_le<std::int64_t>(bytes_.data() + at + 4);
  } else if (h.is_short() && !short_value_is_unsigned(h.typecode)) {
    h.value = load_le<std::int32_t>(bytes_.data() + at + 4);
  } else {
    h.value = load_le<std::uint32_t>(bytes_.data() + at + 4);
  }
  h.body_begin = at + 4 + value_size;
  h.body_end = h.body_begin;
  if (h.is_short()) return h;
  const std::size_t room = end - h.body_begin;
  if (h.value < 0) fail_in_chunk(name_, h.typecode, at, "negative length " + std::to_string(h.value));
  if (static_cast<std::uint64_t>(h.value) > room)
    fail_in_chunk(name_, h.typecode, at,
                  "length " + std::to_string(h.value) + " runs past the end of the " +
                      (open_.empty() ? std::string("file") : "enclosing chunk") + " (" + std::to_string(room) +
                      " bytes left)");
  if (h.has_crc() && h.value < 4)
    fail_in_chunk(name_, h.typecode, at, "length " + std::to_string(h.value) + " leaves no room for its CRC");
  h.body_end = h.body_begin + static_cast<std::size_t>(h.value);
  return h;
}

ChunkHeader ArchiveReader::peek_chunk() const { return read_header_at(at_); }

ChunkHeader ArchiveReader::begin_chunk() {
  const ChunkHeader h = read_header_at(at_);
  if (!crc_.empty()) {
    // The parent's CRC covers its own bytes up to this header; the nested chunk is left out.
    RunningCrc& parent = crc_.back();
    parent.crc = crc32_of(parent.crc, bytes_.substr(parent.from, h.offset - parent.from));
  }
  at_ = h.body_begin;
  if (!h.is_short()) {
    open_.push_back(h);
    crc_.push_back({static_cast<std::uint32_t>(::crc32(0, Z_NULL, 0)), h.body_begin});
  } else if (!crc_.empty()) {
    crc_.back().from = at_;
  }
  return h;
}

ChunkHeader ArchiveReader::begin_chunk(std::uint32_t expected_typecode) {
  const ChunkHeader h = peek_chunk();
  if (h.typecode != expected_typecode) {
    char text[64];
    std::snprintf(text, sizeof text, "expected chunk 0x%08X, found 0x%08X", expected_typecode, h.typecode);
    fail_in_chunk(name_, h.typecode, h.offset, text);
  }
  return begin_chunk();
}

std::pair<int, int> ArchiveReader::begin_versioned_chunk(std::uint32_t expected_typecode) {
  begin_chunk(expected_typecode);
  const int major = i32();
  return {major, i32()};
}

void ArchiveReader::end_chunk() {
  if (open_.empty()) fail("end of chunk with no chunk open");
  const ChunkHeader& c = open_.back();
  if (c.has_crc() && at_ == c.body_end - 4) {
    const RunningCrc& running = crc_.back();
    const std::uint32_t computed = crc32_of(running.crc, bytes_.substr(running.from, at_ - running.from));
    const std::uint32_t stored = load_le<std::uint32_t>(bytes_.data() + at_);
    if (computed != stored) {
      char text[64];
      std::snprintf(text, sizeof text, "CRC mismatch (stored 0x%08X, computed 0x%08X)", stored, computed);
      fail(text);
    }
  }
  at_ = c.body_end;
  open_.pop_back();
  crc_.pop_back();
  if (!crc_.empty()) crc_.back().from = at_;
}

std::pair<int, int> ArchiveReader::chunk_version() {
  const std::uint8_t v = u8();
  return {v >> 4, v & 0xF};
}

}  // namespace cadnurbs::rhino
