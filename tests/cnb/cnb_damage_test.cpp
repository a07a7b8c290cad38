// Damaged and truncated .cnb files: each refused with one FileError line naming the file, the byte and
// what is wrong; payloads that claim more than their bytes can hold refused before allocating.
#include <gtest/gtest.h>
#include <zlib.h>

#include "formats/cnb/cnb_container.hpp"
#include "formats/cnb/cnb_reader.hpp"
#include "formats/cnb/cnb_writer.hpp"
#include "formats/common/file_io.hpp"
#include "formats/vrml/vrml_reader.hpp"

namespace cadnurbs {
namespace {

const std::string name = "capping-90.cnb";

const std::string& capping_file() {
  static const std::string bytes = [] {
    CnbOptions options;
    options.max_deviation = 0.01;
    return write_cnb(read_vrml(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-90.x3dv"), options);
  }();
  return bytes;
}

std::string error_of(const std::string& bytes) {
  try {
    read_cnb(bytes, name);
  } catch (const FileError& e) {
    return e.what();
  }
  return "(read without error)";
}

uint32_t u32_at(const std::string& s, size_t at) {
  uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v |= static_cast<uint32_t>(static_cast<uint8_t>(s[at + i])) << (8 * i);
  return v;
}

// The file with its header CRC made right again after an edit.
std::string with_fresh_crc(std::string file) {
  uLong c = crc32(0L, Z_NULL, 0);
  c = crc32(c, reinterpret_cast<const Bytef*>(file.data()), 14);
  c = crc32(c, reinterpret_cast<const Bytef*>(file.data() + 18), static_cast<uInt>(file.size() - 18));
  for (int i = 0; i < 4; ++i) file[14 + i] = static_cast<char>(c >> (8 * i));
  return file;
}

TEST(CnbDamage, TruncatedFiles) {
  const std::string& file = capping_file();
  const size_t coded = file.size() - 18;
  EXPECT_EQ(error_of(""), name + ": byte 0: truncated: the file ends inside the magic number");
  EXPECT_EQ(error_of(file.substr(0, 2)), name + ": byte 2: truncated: the file ends inside the magic number");
  EXPECT_EQ(error_of(file.substr(0, 10)), name + ": byte 10: truncated: the header needs 18 bytes, the file has 10");
  for (size_t cut : {size_t(18), size_t(19), file.size() / 2, file.size() - 1})
    EXPECT_EQ(error_of(file.substr(0, cut)), name + ": byte " + std::to_string(cut) + ": truncated: the header promises " +
                                                 std::to_string(coded) + " coded bytes after byte 18, the file has " +
                                                 std::to_string(cut - 18));
  EXPECT_EQ(error_of(file + "x"), name + ": byte " + std::to_string(file.size()) + ": damaged: the header promises " +
                                      std::to_string(coded) + " coded bytes after byte 18, the file has " +
                                      std::to_string(coded + 1));
}

// Every byte of the file flipped in turn gives the message for the field it lies in.
TEST(CnbDamage, EveryFlippedByteIsRefused) {
  const std::string& file = capping_file();
  const size_t coded = file.size() - 18;
  const std::string crc_message = name + ": byte 14: damaged: the CRC-32 of the file does not match the one in its header";
  for (size_t at = 0; at < file.size(); ++at) {
    std::string damaged = file;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x24);
    std::string expected;
    if (at < 4) {
      expected = name + ": byte " + std::to_string(at) + ": not a .cnb file (the magic number is \\x89CNB)";
    } else if (at == 4) {
      expected = name + ": byte 4: version " + std::to_string(1 ^ 0x24) + " is not one this reader knows (1)";
    } else if (at >= 10 && at < 14) {
      const size_t claimed = u32_at(damaged, 10);
      expected = name + ": byte " + std::to_string(std::min(file.size(), 18 + claimed)) + ": " +
                 (claimed > coded ? "truncated" : "damaged") + ": the header promises " + std::to_string(claimed) +
                 " coded bytes after byte 18, the file has " + std::to_string(coded);
    } else {
      expected = crc_message;
    }
    ASSERT_EQ(error_of(damaged), expected) << "byte " << at;
  }
}

TEST(CnbDamage, HeaderClaimingAnImpossiblePayloadSize) {
  CnbOptions options;
  options.coder = CnbOptions::Coder::deflate;
  std::string file = write_cnb(read_vrml(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-end.x3dv"), options);
  const size_t coded = file.size() - 18;
  for (int i = 0; i < 4; ++i) file[6 + i] = '\xFF';
  EXPECT_EQ(error_of(with_fresh_crc(file)), name + ": byte 6: a payload of 4294967295 bytes cannot come from " +
                                                std::to_string(coded) + " deflated bytes");
  // One byte fewer than the stream holds.
  std::string shorter = write_cnb(read_vrml(std::string(CADNURBS_SOURCE_DIR) + "/samples/capping-end.x3dv"), options);
  const uint32_t size = u32_at(shorter, 6) - 1;
  for (int i = 0; i < 4; ++i) shorter[6 + i] = static_cast<char>(size >> (8 * i));
  EXPECT_EQ(error_of(with_fresh_crc(shorter)),
            name + ": byte 6: the deflate stream holds more than the " + std::to_string(size) + " payload bytes the header promises");
}

// A payload's scene header (unit mm, D = q = bound = 1) and the root node's name and flags.
cnb::ByteWriter scene_header_and_root() {
  cnb::ByteWriter w;
  w.text("mm");
  w.float64(1.0);
  w.text("mm");
  w.float64(1.0);
  for (int i = 0; i < 3; ++i) w.float64(1.0);
  w.text("");
  w.byte(0);
  return w;
}

// A payload with a valid checksum whose counts lie: refused at the count, before allocating.
TEST(CnbDamage, CountsBeyondTheBytesLeft) {
  for (auto coder : {CnbOptions::Coder::deflate, CnbOptions::Coder::arithmetic}) {
    cnb::ByteWriter w = scene_header_and_root();
    const size_t count_at = w.bytes().size();
    w.varuint(1000000, cnb::Field::count);  // shapes
    w.varuint(0, cnb::Field::count);        // children
    const std::string file = cnb::pack(w, coder, nullptr);
    EXPECT_EQ(error_of(file), name + ": decoded byte " + std::to_string(count_at) +
                                  ": count 1000000 cannot fit in the 1 bytes left");
  }
}

// A surface whose knot multiplicities do not add up to what its net needs.
TEST(CnbDamage, KnotsThatDoNotFitTheNet) {
  cnb::ByteWriter w = scene_header_and_root();
  w.varuint(1, cnb::Field::count);  // one shape
  w.byte(0);                        // a trimmed surface
  w.text("face");
  for (int v : {2, 2, 2, 2}) w.varuint(v, cnb::Field::count);  // orders, counts
  const size_t knots_at = w.bytes().size();
  w.varuint(2, cnb::Field::count);  // two distinct knots
  w.byte(0, cnb::Field::knot);      // whole numbers
  w.varsint(0, cnb::Field::knot);
  w.varuint(0, cnb::Field::knot);
  w.varuint(1, cnb::Field::count);  // multiplicity 2
  w.varuint(0, cnb::Field::count);  // multiplicity 1: 3 knots where 4 are needed
  for (int i = 0; i < 40; ++i) w.byte(0);
  EXPECT_EQ(error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr)),
            name + ": decoded byte " + std::to_string(knots_at) + ": knot multiplicities add up to 3, the net needs 4");
}

// Repeats of a large shape: refused once the scene would hold more numbers than the payload allows.
TEST(CnbDamage, RepeatsBeyondTheNumberBudget) {
  cnb::ByteWriter w = scene_header_and_root();
  const int vertices = 1000, repeats = 2000;
  w.varuint(1 + repeats, cnb::Field::count);  // shapes
  w.byte(2);                                  // a triangle mesh
  w.text("");
  w.varuint(vertices, cnb::Field::count);
  for (int i = 0; i < 3 * vertices; ++i) w.varsint(0, cnb::Field::point);
  w.varuint(1, cnb::Field::count);
  for (int k = 0; k < 3; ++k) w.varsint(0, cnb::Field::index);
  w.byte(0);  // no normals
  std::vector<size_t> repeat_at;
  for (int r = 0; r < repeats; ++r) {
    w.byte(4);  // the same geometry as the shape just before
    w.text("");
    repeat_at.push_back(w.bytes().size());
    w.varuint(0, cnb::Field::index);
  }
  w.varuint(0, cnb::Field::count);  // children
  const size_t budget = 256 * w.bytes().size() + (size_t(1) << 20), each = 3 * vertices + 3;
  const size_t failing = budget / each;  // shapes that fit: the mesh and failing - 1 repeats
  ASSERT_LT(failing, size_t(repeats));
  EXPECT_EQ(error_of(cnb::pack(w, CnbOptions::Coder::deflate, nullptr)),
            name + ": decoded byte " + std::to_string(repeat_at[failing - 1]) + ": the scene would hold more than " +
                std::to_string(budget) + " numbers (256 per payload byte and 1048576)");
}

}  // namespace
}  // namespace cadnurbs
