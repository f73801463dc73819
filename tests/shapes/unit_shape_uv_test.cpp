// Texture coordinates (scene-format.md §8) at points with hand-computed (u, v).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shapes/unit_shapes.h"

namespace whitted {
namespace {

const float kBelowOne = std::nextafter(1.0f, 0.0f);

void expect_uv(ShapeKind k, ShapePart part, glm::vec3 p, float u, float v) {
    const glm::vec2 uv = unit_shape_uv(k, part, p);
    EXPECT_NEAR(uv.x, u, 1e-6f) << shape_name(k) << " part " << int(part) << " u";
    EXPECT_NEAR(uv.y, v, 1e-6f) << shape_name(k) << " part " << int(part) << " v";
    EXPECT_TRUE(uv.x >= 0 && uv.x < 1 && uv.y >= 0 && uv.y < 1) << uv.x << " " << uv.y;
}

TEST(UnitShapeUv, Sphere) {
    // u = 0.5 − φ/(2π), φ = atan2(z, x); v = 0.5 − asin(2y)/π.
    expect_uv(ShapeKind::Sphere, kPartSide, {0, 0, 0.5f}, 0.25f, 0.5f);   // φ = π/2
    expect_uv(ShapeKind::Sphere, kPartSide, {0.5f, 0, 0}, 0.5f, 0.5f);    // φ = 0
    expect_uv(ShapeKind::Sphere, kPartSide, {0, 0, -0.5f}, 0.75f, 0.5f);  // φ = −π/2
    expect_uv(ShapeKind::Sphere, kPartSide, {0, 0.5f, 0}, 0.5f, 0.0f);    // top pole: v = 0
    // y = 0.25: asin(0.5) = π/6 → v = 1/3; x = z > 0: φ = π/4 → u = 3/8.
    const float h = std::sqrt(0.1875f / 2);
    expect_uv(ShapeKind::Sphere, kPartSide, {h, 0.25f, h}, 0.375f, 1.0f / 3);
    // φ = ±π at the seam: u is 0, or 1 clamped below 1.
    expect_uv(ShapeKind::Sphere, kPartSide, {-0.5f, 0, 0}, 0.0f, 0.5f);
    expect_uv(ShapeKind::Sphere, kPartSide, {-0.5f, 0, -0.0f}, kBelowOne, 0.5f);
    // The bottom pole (v = 1) clamps; a point a hair above the top pole must not give NaN.
    expect_uv(ShapeKind::Sphere, kPartSide, {0, -0.5f, 0}, 0.5f, kBelowOne);
    expect_uv(ShapeKind::Sphere, kPartSide, {0, 0.5000001f, 0}, 0.5f, 0.0f);
    expect_uv(ShapeKind::Sphere, kPartSide, {0, -0.5000001f, 0}, 0.5f, kBelowOne);
}

TEST(UnitShapeUv, Sides) {
    // u = 0.5 − φ/(2π), v = 0.5 − y.
    expect_uv(ShapeKind::Cylinder, kPartSide, {0.5f, 0.25f, 0}, 0.5f, 0.25f);
    expect_uv(ShapeKind::Cylinder, kPartSide, {0, -0.25f, 0.5f}, 0.25f, 0.75f);
    expect_uv(ShapeKind::Cylinder, kPartSide, {0, 0.5f, -0.5f}, 0.75f, 0.0f);
    expect_uv(ShapeKind::Cylinder, kPartSide, {0, -0.5f, 0.5f}, 0.25f, kBelowOne);  // v = 1 clamps
    expect_uv(ShapeKind::Cone, kPartSide, {0.125f, 0.25f, 0}, 0.5f, 0.25f);
    expect_uv(ShapeKind::Cone, kPartSide, {0, -0.5f, -0.5f}, 0.75f, kBelowOne);
}

TEST(UnitShapeUv, Caps) {
    // Top: u = x + 0.5, v = z + 0.5; bottoms: u = x + 0.5, v = 0.5 − z.
    expect_uv(ShapeKind::Cylinder, kPartTopCap, {0.25f, 0.5f, -0.25f}, 0.75f, 0.25f);
    expect_uv(ShapeKind::Cylinder, kPartBottomCap, {0.25f, -0.5f, -0.25f}, 0.75f, 0.75f);
    expect_uv(ShapeKind::Cone, kPartBottomCap, {-0.25f, -0.5f, 0.125f}, 0.25f, 0.375f);
    expect_uv(ShapeKind::Cylinder, kPartTopCap, {0.5f, 0.5f, 0.0f}, kBelowOne, 0.5f);
}

TEST(UnitShapeUv, CubeFaces) {
    const float a = 0.25f;
    expect_uv(ShapeKind::Cube, kPartPosZ, {a, a, 0.5f}, 0.75f, 0.25f);   // front: x+.5, .5−y
    expect_uv(ShapeKind::Cube, kPartNegZ, {a, a, -0.5f}, 0.25f, 0.25f);  // back: .5−x, .5−y
    expect_uv(ShapeKind::Cube, kPartPosX, {0.5f, a, a}, 0.25f, 0.25f);   // right: .5−z, .5−y
    expect_uv(ShapeKind::Cube, kPartNegX, {-0.5f, a, a}, 0.75f, 0.25f);  // left: z+.5, .5−y
    expect_uv(ShapeKind::Cube, kPartPosY, {a, 0.5f, a}, 0.75f, 0.75f);   // top: x+.5, z+.5
    expect_uv(ShapeKind::Cube, kPartNegY, {a, -0.5f, a}, 0.75f, 0.25f);  // bottom: x+.5, .5−z
    expect_uv(ShapeKind::Cube, kPartPosZ, {-0.1f, -0.3f, 0.5f}, 0.4f, 0.8f);
    // Corners and points a hair outside clamp into [0, 1).
    expect_uv(ShapeKind::Cube, kPartPosZ, {0.5f, -0.5f, 0.5f}, kBelowOne, kBelowOne);
    expect_uv(ShapeKind::Cube, kPartPosZ, {-0.5000001f, 0.5000001f, 0.5f}, 0.0f, 0.0f);
}

TEST(UnitShapeUv, AlwaysInTheHalfOpenUnitSquare) {
    const struct { ShapeKind k; ShapePart part; } cases[] = {
        {ShapeKind::Sphere, kPartSide},      {ShapeKind::Cylinder, kPartSide},
        {ShapeKind::Cylinder, kPartTopCap},  {ShapeKind::Cylinder, kPartBottomCap},
        {ShapeKind::Cone, kPartSide},        {ShapeKind::Cone, kPartBottomCap},
        {ShapeKind::Cube, kPartPosX},        {ShapeKind::Cube, kPartNegX},
        {ShapeKind::Cube, kPartPosY},        {ShapeKind::Cube, kPartNegY},
        {ShapeKind::Cube, kPartPosZ},        {ShapeKind::Cube, kPartNegZ}};
    std::mt19937 rng(8);
    std::uniform_real_distribution<float> u(-0.51f, 0.51f);
    for (const auto& c : cases) {
        for (int i = 0; i < 2000; ++i) {
            const glm::vec2 uv = unit_shape_uv(c.k, c.part, {u(rng), u(rng), u(rng)});
            EXPECT_TRUE(uv.x >= 0 && uv.x < 1 && uv.y >= 0 && uv.y < 1) << uv.x << " " << uv.y;
        }
    }
}

}  // namespace
}  // namespace whitted
