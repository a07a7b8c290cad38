// The archive layer on hand-built byte strings: chunk nesting, short chunks, 4- and 8-byte lengths, CRCs,
// bounds refused before allocation, strings.
#include "formats/3dm/archive_reader.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstring>

#include "formats/3dm/typecodes.hpp"

namespace cadnurbs::rhino {
namespace {

// Little-endian byte string builder; chunk() frames a body as openNURBS writes it.
struct Bytes {
  std::string s;
  template <class T>
  Bytes& put(T value) {
    char b[sizeof value];
    std::memcpy(b, &value, sizeof value);
    s.append(b, sizeof value);
    return *this;
  }
  Bytes& append(const std::string& more) {
    s += more;
    return *this;
  }
};

// A long chunk: typecode, length (4 or 8 bytes), body, and the body's CRC when the typecode has TCODE_CRC.
std::string chunk(std::uint32_t typecode, const std::string& body, int version, bool good_crc = true) {
  const bool crc = (typecode & tcode::kCrc) != 0;
  Bytes b;
  b.put(typecode);
  const std::size_t length = body.size() + (crc ? 4 : 0);
  if (version < 50) b.put(static_cast<std::uint32_t>(length));
  else b.put(static_cast<std::int64_t>(length));
  b.append(body);
  if (crc) {
    std::uint32_t c = static_cast<std::uint32_t>(
        ::crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size())));
    if (!good_crc) c ^= 1u;
    b.put(c);
  }
  return b.s;
}

std::string short_chunk(std::uint32_t typecode, std::int64_t value, int version) {
  Bytes b;
  b.put(typecode);
  if (version < 50) b.put(static_cast<std::int32_t>(value));
  else b.put(value);
  return b.s;
}

// what() of the ArchiveError `f` throws, or "no error".
template <class F>
std::string error_of(F&& f) {
  try {
    f();
  } catch (const ArchiveError& e) {
    return e.what();
  }
  return "no error";
}

TEST(ArchiveReader, ReadsNestedChunksWithFourByteLengths) {
  const int version = 4;
  const std::string inner = chunk(tcode::kAnonymousChunk, Bytes{}.put(std::int32_t{7}).put(2.5).s, version);
  const std::string outer = chunk(tcode::kObjectTable, Bytes{}.put(std::uint8_t{9}).s + inner, version);
  const std::string file = outer + short_chunk(tcode::kEndOfTable, 0, version);

  ArchiveReader r(file, "t.3dm", version);
  const ChunkHeader o = r.begin_chunk(tcode::kObjectTable);
  EXPECT_EQ(o.offset, 0u);
  EXPECT_EQ(o.body_begin, 8u);
  EXPECT_EQ(o.body_end, outer.size());
  EXPECT_EQ(r.u8(), 9);
  const ChunkHeader i = r.begin_chunk();
  EXPECT_EQ(i.typecode, tcode::kAnonymousChunk);
  EXPECT_TRUE(i.has_crc());
  EXPECT_EQ(r.open_chunks(), 2);
  EXPECT_EQ(r.bytes_left(), 12u);  // the CRC is not data
  EXPECT_EQ(r.i32(), 7);
  EXPECT_EQ(r.f64(), 2.5);
  r.end_chunk();
  r.end_chunk();
  EXPECT_EQ(r.offset(), outer.size());
  const ChunkHeader end = r.begin_chunk();
  EXPECT_TRUE(end.is_short());
  EXPECT_EQ(end.value, 0);
  EXPECT_EQ(r.open_chunks(), 0);  // a short chunk opens nothing
  EXPECT_EQ(r.offset(), file.size());
}

TEST(ArchiveReader, EightByteLengthsFromVersion50) {
  const std::string body = Bytes{}.put(std::int32_t{1}).put(std::int32_t{3}).s;
  const std::string file = chunk(tcode::kOpennurbsClassData, body, 50);
  EXPECT_EQ(file.size(), 4u + 8u + 8u + 4u);
  ArchiveReader r(file, "t.3dm", 50);
  const auto [major, minor] = r.begin_versioned_chunk(tcode::kOpennurbsClassData);
  EXPECT_EQ(major, 1);
  EXPECT_EQ(minor, 3);
  r.end_chunk();
  EXPECT_EQ(r.offset(), file.size());

  // The same bytes read as a version 4 archive: the length's upper half becomes data.
  ArchiveReader old(file, "t.3dm", 4);
  const ChunkHeader h = old.begin_chunk();
  EXPECT_EQ(h.body_begin, 8u);
}

