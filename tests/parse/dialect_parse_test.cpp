// scene-format.md §9.4 rule by rule, each with a small file of its own: the Brown/Tufts dialect
// (light `number`, implicit root, directional-by-omission and its defaults, `blend`, `meshfile`,
// mixing), and the historical keywords (ellipsoid, cactus, cow, alpha, velocity, angularrate,
// shear still refused).
#include <gtest/gtest.h>

#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::count;
using parse_test::error_at;
using parse_test::kRoot;
using parse_test::parse;
using parse_test::parsed_ok;

ParseResult parse_at_time(std::string_view text, float time) {
    ParseOptions options;
    options.time = time;
    return parse_scene_text(text, "t.sc", options);
}

// --- the Brown/Tufts dialect -------------------------------------------------------------------

TEST(ParseDialect, LabsFilesAreTheLabsDialect) {
    const auto r = parse(kRoot);
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.dialect, Dialect::Labs);
    EXPECT_STREQ(dialect_name(Dialect::BrownTufts), "Brown/Tufts");
}

TEST(ParseDialect, LightNumberIsAnIdentifier) {
    const auto r = parse("light [ number 0 color 1 0 0 position 1 2 3 ]\n"
                         "light [ number 7 color 0 1 0 position 4 5 6 ]\n"
                         "trans [ object cube [ ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.dialect, Dialect::BrownTufts);
    ASSERT_EQ(r.scene.lights.size(), 2u);
    EXPECT_EQ(r.scene.lights[0].color, glm::vec3(1, 0, 0));
    EXPECT_EQ(r.scene.lights[1].position, glm::vec3(4, 5, 6));
    EXPECT_EQ(r.scene.lights[1].type, LightType::Point);
    EXPECT_TRUE(error_at(parse("light [ number x ]"), 1, 16, "expected a number for 'number'"));
}

TEST(ParseDialect, LightDefaultsOfThatCourse) {
    // A Brown/Tufts light that says nothing else: white, at (3, 3, 3), not attenuated.
    const auto r = parse("light [ number 0 ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.scene.lights.size(), 1u);
    const LightDesc& l = r.scene.lights[0];
    EXPECT_EQ(l.type, LightType::Point);
    EXPECT_EQ(l.position, glm::vec3(3, 3, 3));
    EXPECT_EQ(l.color, glm::vec3(1, 1, 1));
    EXPECT_EQ(l.falloff, glm::vec3(1, 0, 0));
    // The same light in a labs file keeps the labs' defaults (§6).
    const auto labs = parse(std::string("light [ type point ]\n") + kRoot);
    ASSERT_TRUE(parsed_ok(labs));
    EXPECT_EQ(labs.scene.lights.at(0).position, glm::vec3(1, 1, 1));
    EXPECT_EQ(labs.scene.lights.at(0).color, glm::vec3(0.5f));
}

TEST(ParseDialect, DirectionWithoutPositionIsDirectional) {
    const auto r = parse("light [ number 0 color 0.8 0.8 0.8 direction 0 -1 -1 ]\n"   // directional
                         "light [ number 1 position 0 5 0 direction 0 -1 0 ]\n"         // a point light
                         "light [ number 2 type spotlight direction 0 -1 0 ]\n"         // said so
                         "trans [ object sphere [ ] ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.scene.lights.size(), 3u);
    EXPECT_EQ(r.scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(r.scene.lights[0].direction, glm::vec3(0, -1, -1));
    EXPECT_EQ(r.scene.lights[0].color, glm::vec3(0.8f));
    EXPECT_EQ(r.scene.lights[1].type, LightType::Point);
    EXPECT_EQ(r.scene.lights[2].type, LightType::Spot);
    EXPECT_EQ(r.scene.lights[2].position, glm::vec3(3, 3, 3));
    // In a labs file a direction alone does not change the type (§6: type point by default).
    const auto labs = parse(std::string("light [ direction 0 -1 -1 ]\n") + kRoot);
    ASSERT_TRUE(parsed_ok(labs));
    EXPECT_EQ(labs.scene.lights.at(0).type, LightType::Point);
    // A zero direction is still an error for the directional light it makes.
    EXPECT_TRUE(error_at(parse("light [ number 0 direction 0 0 0 ]"), 1, 18, "light 'direction' is zero"));
}

TEST(ParseDialect, TopLevelTransBlocksAreAnImplicitRoot) {
    const auto r = parse("camera [ eye 0 0 5 ]\n"
                         "trans [ translate 1 0 0 object sphere [ diffuse 1 0 0 ] ]\n"
                         "trans [ object cube [ ] object cone [ ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.dialect, Dialect::BrownTufts);
    ASSERT_EQ(r.scene.subgraphs.size(), 1u);
    ASSERT_EQ(r.scene.root, 0);
    const SubgraphDesc& root = r.scene.subgraphs[0];
    EXPECT_EQ(root.name, "root");
    ASSERT_EQ(root.children.size(), 2u);
    EXPECT_EQ(root.children[0].matrix[3], glm::vec4(1, 0, 0, 1));
    EXPECT_EQ(root.children[0].objects.at(0).kind, ShapeKind::Sphere);
    EXPECT_EQ(root.children[1].objects.size(), 2u);
}

TEST(ParseDialect, MixingTheTwoDialectsIsAnError) {
    // The second dialect's first word is the error, naming the first one's; reported once.
    EXPECT_TRUE(error_at(parse(std::string(kRoot) + "light [ number 0 ]\nlight [ number 1 ]"), 2, 9,
                         "this file mixes two dialects: 'light [ number ...' is the Brown/Tufts form, but "
                         "'mastersubgraph' at 1:1 made it a SceneView/Ray labs file"));
    EXPECT_EQ(count(parse(std::string(kRoot) + "light [ number 0 ]\nlight [ number 1 ]"), Severity::Error), 1);
    EXPECT_TRUE(error_at(parse("trans [ object cube [ ] ]\n" + std::string(kRoot)), 2, 1,
                         "this file mixes two dialects: 'mastersubgraph' is the SceneView/Ray labs form, but "
                         "'trans' at top level at 1:1 made it a Brown/Tufts file"));
}

TEST(ParseDialect, BlendIsReadInBrownTuftsFilesOnly) {
    const auto r = parse("trans [ object cube [ texture a.bmp 1 1 blend 0.8 ] object cube [ ] ]");
    ASSERT_TRUE(parsed_ok(r));
    const auto& objects = r.scene.subgraphs.at(0).children.at(0).objects;
    ASSERT_TRUE(objects.at(0).material.blend.has_value());
    EXPECT_FLOAT_EQ(*objects[0].material.blend, 0.8f);
    EXPECT_TRUE(objects[0].material.texture->loose_lookup);
    EXPECT_FALSE(objects.at(1).material.blend.has_value());
    EXPECT_TRUE(error_at(parse("trans [ object cube [ blend 1.5 ] ]"), 1, 29, "'blend'"));
    // Not a word of the labs' format.
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ object cube [ blend 0.5 ] ] ]"), 1, 45,
                         "unknown keyword 'blend' in object block"));
}

TEST(ParseDialect, MeshfileIsSkippedWithAWarning) {
    const auto r = parse("trans [ object mesh [ meshfile Mesh/cow.sm diffuse 0.6 0.1 0 ] ]\n"
                         "trans [ object sphere [ ] ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(count(r, Severity::Warning), 1);
    EXPECT_EQ(r.diagnostics[0].loc.line, 1);
    EXPECT_EQ(r.diagnostics[0].loc.col, 16);
    EXPECT_NE(r.diagnostics[0].message.find("'mesh'"), std::string::npos);
    EXPECT_TRUE(r.scene.subgraphs.at(0).children.at(0).objects.empty());
    EXPECT_EQ(r.scene.subgraphs.at(0).children.at(1).objects.size(), 1u);
}

// --- historical keywords -----------------------------------------------------------------------

TEST(ParseHistorical, Ellipsoid) {
    const auto r = parse("mastersubgraph root [ trans [ object ellipsoid [ diffuse 1 0 0 ] ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.subgraphs.at(0).children.at(0).objects.at(0).kind, ShapeKind::Ellipsoid);
}

TEST(ParseHistorical, CactusAndCowAreSkippedWithAWarningEach) {
    const auto r = parse("mastersubgraph root [ trans [\n"
                         "  object cactus [ diffuse 0 1 0 ]\n"
                         "  object cow [ ]\n"
                         "  object cube [ ] ] ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(count(r, Severity::Warning), 2);
    EXPECT_EQ(r.diagnostics[0].loc.line, 2);
    EXPECT_NE(r.diagnostics[0].message.find("'cactus'"), std::string::npos);
    EXPECT_EQ(r.diagnostics[1].loc.line, 3);
    EXPECT_NE(r.diagnostics[1].message.find("'cow'"), std::string::npos);
    const auto& objects = r.scene.subgraphs.at(0).children.at(0).objects;
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_EQ(objects[0].kind, ShapeKind::Cube);
}

TEST(ParseHistorical, AlphaWarnsOncePerFileAndChangesNothing) {
    const auto with = parse("mastersubgraph root [ trans [\n"
                            "  object cube [ alpha 0.9 diffuse 1 0 0 ]\n"
                            "  object cube [ alpha 0.5 ] ] ]");
    ASSERT_TRUE(parsed_ok(with));
    ASSERT_EQ(count(with, Severity::Warning), 1);
    EXPECT_EQ(with.diagnostics[0].loc.line, 2);
    EXPECT_EQ(with.diagnostics[0].loc.col, 17);
    EXPECT_NE(with.diagnostics[0].message.find("'alpha'"), std::string::npos);
    const auto& m = with.scene.subgraphs.at(0).children.at(0).objects.at(0).material;
    EXPECT_EQ(m.diffuse, glm::vec3(1, 0, 0));
    EXPECT_EQ(m.transparent, glm::vec3(0));
}

// The matrices of `velocity` / `angularrate` against the file written with translate / rotate.
TEST(ParseHistorical, VelocityAndAngularRateAtTimeZeroAndOne) {
    const char* animated = "mastersubgraph root [ trans [ translate 1 2 3 velocity 0.5 -1 2 "
                           "angularrate 0 1 1 30 scale 2 1 1 object cube [ ] ] ]";
    const char* still = "mastersubgraph root [ trans [ translate 1 2 3 scale 2 1 1 object cube [ ] ] ]";
    const char* moved = "mastersubgraph root [ trans [ translate 1 2 3 translate 0.5 -1 2 "
                        "rotate 0 1 1 30 scale 2 1 1 object cube [ ] ] ]";
    auto matrix = [](const ParseResult& r) { return r.scene.subgraphs.at(0).children.at(0).matrix; };
    const auto at0 = parse_at_time(animated, 0), at1 = parse_at_time(animated, 1);
    ASSERT_TRUE(parsed_ok(at0));
    ASSERT_TRUE(parsed_ok(at1));
    EXPECT_TRUE(at0.diagnostics.empty());
    EXPECT_EQ(matrix(at0), matrix(parse(still)));  // exactly: t = 0 is the file without them
    EXPECT_EQ(matrix(at1), matrix(parse(moved)));
    // At t = 2 the translation doubles: column 3 is (1, 2, 3) + 2·(0.5, −1, 2).
    const auto at2 = parse_at_time("mastersubgraph root [ trans [ translate 1 2 3 velocity 0.5 -1 2 object cube [ ] ] ]", 2);
    EXPECT_EQ(matrix(at2)[3], glm::vec4(2, 0, 7, 1));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ angularrate 0 0 0 10 ] ]"), 1, 31,
                         "'angularrate' axis is zero"));
}

TEST(ParseHistorical, ShearIsStillRefused) {
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ shear 0 1 0 0.6 0 object cube [ ] ] ]"), 1, 31,
                         "unknown keyword 'shear' in trans block"));
    const auto lenient = parse("mastersubgraph root [ trans [ shear 0 1 0 0.6 0 object cube [ ] ] ]", true);
    ASSERT_TRUE(parsed_ok(lenient));
    EXPECT_NE(lenient.diagnostics.at(0).message.find("the 5 numbers after it"), std::string::npos);
}

}  // namespace
}  // namespace whitted
