// What a parse may cost in memory and time whatever the file: warnings past the listed ones are
// counted, not kept (a file of stray brackets once took 400 bytes per byte of text), and the
// parse stops when its cancel flag is set (--timeout, the first Ctrl-C), not at the file's end.
#include <gtest/gtest.h>

#include <atomic>
#include <string>

#include "parse_test_util.h"
#include "render/load_scene.h"

namespace whitted {
namespace {

using parse_test::count;
using parse_test::parse;

TEST(ParseBounds, WarningsPastTheListedOnesAreOnlyCounted) {
    std::string text = parse_test::kRoot;
    for (int i = 0; i < 1000; ++i) text += "[\n";  // lines 2 to 1001, a warning each
    const ParseResult r = parse(text);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), kMaxWarningsListed);
    EXPECT_EQ(r.unlisted_warnings, 1000 - kMaxWarningsListed);
    for (std::size_t i = 0; i < r.diagnostics.size(); ++i) {  // the first ones, in order
        EXPECT_EQ(r.diagnostics[i].loc.line, int(i) + 2);
        EXPECT_NE(r.diagnostics[i].message.find("opens no block"), std::string::npos);
    }
}

// The light's warning is found only after the whole file (lights wait for the dialect), yet it
// comes first in position order, so it is one of the listed, and the last stray bracket is not.
TEST(ParseBounds, TheListedWarningsAreTheFirstInPositionOrderNotTheFirstFound) {
    std::string text = "light [ position 1 1 1 function 0 0 -1 ]\n" + std::string(parse_test::kRoot);
    for (int i = 0; i < 100; ++i) text += "[\n";  // lines 3 to 102
    const ParseResult r = parse(text);
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), kMaxWarningsListed);
    EXPECT_EQ(r.unlisted_warnings, 101 - kMaxWarningsListed);
    EXPECT_EQ(r.diagnostics[0].loc.line, 1);
    EXPECT_NE(r.diagnostics[0].message.find("attenuation"), std::string::npos) << r.diagnostics[0].str();
    for (std::size_t i = 1; i < r.diagnostics.size(); ++i) EXPECT_EQ(r.diagnostics[i].loc.line, int(i) + 2);
}

// Warnings and errors together: every error is kept (up to its own limit) wherever the warnings
// are, and the warnings' limit does not count errors.
TEST(ParseBounds, ErrorsAmongTheWarningsAreAllKept) {
    std::string text = parse_test::kRoot;
    for (int i = 0; i < 60; ++i) text += "[\n";                    // lines 2 to 61
    for (int i = 0; i < 5; ++i) text += "camera [ angle 500 ]\n";  // lines 62 to 66
    const ParseResult r = parse(text);
    EXPECT_EQ(count(r, Severity::Error), 5);
    EXPECT_EQ(count(r, Severity::Warning), int(kMaxWarningsListed));
    EXPECT_EQ(r.unlisted_warnings, 60 - kMaxWarningsListed);
    EXPECT_EQ(r.diagnostics.back().loc.line, 66);
}

// Half a million warnings, 50 of them kept.
TEST(ParseBounds, AFileOfStrayBracketsKeepsItsListOnly) {
    std::string text(500000, '[');
    text += parse_test::kRoot;
    const ParseResult r = parse(text);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.diagnostics.size(), kMaxWarningsListed);
    EXPECT_EQ(r.unlisted_warnings, 500000 - kMaxWarningsListed);
    EXPECT_EQ(r.diagnostics.back().loc.col, int(kMaxWarningsListed));
}

// A scene of about 1 MB whose only error is at its very end.
std::string long_scene_with_a_last_error() {
    std::string text = "mastersubgraph root [\n";
    while (text.size() < (std::size_t(1) << 20))
        text += "  trans [ translate 1 2 3 object sphere [ diffuse 0.5 0.5 0.5 ] ]\n";
    return text + "]\nbackground [ color 1 nan 1 ]\n";
}

TEST(ParseCancel, ASetFlagStopsTheParseBeforeTheEnd) {
    const std::string text = long_scene_with_a_last_error();
    ASSERT_FALSE(parse(text).ok());  // read to its end, the file has its error
    const std::atomic<bool> cancel{true};
    ParseOptions options;
    options.cancel = &cancel;
    const ParseResult r = parse_scene_text(text, "t.sc", options);
    EXPECT_TRUE(r.cancelled);
    EXPECT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].str();  // the end was not reached
    EXPECT_TRUE(r.scene.subgraphs.empty());
}

TEST(ParseCancel, AClearFlagChangesNothing) {
    const std::string text = long_scene_with_a_last_error();
    const std::atomic<bool> cancel{false};
    ParseOptions options;
    options.cancel = &cancel;
    const ParseResult with = parse_scene_text(text, "t.sc", options), without = parse(text);
    EXPECT_FALSE(with.cancelled);
    ASSERT_EQ(with.diagnostics.size(), 1u);
    ASSERT_EQ(without.diagnostics.size(), 1u);
    EXPECT_EQ(with.diagnostics[0].str(), without.diagnostics[0].str());
}

// Scene text from memory (whitted-mpi's ranks) is parsed under the same flag.
TEST(ParseCancel, LoadSceneTextStopsItsParse) {
    const std::atomic<bool> cancel{true};
    LoadOptions options;
    options.cancel = &cancel;
    const LoadResult r = load_scene_text(long_scene_with_a_last_error(), "t.sc", options);
    EXPECT_TRUE(r.cancelled);
    EXPECT_TRUE(r.diagnostics.empty()) << r.diagnostics[0].str();
}

}  // namespace
}  // namespace whitted
