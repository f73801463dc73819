// The ellipsoid of scene-format.md §9.4, x² + 4y² + z² = 1: hand-computed hits and normals, the
// same under a transform (through the instance and the BVH), and the course's ray set checked
// against the implicit equation and an independent quadratic in double.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "accel/bvh.h"
#include "accel/instance_geometry.h"
#include "flatten/flatten.h"
#include "shapes/unit_shape_math.h"
#include "shapes/unit_shapes.h"

namespace whitted {
namespace {

ShapeSpan hit(glm::vec3 o, glm::vec3 d) { return intersect_unit_shape(ShapeKind::Ellipsoid, Ray{o, d}); }

void expect_vec(glm::vec3 a, glm::vec3 b, float eps = 1e-5f) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

float implicit(glm::dvec3 p) { return float(p.x * p.x + 4 * p.y * p.y + p.z * p.z); }

TEST(Ellipsoid, AxisRaysMeetTheSemiAxes) {
    // Semi-axes 1 (x), 0.5 (y), 1 (z).
    ShapeSpan s = hit({0, 0, 5}, {0, 0, -1});
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.t[0], 4.0f, 1e-5f);
    EXPECT_NEAR(s.t[1], 6.0f, 1e-5f);
    s = hit({5, 0, 0}, {-1, 0, 0});
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.t[0], 4.0f, 1e-5f);
    EXPECT_NEAR(s.t[1], 6.0f, 1e-5f);
    s = hit({0, 5, 0}, {0, -1, 0});
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.t[0], 4.5f, 1e-5f);
    EXPECT_NEAR(s.t[1], 5.5f, 1e-5f);
    // A non-unit direction: t is in the ray's own parametrisation.
    s = hit({0, 0, 5}, {0, 0, -2});
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.t[0], 2.0f, 1e-5f);
    // Outside the unit sphere of the other shapes but inside the ellipsoid: x = 0.9 hits.
    EXPECT_EQ(hit({0.9f, 0, 5}, {0, 0, -1}).count, 2);
    EXPECT_EQ(hit({1.01f, 0, 5}, {0, 0, -1}).count, 0);
    EXPECT_EQ(hit({0, 0.51f, 5}, {0, 0, -1}).count, 0);
}

TEST(Ellipsoid, NormalsAreTheGradient) {
    expect_vec(unit_shape_normal(ShapeKind::Ellipsoid, kPartSide, {1, 0, 0}), {1, 0, 0});
    expect_vec(unit_shape_normal(ShapeKind::Ellipsoid, kPartSide, {0, 0.5f, 0}), {0, 1, 0});
    expect_vec(unit_shape_normal(ShapeKind::Ellipsoid, kPartSide, {0, 0, -1}), {0, 0, -1});
    // A ray along x at y = 0.25: x² = 1 − 4/16 = 3/4, so it enters at x = −√3/2, where the
    // gradient (x, 4y, z) = (−√3/2, 1, 0) has length √7/2.
    const ShapeSpan s = hit({-5, 0.25f, 0}, {1, 0, 0});
    ASSERT_EQ(s.count, 2);
    const float x = std::sqrt(3.0f) / 2;
    EXPECT_NEAR(s.t[0], 5 - x, 1e-5f);
    EXPECT_NEAR(s.t[1], 5 + x, 1e-5f);
    const glm::vec3 p = Ray{{-5, 0.25f, 0}, {1, 0, 0}}.at(s.t[0]);
    const float len = std::sqrt(7.0f) / 2;
    expect_vec(unit_shape_normal(ShapeKind::Ellipsoid, s.part[0], p), {-x / len, 1 / len, 0});
}

TEST(Ellipsoid, TextureCoordinatesAreTheSpheres) {
    const glm::vec2 top = unit_shape_uv(ShapeKind::Ellipsoid, kPartSide, {0, 0.5f, 0});
    EXPECT_NEAR(top.y, 0.0f, 1e-6f);  // v = 0 at the top pole
    const glm::vec2 front = unit_shape_uv(ShapeKind::Ellipsoid, kPartSide, {0, 0, 1});
    EXPECT_NEAR(front.x, 0.25f, 1e-6f);  // φ = π/2
    EXPECT_NEAR(front.y, 0.5f, 1e-6f);
    const glm::vec2 side = unit_shape_uv(ShapeKind::Ellipsoid, kPartSide, {-1, 0, 0});
    EXPECT_NEAR(side.x, 0.0f, 1e-6f);  // φ = π: u = 0 (the seam)
}

