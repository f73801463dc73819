// World bounds of transformed unit shapes: they contain every transformed surface point, and
// are tight where the header promises it (sphere, cylinder; cube by its corners).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "shapes/unit_shapes.h"

namespace whitted {
namespace {

constexpr ShapeKind kAllKinds[] = {ShapeKind::Cube, ShapeKind::Cylinder, ShapeKind::Cone, ShapeKind::Sphere};
constexpr ShapeKind kWithEllipsoid[] = {ShapeKind::Cube, ShapeKind::Cylinder, ShapeKind::Cone, ShapeKind::Sphere,
                                        ShapeKind::Ellipsoid};

// Points on the surface of the unit shape, including its rims/corners (where extremes lie).
std::vector<glm::vec3> surface_points(ShapeKind k, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0, 1);
    std::vector<glm::vec3> pts;
    const float two_pi = 2 * std::numbers::pi_v<float>;
    for (int i = 0; i < 4000; ++i) {
        const float a = two_pi * u(rng), y = u(rng) - 0.5f, s = std::sqrt(u(rng));
        switch (k) {
            case ShapeKind::Sphere: {
                const float r = std::sqrt(std::max(0.0f, 0.25f - y * y));
                pts.emplace_back(r * std::cos(a), y, r * std::sin(a));
                break;
            }
            case ShapeKind::Ellipsoid: {  // x² + 4y² + z² = 1
                const float r = std::sqrt(std::max(0.0f, 1.0f - 4 * y * y));
                pts.emplace_back(r * std::cos(a), y, r * std::sin(a));
                break;
            }
            case ShapeKind::Cylinder:
                pts.emplace_back(0.5f * std::cos(a), y, 0.5f * std::sin(a));          // side
                pts.emplace_back(0.5f * std::cos(a), i % 2 ? 0.5f : -0.5f, 0.5f * std::sin(a));  // rims
                pts.emplace_back(0.5f * s * std::cos(a), 0.5f, 0.5f * s * std::sin(a));  // cap
                break;
            case ShapeKind::Cone: {
                const float r = (0.5f - y) / 2;
                pts.emplace_back(r * std::cos(a), y, r * std::sin(a));
                pts.emplace_back(0.5f * std::cos(a), -0.5f, 0.5f * std::sin(a));  // base rim
                break;
            }
            case ShapeKind::Cube: {
                glm::vec3 p(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
                p[i % 3] = (i / 3) % 2 ? 0.5f : -0.5f;
                pts.push_back(p);
                break;
            }
            case ShapeKind::Mesh: break;  // not a unit shape
        }
    }
    if (k == ShapeKind::Cube)
        for (int c = 0; c < 8; ++c) pts.emplace_back(c & 1 ? 0.5f : -0.5f, c & 2 ? 0.5f : -0.5f, c & 4 ? 0.5f : -0.5f);
    if (k == ShapeKind::Cone) pts.emplace_back(0, 0.5f, 0);
    return pts;
}

glm::mat4 random_transform(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-1, 1);
    glm::mat4 m = glm::translate(glm::mat4(1), glm::vec3(5 * u(rng), 5 * u(rng), 5 * u(rng)));
    m = glm::rotate(m, 3.0f * u(rng), glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.01f)));
    glm::vec3 scale(0.2f + 3 * std::abs(u(rng)), 0.2f + 3 * std::abs(u(rng)), 0.2f + 3 * std::abs(u(rng)));
    if (u(rng) < 0) scale.x = -scale.x;  // mirroring
    m = glm::scale(m, scale);
    m = glm::rotate(m, 3.0f * u(rng), glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + glm::vec3(0.01f)));
    return m;
}

TEST(UnitShapeBounds, IdentityIsTheUnitBox) {
    for (ShapeKind k : kAllKinds) {
        const Bounds b = unit_shape_world_bounds(k, glm::mat4(1));
        for (int i = 0; i < 3; ++i) {
            EXPECT_FLOAT_EQ(b.lo[i], -0.5f) << shape_name(k);
            EXPECT_FLOAT_EQ(b.hi[i], 0.5f) << shape_name(k);
        }
    }
}

