// File structure: blocks, brackets, mastersubgraphs, references, cycles, end of file.
#include <gtest/gtest.h>

#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::error_at;
using parse_test::kRoot;
using parse_test::parse;
using parse_test::parsed_ok;

TEST(ParseStructure, EmptyFileIsAnErrorAtItsStart) {
    // Located like every other error (editors jump to FILE:LINE:COL): at the start of the file.
    for (const char* text : {"", "  \r\n\t\n", "# only a comment\n"}) {
        const auto r = parse(text);
        ASSERT_FALSE(r.ok()) << "'" << text << "'";
        ASSERT_EQ(r.diagnostics.size(), 1u);
        EXPECT_EQ(r.diagnostics[0].loc.file, "t.sc");
        EXPECT_EQ(r.diagnostics[0].loc.line, 1) << "'" << text << "'";
        EXPECT_EQ(r.diagnostics[0].loc.col, 1) << "'" << text << "'";
        EXPECT_NE(r.diagnostics[0].message.find("empty scene file"), std::string::npos);
    }
}

TEST(ParseStructure, MinimalSceneAndPath) {
    const auto r = parse(kRoot);
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.path, "t.sc");
    ASSERT_EQ(r.scene.subgraphs.size(), 1u);
    EXPECT_EQ(r.scene.root, 0);
    EXPECT_EQ(r.scene.subgraphs[0].name, "root");
    EXPECT_EQ(r.scene.subgraphs[0].loc.line, 1);
    EXPECT_EQ(r.scene.background, glm::vec3(0));
    EXPECT_TRUE(r.scene.lights.empty());
}

TEST(ParseStructure, OpeningBracketsAreOptionalAndGluedBracketsSplit) {
    auto r = parse("mastersubgraph root trans object cylinder diffuse 1 0 0 ] ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.subgraphs[0].children.at(0).objects.at(0).material.diffuse,
              glm::vec3(1, 0, 0));
    r = parse("background[color 1 1 1]mastersubgraph root[trans[object cube[diffuse 1 0 0]]]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.background, glm::vec3(1));
}

TEST(ParseStructure, CrlfTabsAndComments) {
    const auto r = parse(
        "# a scene\r\nbackground [\tcolor 1 0 0 ] # red\r\n"
        "mastersubgraph root [ trans [ object cube [ ] ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.background, glm::vec3(1, 0, 0));
}

TEST(ParseStructure, RootIsRequired) {
    const auto r = parse("mastersubgraph a [ trans [ object cube [ ] ] ]");
    const Diagnostic* e = parse_test::first_error(r);
    ASSERT_NE(e, nullptr);
    EXPECT_EQ(e->loc.file, "t.sc");
    EXPECT_EQ(e->loc.line, 1);
    EXPECT_EQ(e->loc.col, 1);
    EXPECT_EQ(e->message, "no 'mastersubgraph root' in the file (it defines 'a'): root is the scene and is required");
    EXPECT_FALSE(parse("mastersubgraph Root [ ]").ok());  // names are case-sensitive
}

TEST(ParseStructure, DuplicateNameIsAnErrorAtTheSecondName) {
    EXPECT_TRUE(
        error_at(parse("mastersubgraph a [ ]\nmastersubgraph root [ ]\n\n  mastersubgraph a [ ]"),
                 4, 18, "duplicate mastersubgraph 'a' (first defined at 1:1)"));
}

TEST(ParseStructure, MissingNames) {
    // The '[' there is ignored (spec §1), so the name is missing where the ']' stands.
    EXPECT_TRUE(error_at(parse("mastersubgraph [ ]"), 1, 18,
                         "expected a name after 'mastersubgraph', found ']'"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ subgraph ] ]"), 1, 40,
                         "expected a subgraph name after 'subgraph', found ']'"));
}

