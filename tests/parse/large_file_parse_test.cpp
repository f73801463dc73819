// A file of tens of thousands of blocks read back in full: the parser's fast paths (numbers read
// straight from the text, keywords by hash, the cancel flag looked at every 64 KiB, lines counted
// as the text goes by) give every value and every position exactly, far into a file of megabytes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "parse/number.h"
#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::error_at;
using parse_test::parse;

// What one trans block of the generated file says, as the test wrote it.
struct Written {
    ShapeKind kind;
    std::string translate[3], scale[3], diffuse[3], shine;
    int line = 0, col = 0;  // of its `trans`
};

// A number spelled in one of the forms files use: plain, signed, with or without the integer or
// fraction part, with an exponent, with leading zeros.
std::string spell(std::mt19937& rng) {
    const int whole = int(rng() % 1000), frac = int(rng() % 100000);
    switch (rng() % 8) {
        case 0: return std::to_string(whole);
        case 1: return "-" + std::to_string(whole) + "." + std::to_string(frac);
        case 2: return "." + std::to_string(frac);
        case 3: return std::to_string(whole) + ".";
        case 4: return std::to_string(whole) + "." + std::to_string(frac) + "e-" + std::to_string(rng() % 5);
        case 5: return "+" + std::to_string(whole) + "E+" + std::to_string(rng() % 3);
        case 6: return "000" + std::to_string(whole) + ".5";
        default: return std::to_string(whole) + "." + std::to_string(frac) + std::to_string(frac);  // 9-10 digits
    }
}

float strtod_float(const std::string& s) { return float(std::strtod(s.c_str(), nullptr)); }

constexpr int kBlocks = 40000;  // about 4 MB: some sixty 64 KiB cancel checks, forty thousand lines

struct Generated {
    std::string text;
    std::vector<Written> blocks;
    int lines = 2;  // the line the text ends on (the camera is on line 1)
};

Generated generate() {
    const char* shapes[] = {"cube", "cylinder", "cone", "sphere"};
    const ShapeKind kinds[] = {ShapeKind::Cube, ShapeKind::Cylinder, ShapeKind::Cone, ShapeKind::Sphere};
    const char* breaks[] = {"\n", "\r\n", "\n  # a comment [ with brackets ]\n", "\n\t"};
    std::mt19937 rng(2026);
    Generated g;
    g.text = "camera [ eye 0 45 85 focus 0 0 -5 up 0 1 0 angle 50 ]\nmastersubgraph root [";
    g.blocks.reserve(kBlocks);
    for (int i = 0; i < kBlocks; ++i) {
        Written w;
        const int shape = int(rng() % 4);
        w.kind = kinds[shape];
        for (auto& s : w.translate) s = spell(rng);
        for (auto& s : w.scale) s = std::to_string(1 + rng() % 9) + "." + std::to_string(rng() % 1000);
        for (auto& s : w.diffuse) s = "0." + std::to_string(rng() % 10000);
        w.shine = std::to_string(rng() % 200);
        const int b = int(rng() % 4);
        g.text += breaks[b];
        g.lines += b == 2 ? 2 : 1;
        w.line = g.lines;
        w.col = b == 3 ? 2 : 1;  // after a tab or at the start of the line
        g.text += "trans [ translate " + w.translate[0] + " " + w.translate[1] + " " + w.translate[2] + "  scale " +
                  w.scale[0] + " " + w.scale[1] + " " + w.scale[2] + " object " + shapes[shape] + " [ diffuse " +
                  w.diffuse[0] + " " + w.diffuse[1] + " " + w.diffuse[2] + " shine " + w.shine + " ] ]";
        g.blocks.push_back(std::move(w));
    }
    g.text += "\n";
    ++g.lines;
    return g;
}

const Generated& generated() {
    static const Generated g = generate();
    return g;
}