TEST(UnitShapeBounds, SphereUnderScaleAndRotationIsAnalytic) {
    // Scale x by 2, then rotate 90° about z: the long axis lies along y.
    glm::mat4 m = glm::translate(glm::mat4(1), glm::vec3(1, 2, 3));
    m = glm::rotate(m, std::numbers::pi_v<float> / 2, glm::vec3(0, 0, 1));
    m = glm::scale(m, glm::vec3(2, 1, 1));
    const Bounds b = unit_shape_world_bounds(ShapeKind::Sphere, m);
    const glm::vec3 lo(0.5f, 1.0f, 2.5f), hi(1.5f, 3.0f, 3.5f);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(b.lo[i], lo[i], 1e-5f);
        EXPECT_NEAR(b.hi[i], hi[i], 1e-5f);
    }
    // Scale (1, 3, 1) then rotate 45° about z: the ellipsoid's support along x and y is
    // 0.5·sqrt(1·cos² + 9·sin²) = 0.5·sqrt(5).
    m = glm::rotate(glm::mat4(1), std::numbers::pi_v<float> / 4, glm::vec3(0, 0, 1));
    m = glm::scale(m, glm::vec3(1, 3, 1));
    const Bounds e = unit_shape_world_bounds(ShapeKind::Sphere, m);
    EXPECT_NEAR(e.hi.x, 0.5f * std::sqrt(5.0f), 1e-5f);
    EXPECT_NEAR(e.hi.y, 0.5f * std::sqrt(5.0f), 1e-5f);
    EXPECT_NEAR(e.hi.z, 0.5f, 1e-5f);
}

TEST(UnitShapeBounds, EllipsoidIsAnalytic) {
    // Semi-axes 1, 0.5, 1; under scale (1, 2, 3) they become 1, 1, 3, then moved by (1, 2, 3).
    const Bounds id = unit_shape_world_bounds(ShapeKind::Ellipsoid, glm::mat4(1));
    const glm::vec3 half(1, 0.5f, 1);
    for (int i = 0; i < 3; ++i) {
        EXPECT_FLOAT_EQ(id.lo[i], -half[i]);
        EXPECT_FLOAT_EQ(id.hi[i], half[i]);
    }
    glm::mat4 m = glm::translate(glm::mat4(1), glm::vec3(1, 2, 3));
    m = glm::scale(m, glm::vec3(1, 2, 3));
    const Bounds b = unit_shape_world_bounds(ShapeKind::Ellipsoid, m);
    const glm::vec3 lo(0, 1, 0), hi(2, 3, 6);
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(b.lo[i], lo[i], 1e-5f);
        EXPECT_NEAR(b.hi[i], hi[i], 1e-5f);
    }
    // Rotated 90° about z: the long x axis lies along y.
    const Bounds r = unit_shape_world_bounds(ShapeKind::Ellipsoid,
                                             glm::rotate(glm::mat4(1), std::numbers::pi_v<float> / 2, glm::vec3(0, 0, 1)));
    EXPECT_NEAR(r.hi.x, 0.5f, 1e-5f);
    EXPECT_NEAR(r.hi.y, 1.0f, 1e-5f);
    EXPECT_NEAR(r.hi.z, 1.0f, 1e-5f);
}

TEST(UnitShapeBounds, ContainTransformedSurfacesAndAreTight) {
    std::mt19937 rng(1234);
    for (int trial = 0; trial < 50; ++trial) {
        const glm::mat4 m = random_transform(rng);
        for (ShapeKind k : kWithEllipsoid) {
            const Bounds b = unit_shape_world_bounds(k, m);
            Bounds seen;
            for (const glm::vec3& p : surface_points(k, rng)) {
                const glm::vec3 w(m * glm::vec4(p, 1));
                seen.grow(w);
                for (int i = 0; i < 3; ++i) {
                    const float eps = 1e-5f * (1 + std::abs(w[i]));
                    ASSERT_GE(w[i], b.lo[i] - eps) << shape_name(k) << " trial " << trial;
                    ASSERT_LE(w[i], b.hi[i] + eps) << shape_name(k) << " trial " << trial;
                }
            }
            // Tight: dense samples come within a small fraction of the extent (cube: exact).
            const float tol = k == ShapeKind::Cube ? 1e-4f : 2e-3f;
            for (int i = 0; i < 3; ++i) {
                const float ext = b.hi[i] - b.lo[i];
                EXPECT_LE(seen.lo[i] - b.lo[i], tol * ext) << shape_name(k) << " trial " << trial;
                EXPECT_LE(b.hi[i] - seen.hi[i], tol * ext) << shape_name(k) << " trial " << trial;
            }
        }
    }
}

}  // namespace
}  // namespace whitted
