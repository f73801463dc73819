// Lenient mode: unknown keywords and object types are skipped with warnings (scene-format.md §2).
#include <gtest/gtest.h>

#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::count;
using parse_test::error_at;
using parse_test::kRoot;
using parse_test::parse;
using parse_test::parsed_ok;

TEST(ParseLenient, UnknownKeywordIsSkippedWithItsNumbers) {
    const auto r =
        parse("mastersubgraph root [ trans [\n  object cube [ opacity 0.9 diffuse 1 0 0 ] ] ]", true);
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.diagnostics[0].loc.line, 2);
    EXPECT_EQ(r.diagnostics[0].loc.col, 17);
    EXPECT_NE(r.diagnostics[0].message.find("'opacity'"), std::string::npos);
    EXPECT_NE(r.diagnostics[0].message.find("object block"), std::string::npos);
    const auto& obj = r.scene.subgraphs[0].children.at(0).objects.at(0);
    EXPECT_EQ(obj.material.diffuse, glm::vec3(1, 0, 0));  // parsing went on after the skip
}

TEST(ParseLenient, UnknownKeywordsInEveryBlock) {
    const auto r = parse(
        "sky 1 2 3\nbackground [ gradient 1 color 0 0 1 ]\ncamera [ fov 40 angle 30 ]\n"
        "light [ intensity 0 color 1 1 1 ]\n"
        "mastersubgraph root [ comment trans [ shear 0 1 0 0.65 0 wobble 1 2 3 "
        "spin 0 1 0 2 translate 1 0 0 object cube [ ] ] ]",
        true);
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(count(r, Severity::Warning), 8);
    EXPECT_EQ(r.scene.background, glm::vec3(0, 0, 1));
    EXPECT_EQ(r.scene.camera.angle_deg, 30.0f);
    ASSERT_EQ(r.scene.lights.size(), 1u);
    EXPECT_EQ(r.scene.lights[0].color, glm::vec3(1));
    const auto& trans = r.scene.subgraphs[0].children.at(0);
    EXPECT_EQ(trans.matrix[3], glm::vec4(1, 0, 0, 1));  // only the translate counted
    EXPECT_EQ(trans.objects.size(), 1u);
}

TEST(ParseLenient, UnknownKeywordWithABracketedBlock) {
    const auto r = parse(
        "mastersubgraph root [ trans [ physics [ mass 1 [ inner ] drag 2 ] object cube [ ] ] ]",
        true);
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.subgraphs[0].children.at(0).objects.size(), 1u);
    EXPECT_EQ(count(r, Severity::Warning), 1);
}

TEST(ParseLenient, UnknownObjectTypeIsSkippedWithItsBlock) {
    const auto r = parse(
        "mastersubgraph root [ trans [\n"
        "  object teapot [ diffuse 1 0 0 extra [ 1 ] ]\n"
        "  object sphere [ diffuse 0 1 0 ] ] ]",
        true);
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_EQ(r.diagnostics[0].loc.line, 2);
    EXPECT_EQ(r.diagnostics[0].loc.col, 10);
    EXPECT_NE(r.diagnostics[0].message.find("'teapot'"), std::string::npos);
    const auto& objects = r.scene.subgraphs[0].children.at(0).objects;
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].kind, ShapeKind::Sphere);
}

TEST(ParseLenient, UnknownObjectTypeWithoutOpeningBracket) {
    // As with known types, the object's block ends at the next ']'.
    const auto r =
        parse("mastersubgraph root [ trans [ object teapot diffuse 1 1 1 ] object cube ] ] ]", true);
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.subgraphs[0].children.at(0).objects.size(), 1u);
}

TEST(ParseLenient, SomeErrorsStayErrors) {
    EXPECT_TRUE(
        error_at(parse("mastersubgraph root [ trans [ object cube [ diffuse 1 x 1 ] ] ]", true), 1,
                 55, "expected a number for 'diffuse', found 'x'"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ trans [ ] ] ]", true), 1, 31,
                         "trans blocks do not nest"));
    EXPECT_TRUE(error_at(parse("light [ type area ]\n" + std::string(kRoot), true), 1, 14,
                         "unknown light type"));
    // Skipping a bracketed block still needs its ']'.
    EXPECT_TRUE(error_at(parse(std::string(kRoot) + "sky [ 1 2", true), 2, 10,
                         "unexpected end of file: 'sky' block opened at 2:1 is not closed"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ object blob [ ", true), 1, 44,
                         "unexpected end of file: object block opened at 1:31"));
}

}  // namespace
}  // namespace whitted