TEST(ArchiveReader, ShortChunkValuesAreSignedUnlessTheTypecodeSaysUnsigned) {
  const std::string file =
      short_chunk(tcode::kObjectRecordEnd, -1, 4) + short_chunk(tcode::kObjectRecordType, -1, 4);
  ArchiveReader r(file, "t.3dm", 4);
  EXPECT_EQ(r.begin_chunk().value, -1);
  EXPECT_EQ(r.begin_chunk().value, 0xFFFFFFFFll);
}

TEST(ArchiveReader, EndChunkSkipsUnreadDataWithoutCheckingTheCrc) {
  const std::string body = Bytes{}.put(1.0).put(2.0).s;
  const std::string file = chunk(tcode::kAnonymousChunk, body, 60, false) + short_chunk(tcode::kEndOfTable, 0, 60);
  ArchiveReader r(file, "t.3dm", 60);
  r.begin_chunk();
  EXPECT_EQ(r.f64(), 1.0);
  r.end_chunk();  // partly read: its CRC cannot be checked (the rest may hold nested chunks)
  EXPECT_EQ(r.peek_chunk().typecode, tcode::kEndOfTable);
}

TEST(ArchiveReader, CrcMismatchIsOneLineNamingTheChunk) {
  const std::string file = chunk(tcode::kAnonymousChunk, Bytes{}.put(1.0).s, 60, false);
  ArchiveReader r(file, "bad.3dm", 60);
  r.begin_chunk();
  r.f64();
  const std::uint32_t good =
      static_cast<std::uint32_t>(::crc32(0, reinterpret_cast<const Bytef*>(file.data() + 12), 8));
  char expected[160];
  std::snprintf(expected, sizeof expected,
                "bad.3dm: chunk 0x40008000 at offset 0: CRC mismatch (stored 0x%08X, computed 0x%08X)", good ^ 1u, good);
  EXPECT_EQ(error_of([&] { r.end_chunk(); }), expected);
}

TEST(ArchiveReader, ParentCrcLeavesNestedChunksOut) {
  // openNURBS's CRC of a chunk covers only its own bytes: a record with a nested chunk between two ints.
  const int version = 60;
  const std::string nested = chunk(tcode::kAnonymousChunk, Bytes{}.put(std::int32_t{5}).s, version);
  const std::string own = Bytes{}.put(std::int32_t{1}).put(std::int32_t{2}).s;
  Bytes record;
  record.put(tcode::kObjectRecord).put(static_cast<std::int64_t>(own.size() + nested.size() + 4));
  record.append(own.substr(0, 4)).append(nested).append(own.substr(4));
  record.put(static_cast<std::uint32_t>(::crc32(0, reinterpret_cast<const Bytef*>(own.data()), 8)));
  ArchiveReader r(record.s, "t.3dm", version);
  r.begin_chunk(tcode::kObjectRecord);
  EXPECT_EQ(r.i32(), 1);
  r.begin_chunk(tcode::kAnonymousChunk);
  EXPECT_EQ(r.i32(), 5);
  r.end_chunk();
  EXPECT_EQ(r.i32(), 2);
  EXPECT_NO_THROW(r.end_chunk());
}

TEST(ArchiveReader, LengthPastTheFileIsRefusedWithOneLine) {
  Bytes b;
  b.put(std::uint32_t{0}).put(std::uint32_t{0});  // 8 bytes of something before the chunk
  b.put(tcode::kObjectTable).put(static_cast<std::int64_t>(1000000)).put(1.0);
  ArchiveReader r(b.s, "big.3dm", 70, 8);
  EXPECT_EQ(error_of([&] { r.begin_chunk(); }),
            "big.3dm: chunk 0x10000013 at offset 8: length 1000000 runs past the end of the file (8 bytes left)");
  // Inside a chunk the limit is the enclosing chunk, not the file.
  const std::string inner = Bytes{}.put(tcode::kAnonymousChunk).put(std::uint32_t{100}).s;
  const std::string file = chunk(tcode::kObjectTable, inner, 4) + std::string(200, '\0');
  ArchiveReader nested(file, "n.3dm", 4);
  nested.begin_chunk();
  EXPECT_EQ(error_of([&] { nested.begin_chunk(); }),
            "n.3dm: chunk 0x40008000 at offset 8: length 100 runs past the end of the enclosing chunk (0 bytes left)");
}

TEST(ArchiveReader, NegativeLengthAndTruncatedHeaderAreRefused) {
  const std::string negative = Bytes{}.put(tcode::kObjectTable).put(std::int64_t{-5}).s;
  ArchiveReader r(negative, "neg.3dm", 50);
  EXPECT_EQ(error_of([&] { r.begin_chunk(); }), "neg.3dm: chunk 0x10000013 at offset 0: negative length -5");
  const std::string cut = negative.substr(0, 7);
  ArchiveReader t(cut, "cut.3dm", 50);
  EXPECT_EQ(error_of([&] { t.begin_chunk(); }),
            "cut.3dm: offset 0: chunk header needs 12 bytes, 7 left");
}

