// Every error at once: after an error the parser skips to the end of the block it is in and goes
// on, so one run reports all the problems of a file (up to 20, then a count), in position order;
// "did you mean" for near misses; binary files are named for what they are.
#include <gtest/gtest.h>

#include <string>

#include "parse/suggest.h"
#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::count;
using parse_test::parse;

std::vector<const Diagnostic*> errors(const ParseResult& r) {
    std::vector<const Diagnostic*> out;
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Error) out.push_back(&d);
    return out;
}

TEST(ParseRecovery, FivePlantedErrorsAreAllReportedInOrder) {
    const char* text =
        "camera [ eye 0 0 x angle 45 ]\n"                         // 1: 'x' at 1:18
        "light [ type spotligth position 0 5 0 ]\n"              // 2: spotligth at 2:14
        "mastersubgraph root [\n"                                 // 3
        "  trans [ translate 1 1 ]\n"                             // 4: ']' for a number at 4:25
        "  trans [ object cube [ difuse 1 0 0 shine 5 ] ]\n"     // 5: difuse at 5:25
        "  trans [ object sphere [ shininess 20 ] ]\n"           // 6: shininess at 6:27
        "]\n";
    const auto r = parse(text);
    const auto e = errors(r);
    ASSERT_EQ(e.size(), 5u);
    const int want[][2] = {{1, 18}, {2, 14}, {4, 25}, {5, 25}, {6, 27}};
    for (std::size_t i = 0; i < e.size(); ++i) {
        EXPECT_EQ(e[i]->loc.line, want[i][0]) << e[i]->str();
        EXPECT_EQ(e[i]->loc.col, want[i][1]) << e[i]->str();
    }
    EXPECT_NE(e[0]->message.find("expected a number for 'eye', found 'x'"), std::string::npos);
    EXPECT_NE(e[1]->message.find("unknown light type 'spotligth' (did you mean 'spotlight'?)"), std::string::npos);
    EXPECT_NE(e[2]->message.find("expected a number for 'translate', found ']'"), std::string::npos);
    EXPECT_NE(e[3]->message.find("unknown keyword 'difuse' in object block (did you mean 'diffuse'?)"),
              std::string::npos);
    EXPECT_NE(e[4]->message.find("unknown keyword 'shininess' in object block (did you mean 'shine'?)"),
              std::string::npos);
    EXPECT_FALSE(r.ok());
}

TEST(ParseRecovery, AnErrorSkipsTheRestOfItsBlockOnly) {
    // The bad number ends the object block; the next object and the light after are still read.
    const auto r = parse("mastersubgraph root [ trans [\n"
                         "  object cube [ diffuse 1 zz 1 foo 9 9 9 ]\n"
                         "  object sphere [ diffus 1 1 1 ] ] ]\n"
                         "light [ colr 1 1 1 ]");
    const auto e = errors(r);
    ASSERT_EQ(e.size(), 3u);
    EXPECT_EQ(e[0]->loc.line, 2);  // zz; `foo` in the skipped rest of the block is not reported
    EXPECT_EQ(e[1]->loc.line, 3);
    EXPECT_NE(e[1]->message.find("did you mean 'diffuse'?"), std::string::npos);
    EXPECT_EQ(e[2]->loc.line, 4);
    EXPECT_NE(e[2]->message.find("did you mean 'color'?"), std::string::npos);
}

// `object cube [ … ]` straight in a subgraph (a missing trans) is one error that says where it
// belongs, not a second one for 'cube'; the unknown word's own block goes with it, so the next
// line is read as usual. A valid keyword after an unknown one is not swallowed.
TEST(ParseRecovery, AMisplacedObjectIsOneErrorWithItsBlock) {
    const auto r = parse("mastersubgraph root [\n"
                         "  object cube [ diffuse 0 1 0 ]\n"
                         "  frobnicate trans [ object sphere [ shine 5 ] ]\n"
                         "  trans [ object cone [ difuse 1 1 1 ] ]\n"
                         "]\n");
    const auto e = errors(r);
    ASSERT_EQ(e.size(), 3u);
    EXPECT_EQ(e[0]->loc.line, 2);
    EXPECT_EQ(e[0]->loc.col, 3);
    EXPECT_NE(e[0]->message.find("'object' cannot stand directly in mastersubgraph 'root' block: it belongs "
                                 "inside a 'trans [ ... ]' block"),
              std::string::npos)
        << e[0]->str();
    EXPECT_EQ(e[1]->loc.line, 3);  // frobnicate: its next word is a keyword of the block, read as one
    EXPECT_NE(e[1]->message.find("unknown keyword 'frobnicate'"), std::string::npos) << e[1]->str();
    EXPECT_EQ(e[2]->loc.line, 4);
    EXPECT_NE(e[2]->message.find("did you mean 'diffuse'?"), std::string::npos) << e[2]->str();
}