TEST(ParseStructure, ForwardReferencesAndInstancing) {
    const auto r = parse(
        "mastersubgraph root [ trans [ subgraph leg ] trans [ translate 1 0 0 subgraph leg ] ]\n"
        "mastersubgraph leg [ trans [ object cylinder [ ] ] ]\n"
        "mastersubgraph unused [ trans [ object cone [ ] ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.subgraphs.size(), 3u);
    EXPECT_EQ(r.scene.root, 0);
    EXPECT_EQ(r.scene.find_subgraph("leg"), 1);
    const SubgraphRef& ref = r.scene.subgraphs[0].children[1].subgraphs.at(0);
    EXPECT_EQ(ref.name, "leg");
    EXPECT_EQ(ref.loc.line, 1);
    EXPECT_EQ(ref.loc.col, 79);  // the name token
}

TEST(ParseStructure, UndefinedReferenceIsAnErrorAtTheName) {
    EXPECT_TRUE(error_at(parse("mastersubgraph root [\n  trans [ subgraph table ] ]"), 2, 20,
                         "undefined subgraph 'table'"));
}

TEST(ParseStructure, CyclesAreNamed) {
    EXPECT_TRUE(
        error_at(parse("mastersubgraph root [ trans [ subgraph a ] ]\n"
                       "mastersubgraph a [ trans [ subgraph b ] ]\n"
                       "mastersubgraph b [ trans [ object cube [ ] ]\n trans [ subgraph a ] ]"),
                 4, 19, "subgraph cycle: a -> b -> a"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ subgraph root ] ]"), 1, 40,
                         "subgraph cycle: root -> root"));
    // A diamond is not a cycle.
    EXPECT_TRUE(
        parsed_ok(parse("mastersubgraph root [ trans [ subgraph a subgraph b ] ]\n"
                        "mastersubgraph a [ trans [ subgraph c ] ]\n"
                        "mastersubgraph b [ trans [ subgraph c ] ]\n"
                        "mastersubgraph c [ trans [ object cube [ ] ] ]")));
}

TEST(ParseStructure, LongChainOfSubgraphsIsFine) {
    // Deep instancing must not overflow the stack of the cycle check.
    std::string text = "mastersubgraph root [ trans [ subgraph s0 ] ]\n";
    const int n = 20000;
    for (int i = 0; i < n; ++i)
        text +=
            "mastersubgraph s" + std::to_string(i) + " [ trans [ " +
            (i + 1 < n ? "subgraph s" + std::to_string(i + 1) : std::string("object cube [ ]")) +
            " ] ]\n";
    EXPECT_TRUE(parsed_ok(parse(text)));
    text += "mastersubgraph extra [ trans [ subgraph s0 ] ]\n";
    text.replace(text.rfind("object cube [ ]"), 15, "subgraph root");  // s19999 -> root: a cycle
    const auto r = parse(text);
    ASSERT_FALSE(r.ok());
    EXPECT_NE(parse_test::first_error(r)->message.find("subgraph cycle: root -> s0 -> s1 -> "),
              std::string::npos);
}

TEST(ParseStructure, TransDoesNotNest) {
    EXPECT_TRUE(
        error_at(parse("mastersubgraph root [\n  trans [ translate 1 0 0\n    trans [ ] ] ]"), 3, 5,
                 "'trans' inside the trans block opened at 2:3"));
}

TEST(ParseStructure, TopLevelTransInAFileWithMastersubgraphsMixesDialects) {
    // A top-level trans makes a Brown/Tufts file (tests/parse/dialect_parse_test.cpp); beside a
    // mastersubgraph it is an error, in either mode.
    for (bool lenient : {false, true})
        EXPECT_TRUE(error_at(parse(std::string(kRoot) + "trans [ object cube ]", lenient), 2, 1,
                             "this file mixes two dialects: 'trans' at top level is the Brown/Tufts form, "
                             "but 'mastersubgraph' at 1:1"));
}

TEST(ParseStructure, EndOfFileInsideABlock) {
    EXPECT_TRUE(error_at(parse("mastersubgraph root [\n  trans [\n    object cube [\n"), 3, 18,
                         "unexpected end of file: object block opened at 3:5 is not closed"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [\n  trans [ object cube ]\n"), 2, 24,
                         "unexpected end of file: trans block opened at 2:3 is not closed"));
    EXPECT_TRUE(error_at(parse("camera [ eye 1 2 3"), 1, 19,
                         "unexpected end of file: camera block opened at 1:1 is not closed"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ ] light\n"), 1, 30,
                         "unexpected end of file: light block opened at 1:25"));
}

// The warning for a '[' that opens no block, at line:col.
::testing::AssertionResult stray_open_warned(const ParseResult& r, int line, int col) {
    for (const auto& d : r.diagnostics)
        if (d.severity == Severity::Warning && d.loc.line == line && d.loc.col == col &&
            d.message.find("opens no block and is ignored") != std::string::npos)
            return ::testing::AssertionSuccess();
    auto failure = ::testing::AssertionFailure() << "no stray '[' warning at " << line << ":" << col;
    for (const auto& d : r.diagnostics) failure << "\n  " << d.str();
    return failure;
}

