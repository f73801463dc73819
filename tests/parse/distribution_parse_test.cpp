// The §9.1 keywords: camera aperture / focaldistance, light radius / angle, material gloss, and
// every error they can give.
#include <cmath>

#include <gtest/gtest.h>

#include "flatten/flatten.h"
#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::error_at;
using parse_test::kRoot;
using parse_test::parse;
using parse_test::parsed_ok;

ParseResult with_root(const std::string& text) { return parse(text + "\n" + kRoot); }

TEST(ParseDistribution, ThinLensFocusedOnTheFocusPoint) {
    const auto r = with_root("camera [ eye 0 0 10 focus 0 0 4 aperture 0.5 ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.camera.aperture, 0.5f);
    const Camera cam = flatten(r.scene).scene.camera;
    EXPECT_FLOAT_EQ(cam.lens_radius, 0.25f);
    EXPECT_FLOAT_EQ(cam.focal_distance, 6.0f);  // |focus − eye|
}

TEST(ParseDistribution, FocalDistanceGivenOverridesTheFocusPoint) {
    const auto r = with_root("camera [ eye 0 0 10 focus 0 0 4 aperture 0.5 focaldistance 2.5 ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_FLOAT_EQ(flatten(r.scene).scene.camera.focal_distance, 2.5f);
    // With `look` there is no focus point: focaldistance says where to focus.
    const auto l = with_root("camera [ look 0 0 -1 aperture 1 focaldistance 3 ]");
    ASSERT_TRUE(parsed_ok(l));
    EXPECT_FLOAT_EQ(flatten(l.scene).scene.camera.focal_distance, 3.0f);
}

TEST(ParseDistribution, NoApertureIsAPinhole) {
    const auto r = with_root("camera [ eye 0 0 10 focus 0 0 4 ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_TRUE(flatten(r.scene).scene.camera.is_pinhole());
    // aperture 0 with look and no focaldistance is fine: nothing needs focusing.
    EXPECT_TRUE(parsed_ok(with_root("camera [ look 0 0 -1 aperture 0 ]")));
}

TEST(ParseDistribution, ApertureLookingAlongLookNeedsAFocalDistance) {
    const auto r = with_root("camera [ look 0 0 -1\n aperture 0.5 ]");
    EXPECT_TRUE(error_at(r, 2, 2, "needs a distance to focus at"));
    // The later of look/focus decides: look after focus leaves nothing to focus on.
    EXPECT_TRUE(error_at(with_root("camera [ focus 0 0 0 aperture 1 look 0 0 -1 ]"), 1, 22, "focaldistance"));
}

TEST(ParseDistribution, BadCameraValues) {
    EXPECT_TRUE(error_at(with_root("camera [ aperture -1 ]"), 1, 19, "'aperture' (the lens diameter) must be >= 0"));
    EXPECT_TRUE(error_at(with_root("camera [ focaldistance 0 ]"), 1, 24, "'focaldistance' must be > 0"));
    EXPECT_TRUE(error_at(with_root("camera [ focaldistance -2 ]"), 1, 24, "'focaldistance' must be > 0"));
}

TEST(ParseDistribution, LightRadiusAndAngle) {
    const auto r = with_root("light [ position 0 5 0 radius 0.5 ]\nlight [ type spotlight radius 2 ]\n"
                             "light [ type directional angle 0.53 ]");
    ASSERT_TRUE(parsed_ok(r));
    ASSERT_EQ(r.scene.lights.size(), 3u);
    EXPECT_EQ(r.scene.lights[0].radius, 0.5f);
    EXPECT_EQ(r.scene.lights[1].radius, 2.0f);
    EXPECT_EQ(r.scene.lights[2].angle_deg, 0.53f);
    const SceneData flat = flatten(r.scene).scene;
    EXPECT_FLOAT_EQ(flat.lights[0].radius, 0.5f);
    EXPECT_NEAR(flat.lights[2].cos_half_angle, std::cos(0.53 * 3.14159265358979 / 360.0), 1e-7);
    EXPECT_EQ(flat.lights[0].cos_half_angle, 1.0f);  // the defaults: no extent
}

TEST(ParseDistribution, BadLightValues) {
    EXPECT_TRUE(error_at(with_root("light [ radius -0.1 ]"), 1, 16, "light 'radius'"));
    EXPECT_TRUE(error_at(with_root("light [ type directional angle 180 ]"), 1, 32, "must be in [0, 180)"));
    EXPECT_TRUE(error_at(with_root("light [ type directional angle -1 ]"), 1, 32, "must be in [0, 180)"));
    // The size keyword of the other kind of light: located at the keyword, whatever the order.
    EXPECT_TRUE(error_at(with_root("light [ radius 1 type directional ]"), 1, 9, "a directional light's size is its 'angle'"));
    EXPECT_TRUE(error_at(with_root("light [ type point angle 2 ]"), 1, 20, "applies to directional lights"));
    // Zero of either is the light without extent, on any type.
    EXPECT_TRUE(parsed_ok(with_root("light [ type directional radius 0 ] light [ angle 0 ]")));
}

TEST(ParseDistribution, Gloss) {
    const auto r = parse("mastersubgraph root [ trans [ object sphere [ reflect 1 1 1 gloss 200 ] ] ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(r.scene.subgraphs[0].children[0].objects[0].material.gloss, 200.0f);
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ object sphere [ gloss 0 ] ] ]"), 1, 53,
                         "'gloss' (the exponent of the blur lobe; large = sharp) must be > 0"));
    EXPECT_TRUE(error_at(parse("mastersubgraph root [ trans [ object sphere [ gloss -3 ] ] ]"), 1, 53, "must be > 0"));
}

}  // namespace
}  // namespace whitted
