// STEP string literals to UTF-8: every escape the standard has, and what malformed ones become.
#include <gtest/gtest.h>

#include "formats/step/part21/step_string.hpp"

namespace cadnurbs::part21 {
namespace {

TEST(StepString, PlainQuoteAndBackslash) {
  EXPECT_EQ(decode_step_string("abc"), "abc");
  EXPECT_EQ(decode_step_string("it''s"), "it's");
  EXPECT_EQ(decode_step_string("a\\\\b"), "a\\b");
}

TEST(StepString, Latin1Escapes) {
  EXPECT_EQ(decode_step_string("\\X\\E9"), "\xC3\xA9");
  EXPECT_EQ(decode_step_string("\\X\\41"), "A");
  EXPECT_EQ(decode_step_string("\\S\\i"), "\xC3\xA9");  // 'i' + 128 = 0xE9
  EXPECT_EQ(decode_step_string("\\PA\\x\\S\\i"), "x\xC3\xA9");  // the page switch is dropped
}

TEST(StepString, Utf16AndUcs4) {
  EXPECT_EQ(decode_step_string("\\X2\\00E9041F\\X0\\!"), "\xC3\xA9\xD0\x9F!");
  EXPECT_EQ(decode_step_string("\\X2\\D83DDE00\\X0\\"), "\xF0\x9F\x98\x80");
  EXPECT_EQ(decode_step_string("\\X4\\0001F600000000E9\\X0\\"), "\xF0\x9F\x98\x80\xC3\xA9");
  EXPECT_EQ(decode_step_string("\\X2\\D83D\\X0\\"), "\xEF\xBF\xBD");  // an unpaired surrogate
  EXPECT_EQ(decode_step_string("\\X4\\00110000\\X0\\"), "\xEF\xBF\xBD");  // past U+10FFFF
}

TEST(StepString, MalformedEscapesStayAsWritten) {
  EXPECT_EQ(decode_step_string("\\X2\\00E"), "\\X2\\00E");
  EXPECT_EQ(decode_step_string("\\X\\G1"), "\\X\\G1");
  EXPECT_EQ(decode_step_string("a\\q"), "a\\q");
}

TEST(StepString, LineBreaksDroppedRawBytesMadeUtf8) {
  EXPECT_EQ(decode_step_string("Undefined De\r\nscription"), "Undefined Description");
  EXPECT_EQ(decode_step_string("caf\xC3\xA9"), "caf\xC3\xA9");  // valid UTF-8 kept
  EXPECT_EQ(decode_step_string("caf\xE9"), "caf\xC3\xA9");      // otherwise ISO 8859-1
}

}  // namespace
}  // namespace cadnurbs::part21