// Every block, every number: the translation T·S leaves in the last column and the scale on the
// diagonal exactly (products with 0 and 1 only), so each must be the written literal read as
// strtod reads it, rounded to float.
TEST(ParseLargeFile, EveryValueOfFortyThousandBlocksReadsAsStrtodDoes) {
    const Generated& g = generated();
    ASSERT_GT(g.text.size(), std::size_t(3) << 20);
    const ParseResult r = parse(g.text + "]\n");
    ASSERT_TRUE(parse_test::parsed_ok(r));
    ASSERT_EQ(r.scene.subgraphs.size(), 1u);
    const auto& children = r.scene.subgraphs[0].children;
    ASSERT_EQ(children.size(), std::size_t(kBlocks));
    int wrong = 0;
    for (std::size_t i = 0; i < children.size() && wrong < 10; ++i) {
        const TransDesc& t = children[i];
        const Written& w = g.blocks[i];
        const int before = wrong;
        for (int k = 0; k < 3; ++k) {
            wrong += t.matrix[3][k] != strtod_float(w.translate[k]);
            wrong += t.matrix[k][k] != strtod_float(w.scale[k]);
        }
        wrong += t.objects.size() != 1;
        if (t.objects.size() == 1) {
            const ObjectDesc& o = t.objects[0];
            wrong += o.kind != w.kind;
            for (int k = 0; k < 3; ++k) wrong += o.material.diffuse[k] != strtod_float(w.diffuse[k]);
            wrong += o.material.shine != strtod_float(w.shine);
        }
        EXPECT_EQ(wrong, before) << "block " << i << ": translate " << w.translate[0] << " " << w.translate[1] << " "
                                 << w.translate[2];
    }
}

// Every block's position, counted by the test as it wrote the line ends (LF, CRLF, comment lines,
// a tab), and errors after four megabytes located at the line and column where they are.
TEST(ParseLargeFile, PositionsFarIntoTheFileAreExact) {
    const Generated& g = generated();
    const ParseResult ok = parse(g.text + "]\n");
    ASSERT_TRUE(parse_test::parsed_ok(ok));
    const auto& children = ok.scene.subgraphs[0].children;
    ASSERT_EQ(children.size(), std::size_t(kBlocks));
    int wrong = 0;
    for (std::size_t i = 0; i < children.size() && wrong < 10; ++i) {
        const Written& w = g.blocks[i];
        const SourceLoc& at = children[i].loc;
        const bool right = at.file == "t.sc" && at.line == w.line && at.col == w.col;
        wrong += !right;
        EXPECT_TRUE(right) << "block " << i << " at " << at.line << ":" << at.col << ", written at " << w.line << ":"
                           << w.col;
    }
    EXPECT_EQ(g.blocks.back().line, g.lines - 1);
    // "  trans [ translate 1 2 3x ]": the bad number is at column 25 of the line after the last block.
    const ParseResult bad = parse(g.text + "  trans [ translate 1 2 3x ] ]\n");
    EXPECT_TRUE(error_at(bad, g.lines, 25, "expected a number for 'translate', found '3x'"));
    // Without the closing ']': the end of the file is placed just past the last token, the ']' of
    // the last block, on the line before the final line end.
    const std::size_t last_line = g.text.rfind('\n', g.text.size() - 2) + 1;
    EXPECT_TRUE(error_at(parse(g.text), g.lines - 1, int(g.text.size() - 1 - last_line) + 1,
                         "mastersubgraph 'root' block opened at 2:1 is not closed"));
}

// Malformed numbers in a file: each refused with the error that names it, at its place; a number
// beyond float's range with its own message. The same spellings parse_number refuses.
TEST(ParseLargeFile, MalformedNumbersAreRefusedAtTheirPlace) {
    const std::string root = parse_test::kRoot;
    for (const char* bad : {"1.2.3", "1e", "1e+", "+-1", "1f", "0x1p3", ".e1", "1..", "-", ".", "nan", "Infinity",
                            "1,2", "1e5e5", "0b1", "1_000", "--1", "1.0f"}) {
        ASSERT_EQ(parse_number(bad).status, NumberStatus::Invalid) << bad;
        EXPECT_TRUE(error_at(parse(root + "background [ color 1 " + bad + " 1 ]"), 2, 22,
                             "expected a number for 'color', found '" + std::string(bad) + "'"))
            << bad;
    }
    for (const char* big : {"1e39", "-3.4028235e38", "1e-400"}) {
        ASSERT_EQ(parse_number(big).status, NumberStatus::OutOfRange) << big;
        EXPECT_TRUE(error_at(parse(root + "background [ color " + big + " 1 1 ]"), 2, 20,
                             "number '" + std::string(big) + "' for 'color' is out of range"))
            << big;
    }
}

}  // namespace
}  // namespace whitted
