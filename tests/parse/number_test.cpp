#include "parse/number.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <vector>

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

// The reader's rules at their edges, pinned so that a faster reader accepts exactly the same set and
// gives the same floats. Values: a literal is read as the nearest double (the C library's strtod,
// or the compiler for a literal) and that double rounded to float.
TEST(ParseNumber, SignsPointsAndExponentsAtTheEdges) {
    const std::pair<const char*, float> cases[] = {
        {"+.5", 0.5f},      {"5.e3", 5000.0f},  {".5e1", 5.0f},     {"-5.", -5.0f},     {"1e+5", 1e5f},
        {"1E-3", 1e-3f},    {"1e-0", 1.0f},     {"+1e+1", 10.0f},   {"0.1", float(0.1)}, {"-.25e-2", -0.0025f},
        {"00000000000000000000001.5", 1.5f},    // leading zeros are not digits that count
        {"1e0000000000000000000001", 10.0f},    // nor are an exponent's
        {"0e99999", 0.0f},  {"0e-99999", 0.0f},  // zero stays zero at any scale
        {"123456789012345678901234567890", float(123456789012345678901234567890.0)},
        {"0.100000000000000000000000000001", float(0.1)},
        {"100000000000000000000000000000000000000000e-10", float(1e31)},
        {"0.000000000000000000000000000000000000000000000000000000001e40", float(1e-17)},
        {"9007199254740993", float(9007199254740992.0)},  // 2^53 + 1: beyond exact doubles
        {"3.4e38", 3.4e38f},
    };
    for (const auto& [text, value] : cases) {
        const NumberParse n = parse_number(text);
        EXPECT_EQ(n.status, NumberStatus::Ok) << text;
        EXPECT_EQ(n.value, value) << text;
    }
}

TEST(ParseNumber, NegativeZeroKeepsItsSign) {
    for (const char* text : {"-0", "-0.0", "-.0e5", "-0,"}) {
        const NumberParse n = parse_number(text);
        EXPECT_NE(n.status, NumberStatus::Invalid) << text;
        EXPECT_EQ(n.value, 0.0f) << text;
        EXPECT_TRUE(std::signbit(n.value)) << text;
    }
    EXPECT_FALSE(std::signbit(parse_number("+0").value));
}

// The literal is rounded to double first, then to float. 1 + 2^-24 (1.000000059604644775390625) is
// halfway between the floats 1 and 1 + 2^-23, and an exact double; 1.0000000596046448 lies 2.5e-17
// above it, less than half a double step (1.1e-16), so it becomes that double, whose tie goes to the
// even float, 1. (Rounded to float directly it would be 1 + 2^-23.)
TEST(ParseNumber, RoundsToDoubleThenToFloat) {
    EXPECT_EQ(parse_number("1.0000000596046448").value, 1.0f);
    EXPECT_EQ(parse_number("1.000000059604645").value, 1.0f + 0x1p-23f);  // past the tie in double too
}

// Below float's range a literal rounds to float's subnormals or to 0, and is accepted; out of
// range are only magnitudes above FLT_MAX (3.40282347e38, so 3.4028235e38 already, being larger
// as a double) and literals too small even for double's subnormals (below 2.47e-324).
TEST(ParseNumber, RangeEdges) {
    EXPECT_EQ(parse_number("1e-40").value, float(1e-40));  // a float subnormal
    EXPECT_NE(parse_number("1e-40").value, 0.0f);
    EXPECT_EQ(parse_number("1e-45").value, 0x1p-149f);  // the smallest float
    for (const char* text : {"1e-46", "1e-310", "1e-320"}) {
        EXPECT_EQ(parse_number(text).status, NumberStatus::Ok) << text;
        EXPECT_EQ(parse_number(text).value, 0.0f) << text;
    }
    for (const char* text : {"3.4028235e38", "-3.4028235e38", "1e308", "1.7976931348623159e308", "2e-324",
                             "2.4e-324", "1e-400000000000000000000"})
        EXPECT_EQ(parse_number(text).status, NumberStatus::OutOfRange) << text;
    EXPECT_EQ(parse_number("3.4028234e38").value, 3.4028234e38f);
}

TEST(ParseNumber, TrailingCommaAfterEveryShape) {
    const std::pair<const char*, float> cases[] = {{"1.,", 1.0f}, {"1e5,", 1e5f}, {"-.5,", -0.5f}, {"+2,", 2.0f}};
    for (const auto& [text, value] : cases) {
        const NumberParse n = parse_number(text);
        EXPECT_EQ(n.status, NumberStatus::TrailingComma) << text;
        EXPECT_EQ(n.value, value) << text;
    }
    EXPECT_EQ(parse_number("1e39,").status, NumberStatus::OutOfRange);
}

