// Camera blocks (scene-format.md §5).
#include <gtest/gtest.h>

#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::error_at;
using parse_test::kRoot;
using parse_test::parse;
using parse_test::parsed_ok;

CameraDesc camera_of(const std::string& text) {
    const auto r = parse(text + "\n" + kRoot);
    EXPECT_TRUE(parsed_ok(r)) << text;
    return r.scene.camera;
}

TEST(ParseCamera, DefaultsWithoutACameraBlock) {
    const CameraDesc c = camera_of("");
    EXPECT_EQ(c.eye, glm::vec3(0, 0, 1));
    EXPECT_EQ(c.view_direction(), glm::vec3(0, 0, -1));
    EXPECT_EQ(c.up, glm::vec3(0, 1, 0));
    EXPECT_EQ(c.angle_deg, 60.0f);
}

TEST(ParseCamera, AllKeywords) {
    const CameraDesc c =
        camera_of("camera [ eye 1 2 3 look 0 0 -2 up 0 1 1 angle 45 near-far 0.5 200 ]");
    EXPECT_EQ(c.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(c.view_direction(), glm::vec3(0, 0, -2));
    EXPECT_EQ(c.up, glm::vec3(0, 1, 1));  // kept as written; orthonormalised by the renderer
    EXPECT_EQ(c.angle_deg, 45.0f);
    EXPECT_EQ(c.near_plane, 0.5f);
    EXPECT_EQ(c.far_plane, 200.0f);
    EXPECT_EQ(c.loc.line, 1);
}

TEST(ParseCamera, SeveralBlocksMergeKeywordByKeyword) {
    const CameraDesc c = camera_of("camera [ eye 1 2 3 angle 30 ]\ncamera [ angle 45 ]");
    EXPECT_EQ(c.eye, glm::vec3(1, 2, 3));
    EXPECT_EQ(c.angle_deg, 45.0f);
    EXPECT_EQ(c.loc.line, 2);  // the last block
}

TEST(ParseCamera, LaterOfLookAndFocusWins) {
    CameraDesc c = camera_of("camera [ focus 0 0 0 look 1 0 0 ]");
    EXPECT_FALSE(c.use_focus);
    EXPECT_EQ(c.view_direction(), glm::vec3(1, 0, 0));
    c = camera_of("camera [ look 1 0 0 focus 0 0 -3 ]");
    EXPECT_TRUE(c.use_focus);
    EXPECT_EQ(c.view_direction(), glm::vec3(0, 0, -4));  // focus - default eye (0 0 1)
    c = camera_of("camera [ look 1 0 0 ] camera [ focus 0 0 0 ] camera [ look 0 0 -1 ]");
    EXPECT_FALSE(c.use_focus);
}

TEST(ParseCamera, FocusUsesTheEyeAtTheEndOfTheFile) {
    const CameraDesc c = camera_of("camera [ focus 0 0 0 ]\ncamera [ eye 0 0 5 ]");
    EXPECT_EQ(c.view_direction(), glm::vec3(0, 0, -5));
}

TEST(ParseCamera, AngleMustBeBetween0And180) {
    EXPECT_TRUE(error_at(parse("camera [ angle 0 ]\n" + std::string(kRoot)), 1, 16, "'angle'"));
    EXPECT_TRUE(error_at(parse("camera [\n angle 180 ]\n" + std::string(kRoot)), 2, 8, "'angle'"));
    EXPECT_TRUE(error_at(parse("camera [ angle -5 ]\n" + std::string(kRoot)), 1, 16, "'angle'"));
    EXPECT_EQ(camera_of("camera [ angle 179.5 ]").angle_deg, 179.5f);
}

TEST(ParseCamera, UpParallelToViewIsAnErrorAtUp) {
    // Looking straight down with the default up: located at the camera block (no `up` written).
    EXPECT_TRUE(error_at(parse("\n  camera [ eye 0 5 0 focus 0 0 0 ]\n" + std::string(kRoot)), 2, 3,
                         "parallel to the view direction"));
    EXPECT_TRUE(error_at(parse("camera [ look 0 0 -1\n   up 0 0 3 ]\n" + std::string(kRoot)), 2, 4,
                         "parallel"));
    // Parallel only with the final eye (set in a later block): still caught, at `up`.
    EXPECT_TRUE(error_at(
        parse("camera [ focus 0 0 0 up 0 1 0 ]\ncamera [ eye 0 3 0 ]\n" + std::string(kRoot)), 1,
        22, "parallel"));
    // Not parallel: fine, up need not be perpendicular.
    EXPECT_TRUE(parsed_ok(parse("camera [ look 0 -1 -1 up 0 1 0 ]\n" + std::string(kRoot))));
}

TEST(ParseCamera, ZeroViewDirectionIsAnError) {
    EXPECT_TRUE(error_at(parse("camera [ eye 1 1 1\n focus 1 1 1 ]\n" + std::string(kRoot)), 2, 2,
                         "equals 'eye'"));
    EXPECT_TRUE(error_at(parse("camera [ look 0 0 0 ]\n" + std::string(kRoot)), 1, 10,
                         "'look' direction is zero"));
}

}  // namespace
}  // namespace whitted