TEST(Ellipsoid, TransformedHitsAndNormals) {
    // Rotated 90° about z, then moved to (0, 0, −3): the long x axis now lies along y, so in the
    // world it is y² + 4x² + (z + 3)² = 1.
    glm::mat4 m = glm::translate(glm::mat4(1), glm::vec3(0, 0, -3));
    m = glm::rotate(m, std::numbers::pi_v<float> / 2, glm::vec3(0, 0, 1));
    std::vector<Instance> instances{make_instance(m, ShapeKind::Ellipsoid, 0)};
    const Bvh bvh = build_bvh(instances);
    struct Case {
        glm::vec3 o, d;
        float t;
        glm::vec3 n;
    } cases[] = {
        {{0, 5, -3}, {0, -1, 0}, 4.0f, {0, 1, 0}},    // the top at y = 1
        {{5, 0, -3}, {-1, 0, 0}, 4.5f, {1, 0, 0}},    // the side at x = 0.5
        {{0, 0, 5}, {0, 0, -1}, 7.0f, {0, 0, 1}},     // the front at z = −2
    };
    for (const Case& c : cases) {
        Hit h;
        ASSERT_TRUE(intersect_nearest(bvh, instances, Ray{c.o, c.d}, 0.0f, 1e30f, h));
        EXPECT_NEAR(h.t, c.t, 1e-5f);
        const glm::vec3 p = to_object_space(instances[0], Ray{c.o, c.d}).at(h.t);
        expect_vec(normal_to_world(instances[0], unit_shape_normal(ShapeKind::Ellipsoid, h.part, p)), c.n);
    }
    Hit h;
    EXPECT_FALSE(intersect_nearest(bvh, instances, Ray{{0.55f, 0, 5}, {0, 0, -1}}, 0.0f, 1e30f, h));
}

// The course harness's rays (tests/shapes/course_intersections_test.cpp builds the same set):
// every hit lies on x² + 4y² + z² = 1, its normal is the normalised gradient, and the hits are
// those of the quadratic solved here independently in double.
double radical_inverse(int n, int b) {
    const double inv = 1.0 / b;
    double f = inv, r = 0;
    for (; n > 0; n /= b, f *= inv) r += (n % b) * f;
    return r;
}

TEST(Ellipsoid, CourseRaysAgainstTheImplicitEquation) {
    const double pi = std::numbers::pi;
    auto unit = [pi](double a, double b) {
        return glm::dvec3(std::sin(pi * a) * std::cos(2 * pi * b), std::sin(pi * a) * std::sin(2 * pi * b),
                          std::cos(pi * a));
    };
    int hits = 0, inside = 0;
    for (int i = 13; i <= 1650; ++i) {
        auto h = [i](int b) { return radical_inverse(i + 1, b); };
        const glm::dvec3 o = h(11) * unit(h(2), h(3)), d = unit(h(5), h(7));
        // Independent: a t² + b t + c = 0 with the ellipsoid's own coefficients.
        const double a = d.x * d.x + 4 * d.y * d.y + d.z * d.z;
        const double b = 2 * (o.x * d.x + 4 * o.y * d.y + o.z * d.z);
        const double c = o.x * o.x + 4 * o.y * o.y + o.z * o.z - 1;
        const double disc = b * b - 4 * a * c;
        const auto s = shape_math::intersect<double>(ShapeKind::Ellipsoid, o, d);
        ASSERT_EQ(s.count == 2, disc >= 0) << "ray " << i;
        if (s.count == 0) continue;
        const double r0 = (-b - std::sqrt(disc)) / (2 * a), r1 = (-b + std::sqrt(disc)) / (2 * a);
        EXPECT_NEAR(s.t[0], r0, 1e-9) << "ray " << i;
        EXPECT_NEAR(s.t[1], r1, 1e-9) << "ray " << i;
        if (c < 0) {  // starting inside: behind, then ahead
            ++inside;
            EXPECT_LT(s.t[0], 0.0) << "ray " << i;
            EXPECT_GT(s.t[1], 0.0) << "ray " << i;
        }
        for (int k = 0; k < 2; ++k) {
            if (!(s.t[k] > 0)) continue;
            ++hits;
            const glm::dvec3 p = o + s.t[k] * d;
            EXPECT_NEAR(implicit(p), 1.0f, 1e-6f) << "ray " << i;
            const glm::dvec3 n = shape_math::normal<double>(ShapeKind::Ellipsoid, s.part[k], p);
            const glm::dvec3 g = glm::normalize(glm::dvec3(p.x, 4 * p.y, p.z));
            EXPECT_NEAR(glm::length(n - g), 0.0, 1e-12) << "ray " << i;
            // The float instance the renderer uses agrees to float precision.
            const auto sf = shape_math::intersect<float>(ShapeKind::Ellipsoid, glm::vec3(o), glm::vec3(d));
            ASSERT_EQ(sf.count, 2) << "ray " << i;
            EXPECT_NEAR(sf.t[k], s.t[k], 1e-5 * (1 + std::abs(s.t[k]))) << "ray " << i;
        }
    }
    EXPECT_GT(inside, 1000);  // the origins lie in the unit ball, mostly inside the ellipsoid
    EXPECT_GE(hits, inside);
}

}  // namespace
}  // namespace whitted
