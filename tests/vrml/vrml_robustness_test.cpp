// Damaged input never crashes the reader: every failure is a one-line FileError.
#include <gtest/gtest.h>

#include <random>

#include "formats/common/file_io.hpp"
#include "formats/vrml/vrml_reader.hpp"
#include "formats/vrml/vrml_writer.hpp"
#include "test_scenes.hpp"

namespace cadnurbs {
namespace {

// Reads `text`; passes when it parses or fails with a one-line FileError, fails on anything else.
void expect_clean_outcome(const std::string& text, const std::string& what) {
  try {
    parse_vrml(text, "fuzz");
  } catch (const FileError& e) {
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << what << ": " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << what << ": " << typeid(e).name() << ": " << e.what();
  }
}

std::string mutated(std::string text, std::mt19937& random) {
  static const std::string alphabet = " \n[]{}\"'<>/=#.-+0123456789eEDEFUSEnanNULL&;,";
  std::uniform_int_distribution<int> kind(0, 3);
  std::uniform_int_distribution<size_t> where(0, text.empty() ? 0 : text.size() - 1);
  std::uniform_int_distribution<size_t> letter(0, alphabet.size() - 1);
  for (int edits = 0; edits < 3 && !text.empty(); ++edits) {
    const size_t at = where(random) % text.size();
    switch (kind(random)) {
      case 0: text[at] = alphabet[letter(random)]; break;
      case 1: text.erase(at, std::min<size_t>(text.size() - at, 1 + at % 40)); break;
      case 2: text.insert(at, 1, alphabet[letter(random)]); break;
      default: text.resize(at); break;
    }
  }
  return text;
}

TEST(VrmlRobustness, MutatedFilesFailCleanly) {
  std::vector<std::string> seeds;
  for (auto encoding : {VrmlEncoding::vrml97, VrmlEncoding::x3d_classic, VrmlEncoding::x3d_xml}) {
    VrmlWriteOptions o;
    o.encoding = encoding;
    seeds.push_back(format_vrml(vrml_test::assembly_scene(encoding != VrmlEncoding::vrml97), o));
  }
  const std::string corpus = std::string(CADNURBS_SHARED_DIR) + "/corpus/vrml/";
  for (const char* file : {"NurbsTrimmedSurface.x3d", "nurbs_weights.x3dv", "door.x3dv"}) seeds.push_back(read_file(corpus + file));
  std::mt19937 random(2024);
  for (size_t s = 0; s < seeds.size(); ++s)
    for (int i = 0; i < 400; ++i) expect_clean_outcome(mutated(seeds[s], random), "seed " + std::to_string(s));
}

TEST(VrmlRobustness, SelfReferenceDepthAndExpansionAreRefused) {
  const std::string header = "#X3D V3.3 utf8\n";
  // A node that USEs itself: USE is known only after the DEF'd node ends.
  expect_clean_outcome(header + "DEF A Group { children [ USE A ] }\n", "self USE");
  EXPECT_THROW(parse_vrml(header + "DEF A Group { children [ USE A ] }\n", "t"), FileError);
  // Deep nesting.
  std::string deep = header;
  for (int i = 0; i < 5000; ++i) deep += "Group { children [\n";
  EXPECT_THROW(parse_vrml(deep, "t"), FileError);
  std::string deep_xml = "<X3D><Scene>";
  for (int i = 0; i < 5000; ++i) deep_xml += "<Group>";
  EXPECT_THROW(parse_vrml(deep_xml, "t"), FileError);
  // Exponential USE: 2^40 copies.
  std::string bomb = header + "DEF L0 Group {}\n";
  for (int i = 1; i <= 40; ++i)
    bomb += "DEF L" + std::to_string(i) + " Group { children [ USE L" + std::to_string(i - 1) + " USE L" +
            std::to_string(i - 1) + " ] }\n";
  EXPECT_THROW(parse_vrml(bomb, "t"), FileError);
  // Non-finite numbers.
  EXPECT_THROW(parse_vrml(header + "Transform { translation nan 0 0 }\n", "t"), FileError);
  EXPECT_THROW(parse_vrml(header + "Transform { translation -inf 0 0 }\n", "t"), FileError);
}

// Returns the FileError message of parse_vrml(text), or "" when it reads.
std::string refusal(const std::string& text) {
  try {
    parse_vrml(text, "t");
  } catch (const FileError& e) {
    return e.what();
  }
  return "";
}

TEST(VrmlRobustness, IntegersBeyondInt32AreRefusedNotCast) {
  // Found by fuzz_x3d_xml (UBSan): 5.6e34 was cast to int before it was checked.
  const std::string header = "#X3D V3.3 utf8\nPROFILE Immersive\n";
  const std::string points = "controlPoint Coordinate { point [0 0 0, 1 0 0, 0 1 0, 1 1 0] } } }\n";
  EXPECT_EQ(refusal(header + "Shape { geometry NurbsPatchSurface { uOrder 5.6e34 vOrder 2 uDimension 2 vDimension 2 " + points),
            "t: line 3: field uOrder: expected an integer");
  EXPECT_EQ(refusal(header + "Shape { geometry IndexedFaceSet { coordIndex [0 1 2147483648 -1] }}\n"),
            "t: line 3: field coordIndex: expected integers");
  EXPECT_EQ(refusal("<X3D><Scene><Shape><NurbsPatchSurface uOrder='5.6e34'/></Shape></Scene></X3D>"),
            "t: line 1: field uOrder: expected integers");
  // The largest int32 is still one.
  EXPECT_EQ(refusal(header + "Shape { geometry IndexedFaceSet { coordIndex [0 1 2147483647 -1] }}\n").find("expected"),
            std::string::npos);
}

}  // namespace
}  // namespace cadnurbs