TEST(ArchiveReader, PrimitivesStopAtTheChunkEnd) {
  const std::string file = chunk(tcode::kOpennurbsClassData, Bytes{}.put(std::int32_t{3}).s, 60) + std::string(64, 'x');
  ArchiveReader r(file, "p.3dm", 60);
  r.begin_chunk();
  EXPECT_EQ(error_of([&] { r.f64(); }),
            "p.3dm: chunk 0x0002FFFC at offset 0: double needs 8 bytes, 4 left");
}

TEST(ArchiveReader, CountIsRefusedBeforeTheCallerAllocates) {
  const std::string body = Bytes{}.put(std::int32_t{1000000000}).put(1.0).put(2.0).s;
  const std::string file = chunk(tcode::kOpennurbsClassData, body, 60);
  ArchiveReader r(file, "c.3dm", 60);
  r.begin_chunk();
  EXPECT_EQ(error_of([&] { r.count(sizeof(double)); }),
            "c.3dm: chunk 0x0002FFFC at offset 0: count 1000000000 of 8-byte elements needs 8000000000 bytes, 16 "
                 "left");
  const std::string ok = chunk(tcode::kOpennurbsClassData, Bytes{}.put(std::int32_t{2}).put(1.0).put(2.0).s, 60);
  ArchiveReader g(ok, "c.3dm", 60);
  g.begin_chunk();
  const std::size_t n = g.count(sizeof(double));
  EXPECT_EQ(n, 2u);
  EXPECT_EQ(g.doubles(n), (std::vector<double>{1.0, 2.0}));
  const std::string neg = Bytes{}.put(std::int32_t{-3}).s;
  ArchiveReader m(neg, "c.3dm", 60);
  EXPECT_THROW(m.count(1), ArchiveError);
}

TEST(ArchiveReader, StringsAndWideStringsToUtf8) {
  Bytes b;
  b.put(std::uint32_t{4}).append(std::string("abc\0", 4));
  // "Ä€𝄞" + terminator: U+00C4, U+20AC, U+1D11E (a surrogate pair).
  b.put(std::uint32_t{5}).put(std::uint16_t{0x00C4}).put(std::uint16_t{0x20AC}).put(std::uint16_t{0xD834});
  b.put(std::uint16_t{0xDD1E}).put(std::uint16_t{0});
  b.put(std::uint32_t{0});  // an empty wide string
  b.put(std::uint32_t{3}).put(std::uint16_t{'h'}).put(std::uint16_t{'i'});  // claims 3 units, has 2
  ArchiveReader r(b.s, "s.3dm", 60);
  EXPECT_EQ(r.string(), "abc");
  EXPECT_EQ(r.wide_string(), "\xC3\x84\xE2\x82\xAC\xF0\x9D\x84\x9E");
  EXPECT_EQ(r.wide_string(), "");
  EXPECT_EQ(error_of([&] { r.wide_string(); }),
            ("s.3dm: offset " + std::to_string(b.s.size() - 4) + ": wide string needs 6 bytes, 4 left"));
}

TEST(ArchiveReader, UnexpectedTypecodeAndUuidText) {
  const std::string file = chunk(tcode::kAnonymousChunk, "", 60);
  ArchiveReader r(file, "u.3dm", 60);
  EXPECT_EQ(error_of([&] { r.begin_chunk(tcode::kOpennurbsClass); }),
            "u.3dm: chunk 0x40008000 at offset 0: expected chunk 0x00027FFA, found 0x40008000");
  // ON_NurbsCurve's class id; the file stores Data1..Data3 little-endian.
  const Uuid id = uuid_from_text("4ed7d4dd-e947-11d3-bfe5-0010830122f0");
  EXPECT_EQ(id.bytes[0], 0xDD);
  EXPECT_EQ(id.bytes[3], 0x4E);
  EXPECT_EQ(id.bytes[4], 0x47);
  EXPECT_EQ(id.bytes[8], 0xBF);
  EXPECT_EQ(id.text(), "4ED7D4DD-E947-11D3-BFE5-0010830122F0");
  EXPECT_THROW(uuid_from_text("4ED7D4DD-E947-11D3-BFE5-0010830122F"), std::invalid_argument);
  EXPECT_THROW(uuid_from_text("4ED7D4DD+E947-11D3-BFE5-0010830122F0"), std::invalid_argument);
  ArchiveReader u(std::string_view(reinterpret_cast<const char*>(id.bytes.data()), 16), "u.3dm", 60);
  EXPECT_EQ(u.uuid(), id);
}

}  // namespace
}  // namespace cadnurbs::rhino
