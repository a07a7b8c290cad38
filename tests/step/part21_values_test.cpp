// A small hand-written Part 21 file read back value by value: simple and complex instances, nested
// lists, a typed parameter, escaped strings, enumerations, $ and *, a forward reference, comments.
#include <gtest/gtest.h>

#include <string>

#include "formats/step/part21/parse_part21.hpp"

namespace cadnurbs::part21 {
namespace {

const char* const small_file = R"(ISO-10303-21;
HEADER;
/* a comment in the header */
FILE_DESCRIPTION(('a test'),'2;1');
FILE_NAME('small.step','2024-01-01T00:00:00',('me'),(''),'','','');
FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }', 'CONFIG_CONTROL_DESIGN'));
ENDSEC;
DATA;
#10 = CARTESIAN_POINT('origin', (0., 1.E-07, -5.));
#11=DIRECTION('',(+3,-2.5E+2,.5));
#12 = ORIENTED_EDGE('it''s \X2\00E9D83DDE00\X0\', *, $, #20, .T.);
/* between
   instances */ #13 = MEASURE_WITH_UNIT(LENGTH_MEASURE(2.), #10);
#14 = (BOUNDED_SURFACE() B_SPLINE_SURFACE(1, 1, ((#10, #11), (#10, #11)), .UNSPECIFIED., .F., .F., .U.)
  REPRESENTATION_ITEM('complex'));
#15 = NESTED((((1), 2), ()), "2F0", 'caf\X\E9 \\ \S\i');
ENDSEC;
DATA;
#20 = EDGE_CURVE('', #10, #10, #11, .T.);
ENDSEC;
END-ISO-10303-21;
)";

class SmallFile : public ::testing::Test {
 protected:
  Model model = parse_part21(small_file, "small.step");
  Value parameter(std::int64_t number, std::size_t k) const {
    const EntityId id = model.find(number);
    return model.parameter(model.records(id)[0], k);
  }
};

TEST_F(SmallFile, EntitiesAndTypes) {
  EXPECT_EQ(model.size(), 7u);
  EXPECT_EQ(model.reference_count(), 9u);
  EXPECT_EQ(model.find(99), none);
  const EntityId point = model.find(10);
  ASSERT_EQ(point, 0u);
  EXPECT_EQ(model.number(point), 10);
  EXPECT_EQ(model.line(point), 9);
  EXPECT_EQ(model.line(model.find(13)), 13);
  EXPECT_EQ(model.line(model.find(20)), 19);
  EXPECT_EQ(model.type_name(model.type(point)), "CARTESIAN_POINT");
  EXPECT_EQ(model.type_named("CARTESIAN_POINT"), model.type(point));
  EXPECT_EQ(model.type_named("PLANE"), none);
  EXPECT_EQ(model.entity_text(model.find(12)), "#12 ORIENTED_EDGE");
  ASSERT_EQ(model.file_schemas().size(), 2u);
  EXPECT_EQ(model.file_schemas()[0], "AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }");
  EXPECT_EQ(model.file_schemas()[1], "CONFIG_CONTROL_DESIGN");
  EXPECT_EQ(model.type_named("FILE_NAME"), none);  // header entities are not instances
}

TEST_F(SmallFile, NumbersInEveryForm) {
  const Value coordinates = parameter(10, 1);
  ASSERT_EQ(coordinates.size(), 3u);
  EXPECT_EQ(coordinates.item(0).kind(), ValueKind::real);
  EXPECT_EQ(coordinates.item(0).number(), 0.0);
  EXPECT_EQ(coordinates.item(1).number(), 1e-7);
  EXPECT_EQ(coordinates.item(2).number(), -5.0);
  const Value direction = parameter(11, 1);
  EXPECT_EQ(direction.item(0).kind(), ValueKind::integer);
  EXPECT_EQ(direction.item(0).integer(), 3);
  EXPECT_EQ(direction.item(0).number(), 3.0);
  EXPECT_EQ(direction.item(1).number(), -250.0);
  EXPECT_EQ(direction.item(2).number(), 0.5);
  EXPECT_THROW((void)direction.item(3), ValueError);
  EXPECT_THROW((void)direction.item(1).integer(), ValueError);
}

