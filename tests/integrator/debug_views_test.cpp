// The debugging views (--mode normals, --mode depth) against values worked out by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "integrator/integrator.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

using test::SceneBuilder;
using test::translate_scale;

glm::vec3 view(const Scene& scene, RenderMode mode, glm::vec3 origin, glm::vec3 toward) {
    RayCounts counts;
    // A batch of one camera sample through the mode's integrator.
    CameraBatch one;
    one.rays[0] = Ray{origin, glm::normalize(toward - origin)};
    one.active = 1;
    glm::vec3 out[kPacketSize];
    make_integrator(scene, scene.data.camera, {mode, 5})->radiance(one, Sampler(), out, counts);
    return out[0];
}

void expect_color(glm::vec3 got, glm::vec3 want, float tol = 1e-4f) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// The normals view shows the outward unit normal n as the colour (n + 1) / 2.
TEST(DebugViews, NormalsShowTheOutwardNormal) {
    const glm::vec3 eye(0, 0, 1);  // the builder's camera
    {
        // A sphere of radius 1 at (0, 0, −5): at the point c + (1, 2, 2)/3, facing the eye, the
        // normal is (1, 2, 2)/3 and the colour (2/3, 5/6, 5/6).
        SceneBuilder b;
        b.add(ShapeKind::Sphere, translate_scale({0, 0, -5}, glm::vec3(2)), Material{});
        const Scene s = b.build();
        expect_color(view(s, RenderMode::Normals, eye, glm::vec3(1, 2, 2) / 3.0f + glm::vec3(0, 0, -5)),
                     {2.0f / 3.0f, 5.0f / 6.0f, 5.0f / 6.0f});
        // Straight ahead: the pole facing the eye, n = (0, 0, 1).
        expect_color(view(s, RenderMode::Normals, eye, {0, 0, -5}), {0.5f, 0.5f, 1.0f});
        // Seen from below (from −y): the bottom pole, n = (0, −1, 0).
        expect_color(view(s, RenderMode::Normals, {0, -10, -5}, {0, 0, -5}), {0.5f, 0.0f, 0.5f});
        // Nothing hit: black.
        expect_color(view(s, RenderMode::Normals, eye, {0, 10, -5}), {0, 0, 0});
    }
    {
        // An ellipsoid, radii (2, 1, 1), at (0, 0, −5): the point c + (2·0.6, 0, 0.8) lies on it,
        // and its normal is the gradient of x²/4 + y² + z²: (0.6/2, 0, 0.8), normalized.
        SceneBuilder b;
        b.add(ShapeKind::Sphere, translate_scale({0, 0, -5}, {4, 2, 2}), Material{});
        const Scene s = b.build();
        const glm::vec3 n = glm::normalize(glm::vec3(0.3f, 0.0f, 0.8f));
        expect_color(view(s, RenderMode::Normals, eye, glm::vec3(1.2f, 0.0f, -4.2f)), 0.5f * (n + 1.0f));
    }
}

// The depth view shows 1 − (d − near) / (far − near), for the distance d along the ray, near
// and far being the distances from the eye to the nearest and farthest points of the scene's
// bounding box; nothing hit is black.
TEST(DebugViews, DepthIsWhiteAtTheNearestPointAndFadesWithDistance) {
    // A unit cube at (0, 0, −2) (z from −2.5 to −1.5) before a wall at (0, 0, −10), 20 × 20 × 1
    // (z from −10.5 to −9.5). The eye at (0, 0, 1): near = 2.5 (to z = −1.5); far = the corner
    // (±10, ±10, −10.5): √(100 + 100 + 11.5²) = √332.25.
    SceneBuilder b;
    b.add(ShapeKind::Cube, translate_scale({0, 0, -2}, glm::vec3(1)), Material{});
    b.add(ShapeKind::Cube, translate_scale({0, 0, -10}, {20, 20, 1}), Material{});
    const Scene s = b.build();
    const glm::vec3 eye(0, 0, 1);
    const float near = 2.5f, far = std::sqrt(332.25f);
    // Straight ahead: the cube's front face at distance 2.5, the nearest point: white.
    expect_color(view(s, RenderMode::Depth, eye, {0, 0, -1}), glm::vec3(1.0f), 1e-3f);
    // Along (1, 0, −2): past the cube (x = 1.25 > 0.5 at z = −1.5), onto the wall at z = −9.5,
    // 10.5 down in z, so at distance 10.5 · √5 / 2.
    const float d = 10.5f * std::sqrt(5.0f) / 2.0f;
    expect_color(view(s, RenderMode::Depth, eye, eye + glm::vec3(1, 0, -2)), glm::vec3(1.0f - (d - near) / (far - near)),
                 1e-3f);
    // Nothing hit: black.
    expect_color(view(s, RenderMode::Depth, eye, {0, 0, 5}), glm::vec3(0.0f));
}

}  // namespace
}  // namespace whitted