TEST(ParseStructure, StrayClosingBracketIsAnError) {
    EXPECT_TRUE(error_at(parse(std::string(kRoot) + "  ]"), 2, 3, "unexpected ']' at top level"));
}

TEST(ParseStructure, StrayOpeningBracketsAreIgnoredWithAWarning) {
    // Spec §1: the reference ignores '[' wherever it appears; we do too, and say where it was.
    auto r = parse("[ " + std::string(kRoot));
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_TRUE(stray_open_warned(r, 1, 1));

    r = parse("camera [ [ eye 1 2 [ 3 ]\nmastersubgraph [ root [ trans [ object [ cube ] ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_TRUE(stray_open_warned(r, 1, 10));  // a second '[' after a block's own
    EXPECT_TRUE(stray_open_warned(r, 1, 20));  // among a keyword's numbers
    EXPECT_TRUE(stray_open_warned(r, 2, 16));  // between 'mastersubgraph' and its name
    EXPECT_TRUE(stray_open_warned(r, 2, 40));  // between 'object' and its type
    EXPECT_EQ(r.scene.camera.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(parse_test::count(r, Severity::Warning), 4);

    // Ignoring it leaves the brackets unbalanced: the error that follows names the open block.
    r = parse("mastersubgraph root [ trans [ [ object cube ] ]");
    EXPECT_TRUE(stray_open_warned(r, 1, 31));
    EXPECT_TRUE(error_at(r, 1, 48, "mastersubgraph 'root' block opened at 1:1 is not closed"));
}

TEST(ParseStructure, UnknownKeywordsNameTheBlock) {
    EXPECT_TRUE(error_at(parse("sky [ ]\n" + std::string(kRoot)), 1, 1,
                         "unknown keyword 'sky' in top-level block (expected one of: background, "
                         "camera, light, mastersubgraph)"));
    EXPECT_TRUE(error_at(
        parse("mastersubgraph root [ object cube ]"), 1, 23,
        "'object' cannot stand directly in mastersubgraph 'root' block: it belongs inside a 'trans [ ... ]' block"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ objekt cube ]"), 1, 23,
                         "unknown keyword 'objekt' in mastersubgraph 'root' block (expected one of: trans)"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ shear 0 1 0 0.6 0 ] ]"), 1, 31,
                         "unknown keyword 'shear' in trans block"));
    EXPECT_TRUE(
        error_at(parse("camera [ fov 40 ]"), 1, 10, "unknown keyword 'fov' in camera block"));
    EXPECT_TRUE(
        error_at(parse("light [ intensity 0 ]"), 1, 9, "unknown keyword 'intensity' in light block"));
    EXPECT_TRUE(error_at(parse("background [ colour 1 1 1 ]"), 1, 14,
                         "unknown keyword 'colour' in background block (did you mean 'color'?) "
                         "(expected one of: color)"));
}

TEST(ParseStructure, WarningsAndEveryErrorInPositionOrder) {
    const auto r =
        parse("background [ color 1, 1 1 ]\nbackground [ color x 1 1 ] camera [ angle 0 ]");
    ASSERT_EQ(r.diagnostics.size(), 3u);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.diagnostics[1].severity, Severity::Error);
    EXPECT_EQ(r.diagnostics[1].loc.line, 2);
    EXPECT_EQ(r.diagnostics[1].loc.col, 20);  // 'x'
    EXPECT_EQ(r.diagnostics[2].severity, Severity::Error);
    EXPECT_EQ(r.diagnostics[2].loc.col, 43);  // the angle's 0
}

TEST(ParseStructure, UnreadableFile) {
    const auto r = parse_scene_file("/nonexistent/dir/x.sc");
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Error);
    EXPECT_EQ(r.diagnostics[0].loc.file, "/nonexistent/dir/x.sc");
    EXPECT_EQ(r.diagnostics[0].loc.line, 0);
    EXPECT_NE(r.diagnostics[0].message.find("cannot read"), std::string::npos);
    EXPECT_FALSE(parse_scene_file("/").ok());  // a directory
}

}  // namespace
}  // namespace whitted
