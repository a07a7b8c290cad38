// Every refusal of parse_part21, word for word: one line naming the file, the line, the instance and
// the reason.
#include <gtest/gtest.h>

#include <string>

#include "formats/common/file_io.hpp"
#include "formats/step/part21/parse_part21.hpp"

namespace cadnurbs::part21 {
namespace {

// The message parse_part21 refuses `bytes` with, or "accepted".
std::string refusal(const std::string& bytes, const Part21Limits& limits = {}) {
  try {
    (void)parse_part21(bytes, "bad.step", limits);
  } catch (const FileError& error) {
    return error.what();
  }
  return "accepted";
}

// A file whose DATA section is `data` (starting on line 4).
std::string with_data(const std::string& data) {
  return "ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n" + data + "\nENDSEC;\nEND-ISO-10303-21;\n";
}

TEST(Part21Refusals, NotStepOrTruncated) {
  EXPECT_EQ(refusal("solid cube\nfacet normal 0 0 1\n"), "bad.step: line 1: not a STEP file (it does not start with ISO-10303-21;)");
  EXPECT_EQ(refusal(""), "bad.step: line 1: not a STEP file (it does not start with ISO-10303-21;)");
  EXPECT_EQ(refusal("ISO-10303-21;\nDATA;\n"), "bad.step: line 2: expected HEADER; after ISO-10303-21;, found 'DATA'");
  EXPECT_EQ(refusal("ISO-10303-21;\nHEADER;\nFILE_NAME('x');\n"),
            "bad.step: line 4: the file ends inside the HEADER section (truncated?)");
  EXPECT_EQ(refusal("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=A(1);\n"),
            "bad.step: line 6: the file ends inside a DATA section (truncated?)");
  EXPECT_EQ(refusal("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=A(1);\nENDSEC;\n"),
            "bad.step: line 7: the file ends before END-ISO-10303-21; (truncated?)");
  EXPECT_EQ(refusal("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=A(1,(2,\n"),
            "bad.step: line 6, #1 A: the file ends with 2 parentheses open");
  EXPECT_EQ(refusal("ISO-10303-21;\nHEADER;\nENDSEC;\nDATA;\n#1=(A(1)"),
            "bad.step: line 5, #1 A: the file ends with 1 parenthesis open");
}

TEST(Part21Refusals, Limits) {
  std::string deep = "#1=A(";
  for (int k = 0; k < 100; ++k) deep += "(";
  EXPECT_EQ(refusal(with_data(deep)), "bad.step: line 5, #1 A: parentheses nested more than 64 deep (the limit is 64)");
  Part21Limits small;
  small.max_depth = 3;
  small.max_list = 4;
  EXPECT_EQ(refusal(with_data("#1=A(((1)));"), small), "accepted");
  EXPECT_EQ(refusal(with_data("#1=A((((1))));"), small),
            "bad.step: line 5, #1 A: parentheses nested more than 3 deep (the limit is 3)");
  EXPECT_EQ(refusal(with_data("#1=(B(C((1))));"), small),
            "bad.step: line 5, #1 B: parentheses nested more than 3 deep (the limit is 3)");
  EXPECT_EQ(refusal(with_data("#1=A((1,2,3,4));"), small), "accepted");
  EXPECT_EQ(refusal(with_data("#1=A((1,2,3,4,5));"), small),
            "bad.step: line 5, #1 A: a list of 5 items or more (the limit is 4)");
  EXPECT_EQ(refusal(with_data("#1=A(1,2,3,4,5);"), small),
            "bad.step: line 5, #1 A: a list of 5 items or more (the limit is 4)");
  EXPECT_EQ(refusal(with_data("#1=(A()B()C()D());"), small), "accepted");
  EXPECT_EQ(refusal(with_data("#1=(A()B()C()D()E());"), small),
            "bad.step: line 5, #1 A: a list of 5 items or more (the limit is 4)");
}

TEST(Part21Refusals, Numbers) {
  EXPECT_EQ(refusal(with_data("#1=A(1.E400);")), "bad.step: line 5, #1 A: the number '1.E400' does not fit a double");
  EXPECT_EQ(refusal(with_data("#1=A(-1e400);")), "bad.step: line 5, #1 A: the number '-1e400' does not fit a double");
  EXPECT_EQ(refusal(with_data("#1=A(inf);")), "bad.step: line 5, #1 A: 'inf' is not a finite number");
  EXPECT_EQ(refusal(with_data("#1=A(-INF);")), "bad.step: line 5, #1 A: '-INF' is not a finite number");
  EXPECT_EQ(refusal(with_data("#1=A(NaN);")), "bad.step: line 5, #1 A: 'NaN' is not a finite number");
  EXPECT_EQ(refusal(with_data("#1=A(99999999999999999999);")),
            "bad.step: line 5, #1 A: the integer '99999999999999999999' does not fit 64 bits");
  EXPECT_EQ(refusal(with_data("#1=A(9223372036854775807,-9223372036854775808);")), "accepted");
  EXPECT_EQ(refusal(with_data("#99999999999999999999=A();")),
            "bad.step: line 5: the entity number '#999999999999999999'... is too large");
  EXPECT_EQ(refusal(with_data("#0=A();")), "bad.step: line 5: the entity number #0 (numbers start at 1)");
}

TEST(Part21Refusals, References) {
  EXPECT_EQ(refusal(with_data("#1=A(#2);\n#2=B((#1,#7));")), "bad.step: line 6, #2 B: refers to #7, which the file lacks");
  EXPECT_EQ(refusal(with_data("#1=A(#5);\n#5=(B(#1) C((#9)));")),
            "bad.step: line 6, #5 B: refers to #9, which the file lacks");
  EXPECT_EQ(refusal(with_data("#1=A();\n#2=B();\n\n#1=C(#2);")), "bad.step: line 8, #1 C: #1 is defined twice (first at line 5)");
  // Sparse numbers take the sorted index: the same refusals.
  EXPECT_EQ(refusal(with_data("#1000000000=A();\n#1000000000=C();")),
            "bad.step: line 6, #1000000000 C: #1000000000 is defined twice (first at line 5)");
  EXPECT_EQ(refusal(with_data("#1000000000=A(#3);")), "bad.step: line 5, #1000000000 A: refers to #3, which the file lacks");
  EXPECT_EQ(refusal(with_data("#1=A(#);")), "bad.step: line 5, #1 A: '#' without an entity number");
}

TEST(Part21Refusals, Unterminated) {
  EXPECT_EQ(refusal(with_data("#1=A('abc);")), "bad.step: line 5, #1 A: a string that is never closed");
  EXPECT_EQ(refusal(with_data("#1=A(\"0FF);")), "bad.step: line 5, #1 A: a binary literal that is never closed");
  EXPECT_EQ(refusal(with_data("#1=A(\"9FF\");")),
            "bad.step: line 5, #1 A: the binary literal '9FF' is not a digit 0-3 followed by hex digits");
  EXPECT_EQ(refusal(with_data("#1=A(1); /* never\nclosed")), "bad.step: line 5: a comment that is never closed (no */)");
  EXPECT_EQ(refusal(with_data("#1=A(.T);")), "bad.step: line 5, #1 A: the enumeration '.T' is not closed by '.'");
}

TEST(Part21Refusals, Structure) {
  EXPECT_EQ(refusal(with_data("#1=A(1));")), "bad.step: line 5, #1 A: ')' without a matching '('");
  EXPECT_EQ(refusal(with_data("#1=A((1;\n#2=B();")), "bad.step: line 5, #1 A: ';' with 2 parentheses still open");
  EXPECT_EQ(refusal(with_data("#1=A((1);\n#2=B();")), "bad.step: line 5, #1 A: ';' with 1 parenthesis still open");
  EXPECT_EQ(refusal(with_data("#1=A(1)\n#2=B();")), "bad.step: line 6, #1 A: expected ';' after the instance, found '#'");
  EXPECT_EQ(refusal(with_data("#1=A(1 2);")), "bad.step: line 5, #1 A: expected ',' or ')' after a parameter, found '2'");
  EXPECT_EQ(refusal(with_data("#1=A(1,);")), "bad.step: line 5, #1 A: ')' where a parameter is expected");
  EXPECT_EQ(refusal(with_data("#1=A(@);")), "bad.step: line 5, #1 A: '@' where a parameter is expected");
  EXPECT_EQ(refusal(with_data("#1=A(FOO);")), "bad.step: line 5, #1 A: 'FOO' where a parameter is expected");
  EXPECT_EQ(refusal(with_data("#1=A(B(1,2));")), "bad.step: line 5, #1 A: the typed parameter B(...) holds 2 values, not one");
  EXPECT_EQ(refusal(with_data("#1=A(B());")), "bad.step: line 5, #1 A: ')' where a parameter is expected");
  EXPECT_EQ(refusal(with_data("#1 A(1);")), "bad.step: line 5, #1: expected '=' after #1, found 'A'");
  EXPECT_EQ(refusal(with_data("#1=(A(1) 5);")), "bad.step: line 5, #1 A: expected a type name or ')' in a complex instance, found '5'");
  EXPECT_EQ(refusal(with_data("#1=();")), "bad.step: line 5, #1: a complex instance without any type");
  EXPECT_EQ(refusal(with_data("#1=A(1);\nB(2);")), "bad.step: line 6: expected an instance '#N = ...' or ENDSEC;, found 'B'");
  EXPECT_EQ(refusal("ISO-10303-21;\nHEADER;\nFILE_NAME('x')\nENDSEC;"),
            "bad.step: line 4, FILE_NAME: expected ';' after FILE_NAME, found 'ENDSEC'");
}

}  // namespace
}  // namespace cadnurbs::part21