TEST(ParseRecovery, TooManyErrorsEndWithACount) {
    std::string text = "mastersubgraph root [ trans [ object cube [\n";
    for (int i = 0; i < 30; ++i) text += "  bogus" + std::to_string(i) + " 1\n";
    text += "] ] ]\n";
    const auto r = parse(text);
    ASSERT_EQ(count(r, Severity::Error), 21);
    for (int i = 0; i < 20; ++i) EXPECT_EQ(r.diagnostics[i].loc.line, i + 2);
    const Diagnostic& last = r.diagnostics.back();
    EXPECT_NE(last.message.find("10 more errors not listed"), std::string::npos) << last.str();
    EXPECT_EQ(last.loc.line, 22);  // the first unlisted one
}

TEST(ParseRecovery, EndOfFileIsReportedOnce) {
    const auto r = parse("mastersubgraph root [ trans [ object cube [ diffuse 1 1");
    ASSERT_EQ(count(r, Severity::Error), 1);
    EXPECT_NE(r.diagnostics[0].message.find("found end of file"), std::string::npos);
}

TEST(ParseRecovery, DidYouMean) {
    EXPECT_EQ(closest_word("shininess", "ambient, diffuse, shine, ior"), "shine");
    EXPECT_EQ(closest_word("difuse", "ambient, diffuse, shine, ior"), "diffuse");
    EXPECT_EQ(closest_word("spotligth", "point, directional, spotlight"), "spotlight");
    EXPECT_EQ(closest_word("mastersubgrph", "background, camera, light, mastersubgraph"), "mastersubgraph");
    EXPECT_EQ(closest_word("sky", "background, camera, light, mastersubgraph"), "");
    EXPECT_EQ(closest_word("fov", "eye, look, focus, up, angle"), "");  // 2 edits from 'eye' is not close for 3 letters
    EXPECT_EQ(closest_word("Cube", "cube, cylinder"), "cube");
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
    EXPECT_EQ(edit_distance("", "abc"), 3);
    EXPECT_EQ(edit_distance("spotligth", "spotlight"), 2);
    // In messages: unknown object types too.
    const auto r = parse("mastersubgraph root [ trans [ object spere [ ] ] ]");
    ASSERT_EQ(count(r, Severity::Error), 1);
    EXPECT_NE(r.diagnostics[0].message.find("unknown object type 'spere' (did you mean 'sphere'?)"),
              std::string::npos);
}

TEST(ParseRecovery, BinaryFilesAreNotSceneFiles) {
    const std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10", 20);
    auto r = parse(png);
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].str(), "t.sc:1:1: error: this is not a scene file (it looks like a PNG image)");
    r = parse(std::string("\xFF\xD8\xFF\xE0\0\x10JFIF", 10));
    EXPECT_NE(r.diagnostics.at(0).message.find("a JPEG image"), std::string::npos);
    r = parse(std::string("BM\x36\0\0\0\0\0", 8));
    EXPECT_NE(r.diagnostics.at(0).message.find("a BMP image"), std::string::npos);
    r = parse(std::string("abc\0def", 7));
    EXPECT_NE(r.diagnostics.at(0).message.find("binary data"), std::string::npos);
    // Text that begins like a signature is still text: a scene with non-ASCII words is a scene.
    EXPECT_TRUE(parse("BM [ ]").diagnostics.at(0).message.find("unknown keyword 'BM'") != std::string::npos);
    EXPECT_TRUE(parse("# caf\xC3\xA9\n" + std::string(parse_test::kRoot)).ok());
}

}  // namespace
}  // namespace whitted