TEST_F(SmallFile, StringsEnumerationsUnsetDerivedAndForwardReference) {
  EXPECT_EQ(parameter(10, 0).text(), "origin");
  EXPECT_EQ(parameter(11, 0).text(), "");
  EXPECT_EQ(parameter(12, 0).text(), "it's \xC3\xA9\xF0\x9F\x98\x80");  // é and U+1F600 from a surrogate pair
  EXPECT_EQ(parameter(12, 1).kind(), ValueKind::derived);
  EXPECT_EQ(parameter(12, 2).kind(), ValueKind::unset);
  const Value forward = parameter(12, 3);
  EXPECT_EQ(forward.reference(), model.find(20));
  EXPECT_EQ(forward.reference_number(), 20);
  EXPECT_EQ(model.type_name(model.type(forward.reference())), "EDGE_CURVE");
  EXPECT_TRUE(parameter(12, 4).boolean());
  EXPECT_EQ(parameter(12, 4).text(), "T");
  EXPECT_EQ(model.records(model.find(12))[0].count, 5u);
  try {
    (void)parameter(12, 5);
    FAIL() << "no 6th parameter";
  } catch (const ValueError& error) {
    EXPECT_STREQ(error.what(), "ORIENTED_EDGE has 5 parameters, not 6");
  }
  EXPECT_EQ(parameter(15, 2).text(), "caf\xC3\xA9 \\ \xC3\xA9");
}

TEST_F(SmallFile, TypedParameter) {
  const Value measure = parameter(13, 0);
  ASSERT_EQ(measure.kind(), ValueKind::typed);
  EXPECT_EQ(model.type_name(measure.type()), "LENGTH_MEASURE");
  EXPECT_EQ(measure.type(), model.type_named("LENGTH_MEASURE"));
  EXPECT_TRUE(model.of_type(measure.type()).empty());  // a typed parameter's type, not an instance's
  EXPECT_EQ(measure.inner().number(), 2.0);
  EXPECT_EQ(parameter(13, 1).reference(), model.find(10));
  try {
    (void)measure.number();
    FAIL() << "a typed parameter is not a number";
  } catch (const ValueError& error) {
    EXPECT_STREQ(error.what(), "expected a number, found a typed parameter");
  }
}

TEST_F(SmallFile, ComplexInstance) {
  const EntityId surface = model.find(14);
  EXPECT_EQ(model.type(surface), none);
  const auto records = model.records(surface);
  ASSERT_EQ(records.size(), 3u);
  EXPECT_EQ(model.type_name(records[0].type), "BOUNDED_SURFACE");
  EXPECT_EQ(records[0].count, 0u);
  EXPECT_EQ(model.type_name(records[1].type), "B_SPLINE_SURFACE");
  EXPECT_EQ(model.type_name(records[2].type), "REPRESENTATION_ITEM");
  EXPECT_EQ(model.entity_text(surface), "#14 (BOUNDED_SURFACE B_SPLINE_SURFACE REPRESENTATION_ITEM)");
  const TypeId spline = model.type_named("B_SPLINE_SURFACE");
  EXPECT_TRUE(model.is(surface, spline));
  EXPECT_FALSE(model.is(surface, model.type_named("CARTESIAN_POINT")));
  ASSERT_EQ(model.record(surface, spline), &records[1]);
  EXPECT_EQ(model.parameter(records[1], 0).integer(), 1);
  const Value grid = model.parameter(records[1], 2);
  ASSERT_EQ(grid.size(), 2u);
  ASSERT_EQ(grid.item(1).size(), 2u);
  EXPECT_EQ(grid.item(1).item(1).reference(), model.find(11));
  EXPECT_EQ(model.parameter(records[1], 3).text(), "UNSPECIFIED");
  EXPECT_FALSE(model.parameter(records[1], 4).boolean());
  try {
    (void)model.parameter(records[1], 6).boolean();
    FAIL() << ".U. is not a boolean";
  } catch (const ValueError& error) {
    EXPECT_STREQ(error.what(), "expected a boolean (.T. or .F.), found .U.");
  }
  EXPECT_EQ(model.parameter(records[2], 0).text(), "complex");
  EXPECT_EQ(model.of_type(spline).size(), 1u);
  EXPECT_EQ(model.of_type(spline)[0], surface);
}

