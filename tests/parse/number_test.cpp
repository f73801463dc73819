#include "parse/number.h"

#include <gtest/gtest.h>

#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::error_at;
using parse_test::parse;

TEST(ParseNumber, CFloatingSyntax) {
    const std::pair<const char*, float> cases[] = {
        {"1", 1.0f},     {"-2", -2.0f},   {".5", 0.5f},     {"-.25", -0.25f}, {"1.", 1.0f},
        {"1e-3", 1e-3f}, {"+2", 2.0f},    {"1E3", 1000.0f}, {"-0", 0.0f},     {"2.5e+1", 25.0f},
        {"007", 7.0f},   {"1e-50", 0.0f},  // below float range: rounds to zero, harmless
    };
    for (const auto& [text, value] : cases) {
        const NumberParse n = parse_number(text);
        EXPECT_EQ(n.status, NumberStatus::Ok) << text;
        EXPECT_FLOAT_EQ(n.value, value) << text;
    }
}

TEST(ParseNumber, TrailingCommaIsFlagged) {
    const NumberParse n = parse_number("0.2125,");
    EXPECT_EQ(n.status, NumberStatus::TrailingComma);
    EXPECT_FLOAT_EQ(n.value, 0.2125f);
}

TEST(ParseNumber, RejectsEverythingElse) {
    for (const char* text :
         {"nan", "NaN", "inf", "-inf", "infinity", "0x10", "0X1p3", "1.2.3", "0.6.", "e5",
          ".",   "-",   "+",   "1e",   "1e+",      "",     ",",     "1,,",   "1,2",  "abc",
          "+-1", "1f",  "--1", " 1",   "1 ",       ".e1",  "1..",   ",1"}) {
        EXPECT_EQ(parse_number(text).status, NumberStatus::Invalid) << "'" << text << "'";
    }
}

TEST(ParseNumber, OutOfFloatRange) {
    for (const char* text : {"1e39", "-1e39", "1e999", "1e-999"})
        EXPECT_EQ(parse_number(text).status, NumberStatus::OutOfRange) << text;
    EXPECT_EQ(parse_number("3.4e38").status, NumberStatus::Ok);
}

TEST(ParseNumber, TrailingCommaInAFileIsAWarningAtTheNumber) {
    const auto r = parse("background [ color 0.5, .25 1 ]\n" + std::string(parse_test::kRoot));
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.diagnostics[0].loc.line, 1);
    EXPECT_EQ(r.diagnostics[0].loc.col, 20);
    EXPECT_NE(r.diagnostics[0].message.find("','"), std::string::npos);
    EXPECT_FLOAT_EQ(r.scene.background.x, 0.5f);
    EXPECT_FLOAT_EQ(r.scene.background.y, 0.25f);
}

TEST(ParseNumber, BadNumbersInAFileAreLocatedErrors) {
    const std::string root = parse_test::kRoot;
    EXPECT_TRUE(error_at(parse(root + "background [ color 1 nan 1 ]"), 2, 22,
                         "expected a number for 'color', found 'nan'"));
    EXPECT_TRUE(error_at(parse(root + "background [\n  color inf 1 1 ]"), 3, 9,
                         "expected a number for 'color', found 'inf'"));
    EXPECT_TRUE(error_at(parse(root + "background [ color 0x10 1 1 ]"), 2, 20,
                         "expected a number for 'color', found '0x10'"));
    EXPECT_TRUE(error_at(parse(root + "background [ color 1 1 ]"), 2, 24,
                         "expected a number for 'color', found ']'"));
    EXPECT_TRUE(error_at(parse(root + "background [ color 1 1"), 2, 23,
                         "expected a number for 'color', found end of file"));
    EXPECT_TRUE(error_at(parse(root + "camera [ angle 1e99 ]"), 2, 16, "out of range"));
}

}  // namespace
}  // namespace whitted
