// Light blocks (scene-format.md §6).
#include <gtest/gtest.h>

#include "parse/falloff.h"
#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::count;
using parse_test::error_at;
using parse_test::kRoot;
using parse_test::parse;
using parse_test::parsed_ok;

ParseResult with_root(const std::string& text) { return parse(text + "\n" + kRoot); }

TEST(ParseLight, EmptyBlockIsADefaultPointLight) {
    const auto r = with_root("light [ ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.scene.lights.size(), 1u);
    const LightDesc& l = r.scene.lights[0];
    EXPECT_EQ(l.type, LightType::Point);
    EXPECT_EQ(l.position, glm::vec3(1, 1, 1));
    EXPECT_EQ(l.direction, glm::vec3(0, -1, 0));
    EXPECT_EQ(l.color, glm::vec3(0.5f));
    EXPECT_EQ(l.falloff, glm::vec3(1, 0, 0));
    EXPECT_EQ(l.aperture_deg, 180.0f);
    EXPECT_EQ(l.exponent, 1.0f);
    EXPECT_EQ(l.loc.line, 1);
    EXPECT_EQ(l.loc.col, 1);
    EXPECT_EQ(r.scene.ambient_intensity, glm::vec3(1.0f));  // the documented default I_a
}

TEST(ParseLight, AllKeywords) {
    const auto r = with_root(
        "light [ type spotlight position 1 2 3 direction 0 0 -1 color 2 1 0.5 function 1 0.5 0.25 "
        "aperture 30 exponent 4 ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.scene.lights.size(), 1u);
    const LightDesc& l = r.scene.lights[0];
    EXPECT_EQ(l.type, LightType::Spot);
    EXPECT_EQ(l.position, glm::vec3(1, 2, 3));
    EXPECT_EQ(l.direction, glm::vec3(0, 0, -1));
    EXPECT_EQ(l.color, glm::vec3(2, 1, 0.5f));  // above 1 is legal
    EXPECT_EQ(l.falloff, glm::vec3(1, 0.5f, 0.25f));
    EXPECT_EQ(l.aperture_deg, 30.0f);
    EXPECT_EQ(l.exponent, 4.0f);
    EXPECT_EQ(r.diagnostics.size(), 0u);
}

TEST(ParseLight, AmbientOnlyBlockAddsNoLightAndLastAmbientWins) {
    const auto r = with_root(
        "light [ ambient .2 .3 .4 ]\nlight [ type directional ]\n"
        "light [ ambient .5 .5 .5 color 1 1 1 ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.scene.lights.size(), 2u);
    EXPECT_EQ(r.scene.lights[0].type, LightType::Directional);
    EXPECT_EQ(r.scene.lights[1].color, glm::vec3(1));
    EXPECT_EQ(r.scene.ambient_intensity, glm::vec3(0.5f));
}

TEST(ParseLight, UnknownTypeIsAnErrorAtTheValue) {
    EXPECT_TRUE(
        error_at(with_root("light [ type area ]"), 1, 14,
                 "unknown light type 'area' (expected one of: point, directional, spotlight)"));
    EXPECT_TRUE(error_at(with_root("light [ type ]"), 1, 14, "expected a light type"));
}

TEST(ParseLight, ZeroDirectionIsAnErrorForDirectionalAndSpot) {
    EXPECT_TRUE(error_at(with_root("light [ type directional\n  direction 0 0 0 ]"), 2, 3,
                         "'direction' is zero"));
    // The type may come after the direction.
    EXPECT_TRUE(error_at(with_root("light [ direction 0 0 0 type spotlight ]"), 1, 9,
                         "'direction' is zero"));
    // A point light ignores its direction.
    EXPECT_TRUE(parsed_ok(with_root("light [ direction 0 0 0 ]")));
}

TEST(ParseLight, ApertureAndExponentRanges) {
    EXPECT_TRUE(error_at(with_root("light [ aperture 0 ]"), 1, 18, "'aperture'"));
    EXPECT_TRUE(error_at(with_root("light [ aperture 180.5 ]"), 1, 18, "'aperture'"));
    EXPECT_TRUE(error_at(with_root("light [ exponent -1 ]"), 1, 18, "'exponent' must be >= 0"));
    EXPECT_TRUE(parsed_ok(with_root("light [ type spotlight aperture 180 exponent 0 ]")));
}

TEST(ParseLight, FalloffThatCanReachZeroWarnsOnceAtFunction) {
    const auto r = with_root("light [ position 0 0 0\n function 0 0 0 ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(count(r, Severity::Warning), 1);
    EXPECT_EQ(r.diagnostics[0].loc.line, 2);
    EXPECT_EQ(r.diagnostics[0].loc.col, 2);
    EXPECT_NE(r.diagnostics[0].message.find("function"), std::string::npos);
    // Normal falloffs: no warning.
    EXPECT_EQ(with_root("light [ function 0 0.2 0 ]").diagnostics.size(), 0u);
    EXPECT_EQ(with_root("light [ function 0 0 0.1 ]").diagnostics.size(), 0u);
    // Directional lights are not attenuated: nothing to warn about.
    EXPECT_EQ(with_root("light [ type directional function 0 0 0 ]").diagnostics.size(), 0u);
}

TEST(ParseLight, FalloffCanBeNonpositive) {
    // c + l·d + q·d² <= 0 for some d > 0?
    EXPECT_TRUE(falloff_can_be_nonpositive({0, 0, 0}));  // 0 everywhere
    EXPECT_TRUE(falloff_can_be_nonpositive({-1, 0, 0}));
    EXPECT_TRUE(falloff_can_be_nonpositive({1, -1, 0}));      // 0 at d = 1
    EXPECT_TRUE(falloff_can_be_nonpositive({1, 0, -0.01f}));  // negative beyond d = 10
    EXPECT_TRUE(falloff_can_be_nonpositive({-1, 0, 1}));      // -1 near d = 0
    EXPECT_TRUE(falloff_can_be_nonpositive({1, -3, 1}));      // minimum 1 - 9/4 at d = 1.5
    EXPECT_FALSE(falloff_can_be_nonpositive({1, -1, 1}));     // minimum 1 - 1/4 at d = 0.5
    EXPECT_FALSE(falloff_can_be_nonpositive({1, 0, 0}));
    EXPECT_FALSE(falloff_can_be_nonpositive({0, 0.2f, 0}));  // 0.2·d > 0 for d > 0
    EXPECT_FALSE(falloff_can_be_nonpositive({0, 0, 0.1f}));
    EXPECT_FALSE(falloff_can_be_nonpositive({0.5f, 0, 0}));
}

}  // namespace
}  // namespace whitted