TEST_F(SmallFile, NestedListsAndBinary) {
  const Value nested = parameter(15, 0);
  ASSERT_EQ(nested.size(), 2u);
  const Value first = nested.item(0);
  ASSERT_EQ(first.size(), 2u);
  ASSERT_EQ(first.item(0).size(), 1u);
  EXPECT_EQ(first.item(0).item(0).integer(), 1);
  EXPECT_EQ(first.item(1).integer(), 2);
  EXPECT_EQ(nested.item(1).size(), 0u);
  EXPECT_EQ(parameter(15, 1).kind(), ValueKind::binary);
  EXPECT_EQ(parameter(15, 1).text(), "2F0");
  try {
    (void)nested.item(2);
    FAIL() << "past the end";
  } catch (const ValueError& error) {
    EXPECT_STREQ(error.what(), "a list of 2 items has no item 3");
  }
  try {
    (void)parameter(15, 1).size();
    FAIL() << "a binary is not a list";
  } catch (const ValueError& error) {
    EXPECT_STREQ(error.what(), "expected a list, found a binary");
  }
}

TEST_F(SmallFile, OfTypeInFileOrderAcrossSections) {
  const auto points = model.of_type(model.type_named("CARTESIAN_POINT"));
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(model.number(points[0]), 10);
  const auto edges = model.of_type(model.type_named("EDGE_CURVE"));
  ASSERT_EQ(edges.size(), 1u);
  EXPECT_EQ(edges[0], 6u);  // the second DATA section continues the table
}

TEST(Part21, SparseEntityNumbersAndUserDefinedKeyword) {
  const std::string file =
      "ISO-10303-21;HEADER;ENDSEC;DATA;#9000000000=!MY_THING(#3);#3=POINT(1);ENDSEC;END-ISO-10303-21;";
  const Model model = parse_part21(file, "sparse.step");
  ASSERT_EQ(model.size(), 2u);
  EXPECT_EQ(model.find(9000000000), 0u);
  EXPECT_EQ(model.find(3), 1u);
  EXPECT_EQ(model.find(4), none);
  EXPECT_EQ(model.type_name(model.type(0)), "!MY_THING");
  EXPECT_EQ(model.parameter(model.records(0)[0], 0).reference(), 1u);
}

TEST(Part21, TypeRepeatedInAComplexInstanceListedOnce) {
  const Model model = parse_part21("ISO-10303-21;HEADER;ENDSEC;DATA;#1=(A()B(2)A(1));#2=A(3);ENDSEC;END-ISO-10303-21;", "t.step");
  const TypeId a = model.type_named("A");
  ASSERT_EQ(model.of_type(a).size(), 2u);
  EXPECT_EQ(model.of_type(a)[0], 0u);
  EXPECT_EQ(model.of_type(a)[1], 1u);
  EXPECT_EQ(model.record(0, a), &model.records(0)[0]);  // the first one written
  EXPECT_EQ(model.of_type(model.type_named("B")).size(), 1u);
}

TEST(Part21, TinyNumbersUnderflowToZeroOrSubnormal) {
  const Model model = parse_part21("ISO-10303-21;HEADER;ENDSEC;DATA;#1=A(1.E-400,-1.E-310);ENDSEC;END-ISO-10303-21;", "t.step");
  EXPECT_EQ(model.parameter(model.records(0)[0], 0).number(), 0.0);
  EXPECT_LT(model.parameter(model.records(0)[0], 1).number(), 0.0);
}

}  // namespace
}  // namespace cadnurbs::part21
