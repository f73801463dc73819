// The viewer's camera navigation, without a display: each gesture against hand-computed cameras.
#if __has_include("camera_navigation.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "camera_navigation.h"

#include <cmath>

#include <gtest/gtest.h>

#include "flatten/flatten.h"

namespace whitted::viewer {
namespace {

constexpr float kEps = 1e-4f;

CameraDesc looking_at_origin_from(glm::vec3 eye) {
    CameraDesc c;
    c.eye = eye;
    c.focus = glm::vec3(0.0f);
    c.use_focus = true;
    c.angle_deg = 40;
    return c;
}

void expect_near(glm::vec3 a, glm::vec3 b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

// Where point p lands on an image `height` pixels tall, relative to its centre, in pixels (right, down).
glm::vec2 project(const CameraDesc& c, glm::vec3 p, int height) {
    const Camera cam = make_camera(c);
    const glm::vec3 d = p - cam.eye;
    const float z = glm::dot(d, cam.forward);
    const float k = 0.5f * float(height) / cam.tan_half_fov;
    return {glm::dot(d, cam.right) / z * k, -glm::dot(d, cam.up) / z * k};
}

TEST(CameraNavigation, ALookCameraOrbitsAboutThePointOfItsViewLineNearestTheOrigin) {
    CameraDesc c;
    c.eye = {3, 0, 5};
    c.look = {0, 0, -2};
    const CameraDesc n = navigable(c);
    EXPECT_TRUE(n.use_focus);
    expect_near(n.focus, {3, 0, 0});  // the origin projects 5 units ahead
    expect_near(make_camera(n).forward, make_camera(c).forward);
    c.look = {0, 0, 1};  // looking away from the origin: one unit ahead
    expect_near(navigable(c).focus, {3, 0, 6});
    const CameraDesc f = looking_at_origin_from({1, 2, 3});
    expect_near(navigable(f).focus, f.focus);
}

TEST(CameraNavigation, OrbitTurnsAboutUpThroughTheFocusKeepingTheDistance) {
    const CameraDesc c = looking_at_origin_from({0, 0, 5});
    // 90 degrees to the right (360 px at 0.25 degree/px): the camera goes round to the left, -x.
    const CameraDesc o = orbit(c, 90.0f / kOrbitDegreesPerPixel, 0);
    expect_near(o.eye, {-5, 0, 0});
    expect_near(o.focus, c.focus);
    expect_near(o.up, c.up);
    // A full turn comes back.
    expect_near(orbit(c, 360.0f / kOrbitDegreesPerPixel, 0).eye, c.eye, 1e-3f);
    // Dragging down by 30 degrees raises the camera by 30 degrees over the focus.
    const CameraDesc t = orbit(c, 0, 30.0f / kOrbitDegreesPerPixel);
    expect_near(t.eye, {0, 5 * std::sin(glm::radians(30.0f)), 5 * std::cos(glm::radians(30.0f))});
    EXPECT_NEAR(focus_distance(t), 5.0f, kEps);
}

TEST(CameraNavigation, OrbitStopsOneDegreeShortOfThePoles) {
    const CameraDesc c = looking_at_origin_from({0, 0, 5});
    for (float dy : {1000.0f, -1000.0f}) {
        const CameraDesc o = orbit(c, 0, dy);
        const float cos_polar = glm::dot(glm::normalize(o.eye - o.focus), glm::vec3(0, 1, 0));
        EXPECT_NEAR(std::acos(cos_polar), glm::radians(dy > 0 ? 1.0f : 179.0f), 1e-3f);
        EXPECT_NEAR(focus_distance(o), 5.0f, kEps);
    }
}

TEST(CameraNavigation, PanMovesTheFocusPointWithTheMouse) {
    const CameraDesc c = looking_at_origin_from({1, 2, 6});
    const int H = 480;
    const CameraDesc p = pan(c, 30, -12, H);
    // The old focus point is now 30 px right of the centre and 12 px above it.
    const glm::vec2 at = project(p, c.focus, H);
    EXPECT_NEAR(at.x, 30.0f, 1e-2f);
    EXPECT_NEAR(at.y, -12.0f, 1e-2f);
    EXPECT_NEAR(focus_distance(p), focus_distance(c), kEps);
    expect_near(p.eye - c.eye, p.focus - c.focus);
}

TEST(CameraNavigation, DollyMovesTheEyeATenthOfTheWayPerStep) {
    const CameraDesc c = looking_at_origin_from({0, 0, 10});
    expect_near(dolly(c, 1).eye, {0, 0, 9});
    expect_near(dolly(c, 2).eye, {0, 0, 8.1f});
    expect_near(dolly(c, -1).eye, {0, 0, 10 / 0.9f});
    const CameraDesc far_in = dolly(c, 1000);  // never reaches (or passes) the focus
    EXPECT_GT(far_in.eye.z, 0.0f);
    EXPECT_GT(focus_distance(far_in), 0.0f);
}

TEST(CameraNavigation, FieldOfViewStepsByTenPercentWithinLimits) {
    const CameraDesc c = looking_at_origin_from({0, 0, 10});
    EXPECT_NEAR(change_fov(c, 1).angle_deg, 40 / 1.1f, kEps);
    EXPECT_NEAR(change_fov(c, -2).angle_deg, 40 * 1.21f, 1e-3f);
    EXPECT_EQ(change_fov(c, 100).angle_deg, 1.0f);
    EXPECT_EQ(change_fov(c, -100).angle_deg, 170.0f);
}

TEST(CameraNavigation, FlyKeysMoveEyeAndFocusAlongTheCamerasAxes) {
    const CameraDesc c = looking_at_origin_from({0, 0, 10});
    const std::pair<char, glm::vec3> keys[] = {{'w', {0, 0, -1}}, {'s', {0, 0, 1}}, {'a', {-1, 0, 0}},
                                               {'d', {1, 0, 0}},  {'q', {0, -1, 0}}, {'e', {0, 1, 0}}};
    for (const auto& [key, dir] : keys) {
        const CameraDesc f = fly(c, key);
        expect_near(f.eye, c.eye + dir * 1.0f);  // a tenth of the focus distance
        expect_near(f.focus, c.focus + dir * 1.0f);
    }
    expect_near(fly(c, 'x').eye, c.eye);
}

}  // namespace
}  // namespace whitted::viewer
#endif