TEST(ParseNumber, RejectsOtherSpellings) {
    for (const char* text : {"-nan", "+inf", "INF", "Infinity", "0x", "0x1", "0b1", "1_000", "1'000", "1e5.5", "1e-",
                             "1.e", "-.", "+.", "-e1", "e", "E5", "1d", "1.0f", "1e5e5", "1 ,", ",,", "1.,,", "\xd9\xa1",
                             "1\t", "--", "++1", ".5.", "1e+-5"})
        EXPECT_EQ(parse_number(text).status, NumberStatus::Invalid) << "'" << text << "'";
}

// Random literals against the C library (glibc's strtod rounds correctly), through the double.
TEST(ParseNumber, AgreesWithStrtodOnRandomLiterals) {
    std::mt19937 rng(7);
    auto digits = [&](int n) {
        std::string s;
        for (int i = 0; i < n; ++i) s += char('0' + rng() % 10);
        return s;
    };
    for (int i = 0; i < 200000; ++i) {
        std::string s;
        if (rng() % 3 == 0) s += rng() % 2 ? "-" : "+";
        const int int_digits = int(rng() % 12), frac_digits = int(rng() % 14);
        s += digits(int_digits);
        if (frac_digits > 0 || rng() % 2) {
            s += '.';
            s += digits(frac_digits);
        }
        if (int_digits + frac_digits == 0) s += '0';
        if (rng() % 3 == 0) {
            s += rng() % 2 ? 'e' : 'E';
            if (rng() % 2) s += '-';
            s += std::to_string(rng() % 40);
        }
        const double expected = std::strtod(s.c_str(), nullptr);
        const NumberParse n = parse_number(s);
        if (std::fabs(expected) > double(std::numeric_limits<float>::max())) {
            EXPECT_EQ(n.status, NumberStatus::OutOfRange) << s;
        } else {
            EXPECT_EQ(n.status, NumberStatus::Ok) << s;
            EXPECT_EQ(n.value, float(expected)) << s;
            EXPECT_EQ(std::signbit(n.value), std::signbit(expected)) << s;
        }
    }
}

// The parser reads most numbers straight from the text, not through parse_number: the same
// values, whatever the white space, the sign, the place in the file (its last bytes too).
TEST(ParseNumber, NumbersInAFileReadAsStrtodDoes) {
    std::mt19937 rng(11);
    const char* spaces[] = {" ", "  ", "\t", "\n", "\r\n", "\r", " \n    ", " # comment\n "};
    std::string text = "mastersubgraph root [";
    std::vector<double> expected;
    for (int i = 0; i < 3000; ++i) {
        text += " trans [ translate";
        for (int k = 0; k < 3; ++k) {
            std::string number = rng() % 3 ? "" : "-";
            const int int_digits = int(rng() % 9), frac_digits = int(rng() % 10);
            for (int d = 0; d < int_digits; ++d) number += char('0' + rng() % 10);
            if (frac_digits > 0 || int_digits == 0 || rng() % 4 == 0) number += '.';
            for (int d = 0; d < frac_digits; ++d) number += char('0' + rng() % 10);
            if (int_digits + frac_digits == 0) number += '7';
            text += spaces[rng() % 8];
            text += number;
            expected.push_back(std::strtod(number.c_str(), nullptr));
        }
        text += rng() % 2 ? " object cube [ ] ]" : "\nobject cube[]]";
    }
    text += "\n]";
    const ParseResult r = parse(text);
    ASSERT_TRUE(parse_test::parsed_ok(r));
    const auto& children = r.scene.subgraphs.at(0).children;
    ASSERT_EQ(children.size() * 3, expected.size());
    for (std::size_t i = 0; i < children.size(); ++i)
        for (int k = 0; k < 3; ++k)  // the identity times the translation: exact (but -0 becomes 0)
            EXPECT_EQ(children[i].matrix[3][k], float(expected[3 * i + k])) << i << " " << k;
    // The last bytes of the text: no room for eight at once.
    const std::string before = std::string(parse_test::kRoot) + "background [ color 1 1 ";
    for (const std::string tail : {"1", "-2.5", "0.125", "12345678", "3.", ".5", "-0"}) {
        EXPECT_TRUE(error_at(parse(before + tail), 2, 24 + int(tail.size()), "unexpected end of file")) << tail;
        const ParseResult closed = parse(before + tail + "]");
        ASSERT_TRUE(parse_test::parsed_ok(closed)) << tail;
        EXPECT_EQ(closed.scene.background.z, float(std::strtod(tail.c_str(), nullptr))) << tail;
        EXPECT_EQ(std::signbit(closed.scene.background.z), tail[0] == '-') << tail;
    }
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
