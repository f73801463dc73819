// Hand-computed intersections and normals of the four unit shapes, plus the awkward cases:
// rays lying in a face, along the cylinder axis, through the cone apex, tangent, starting
// inside, with non-unit directions.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "shapes/unit_shape_math.h"
#include "shapes/unit_shapes.h"

namespace whitted {
namespace {

constexpr ShapeKind kAllKinds[] = {ShapeKind::Cube, ShapeKind::Cylinder, ShapeKind::Cone, ShapeKind::Sphere,
                                   ShapeKind::Ellipsoid};
constexpr float kEps = 1e-5f;

ShapeSpan hit(ShapeKind kind, glm::vec3 o, glm::vec3 d) { return intersect_unit_shape(kind, Ray{o, d}); }

void expect_span(const ShapeSpan& s, float t0, ShapePart p0, float t1, ShapePart p1) {
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.t[0], t0, kEps);
    EXPECT_NEAR(s.t[1], t1, kEps);
    EXPECT_EQ(s.part[0], p0);
    EXPECT_EQ(s.part[1], p1);
}

void expect_vec(glm::vec3 a, glm::vec3 b, float eps = kEps) {
    EXPECT_NEAR(a.x, b.x, eps);
    EXPECT_NEAR(a.y, b.y, eps);
    EXPECT_NEAR(a.z, b.z, eps);
}

TEST(UnitShapes, AxisRaysHitAtTheExpectedDistances) {
    const glm::vec3 from_z(0, 0, 5), down_z(0, 0, -1);
    expect_span(hit(ShapeKind::Sphere, from_z, down_z), 4.5f, kPartSide, 5.5f, kPartSide);
    expect_span(hit(ShapeKind::Cube, from_z, down_z), 4.5f, kPartPosZ, 5.5f, kPartNegZ);
    expect_span(hit(ShapeKind::Cube, {-5, 0, 0}, {1, 0, 0}), 4.5f, kPartNegX, 5.5f, kPartPosX);
    expect_span(hit(ShapeKind::Cube, {0, -5, 0}, {0, 1, 0}), 4.5f, kPartNegY, 5.5f, kPartPosY);
    expect_span(hit(ShapeKind::Cylinder, {5, 0, 0}, {-1, 0, 0}), 4.5f, kPartSide, 5.5f, kPartSide);
    // Along the cylinder axis: cap to cap.
    expect_span(hit(ShapeKind::Cylinder, {0, 5, 0}, {0, -1, 0}), 4.5f, kPartTopCap, 5.5f, kPartBottomCap);
    expect_span(hit(ShapeKind::Cylinder, {0, -5, 0}, {0, 1, 0}), 4.5f, kPartBottomCap, 5.5f, kPartTopCap);
    // Cone along its axis: the apex (reported as the side), then the base.
    expect_span(hit(ShapeKind::Cone, {0, 5, 0}, {0, -1, 0}), 4.5f, kPartSide, 5.5f, kPartBottomCap);
    expect_span(hit(ShapeKind::Cone, {0, -5, 0}, {0, 1, 0}), 4.5f, kPartBottomCap, 5.5f, kPartSide);
    // Cone side at y = 0, where the radius is 0.25.
    expect_span(hit(ShapeKind::Cone, {5, 0, 0}, {-1, 0, 0}), 4.75f, kPartSide, 5.25f, kPartSide);
}

TEST(UnitShapes, Misses) {
    for (ShapeKind k : kAllKinds) {
        EXPECT_EQ(hit(k, {0, 0, 5}, {0, 1, 0}).count, 0);
        EXPECT_EQ(hit(k, {2, 2, 5}, {0, 0, -1}).count, 0);
    }
    // Zero direction: no interval.
    for (ShapeKind k : kAllKinds) EXPECT_EQ(hit(k, {0, 0, 0}, {0, 0, 0}).count, 0);
}

TEST(UnitShapes, ConeIgnoresTheUpperNappe) {
    // At y = 1 the double cone has radius 0.25, the solid cone nothing.
    EXPECT_EQ(hit(ShapeKind::Cone, {5, 1, 0}, {-1, 0, 0}).count, 0);
    // Steep rays cross both nappes: only the lower one counts (y = 0.3 where r = 0.1).
    expect_span(hit(ShapeKind::Cone, {0.1f, 5, 0}, {0, -1, 0}), 4.7f, kPartSide, 5.5f, kPartBottomCap);
    expect_span(hit(ShapeKind::Cone, {0.1f, -5, 0}, {0, 1, 0}), 4.5f, kPartBottomCap, 5.3f, kPartSide);
    expect_span(hit(ShapeKind::Cone, {0, -5, 0.1f}, {0, 2, 0}), 2.25f, kPartBottomCap, 2.65f, kPartSide);
}

TEST(UnitShapes, ConeThroughTheApex) {
    // Steeper than the generators, through the apex: inside from the apex to the base.
    expect_span(hit(ShapeKind::Cone, {-0.25f, 1.5f, 0}, {1, -4, 0}), 0.25f, kPartSide, 0.5f, kPartBottomCap);
    // Shallower than the generators: touches the apex only (zero-length, no NaN).
    const ShapeSpan s = hit(ShapeKind::Cone, {-1, 0.5f, 0}, {1, 0, 0});
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.t[0], 1.0f, kEps);
    EXPECT_NEAR(s.t[1], 1.0f, kEps);
    EXPECT_EQ(hit(ShapeKind::Cone, {-1, 0.5f + 1e-3f, 0}, {1, 0, 0}).count, 0);
}

TEST(UnitShapes, ConeRayParallelToAGenerator) {
    // Direction (1, -2, 0) is parallel to the generator from the apex to (0.5, -0.5, 0): the
    // quadratic degenerates to a line. Points (s, -2s, 0) are inside for s in [-0.125, 0.25].
    expect_span(hit(ShapeKind::Cone, {0, 0, 0}, {1, -2, 0}), -0.125f, kPartSide, 0.25f, kPartBottomCap);
    expect_span(hit(ShapeKind::Cone, {0, 0, 0}, {-1, 2, 0}), -0.25f, kPartBottomCap, 0.125f, kPartSide);
}

TEST(UnitShapes, RaysLyingInAFaceCountAsInside) {
    // Origin exactly on a slab plane with a zero direction component: 0·inf must not poison t.
    expect_span(hit(ShapeKind::Cube, {0.5f, 0, 5}, {0, 0, -1}), 4.5f, kPartPosZ, 5.5f, kPartNegZ);
    expect_span(hit(ShapeKind::Cube, {-0.5f, 0.2f, 3}, {0, 0, -1}), 2.5f, kPartPosZ, 3.5f, kPartNegZ);
    expect_span(hit(ShapeKind::Cube, {0.5f, 0.5f, 5}, {0, 0, -1}), 4.5f, kPartPosZ, 5.5f, kPartNegZ);  // an edge
    expect_span(hit(ShapeKind::Cube, {-5, -0.5f, 0.5f}, {1, 0, 0}), 4.5f, kPartNegX, 5.5f, kPartPosX);
    expect_span(hit(ShapeKind::Cube, {-5, 0.5f, 0.1f}, {-1, 0, 0}), -5.5f, kPartPosX, -4.5f, kPartNegX);
    EXPECT_EQ(hit(ShapeKind::Cube, {0.5000001f, 0, 5}, {0, 0, -1}).count, 0);
    EXPECT_EQ(hit(ShapeKind::Cube, {2, 0, 5}, {0, 0, -1}).count, 0);
    EXPECT_EQ(hit(ShapeKind::Cube, {-2, 0, 5}, {0, 0, -1}).count, 0);
    // In the plane of a cylinder cap, and of the cone base.
    expect_span(hit(ShapeKind::Cylinder, {-5, 0.5f, 0}, {1, 0, 0}), 4.5f, kPartSide, 5.5f, kPartSide);
    expect_span(hit(ShapeKind::Cylinder, {-5, -0.5f, 0}, {1, 0, 0}), 4.5f, kPartSide, 5.5f, kPartSide);
    expect_span(hit(ShapeKind::Cone, {-5, -0.5f, 0}, {1, 0, 0}), 4.5f, kPartSide, 5.5f, kPartSide);
    EXPECT_EQ(hit(ShapeKind::Cylinder, {-5, 0.5000001f, 0}, {1, 0, 0}).count, 0);
}

TEST(UnitShapes, RaysParallelToTheCylinderAxis) {
    expect_span(hit(ShapeKind::Cylinder, {0.3f, 0, -0.2f}, {0, 1, 0}), -0.5f, kPartBottomCap, 0.5f, kPartTopCap);
    expect_span(hit(ShapeKind::Cylinder, {0.5f, 0, 0}, {0, -3, 0}), -1 / 6.0f, kPartTopCap, 1 / 6.0f,
                kPartBottomCap);  // on the tube
    EXPECT_EQ(hit(ShapeKind::Cylinder, {0.6f, 0, 0}, {0, 1, 0}).count, 0);
}

TEST(UnitShapes, TangentRaysGiveAZeroLengthInterval) {
    for (ShapeKind k : {ShapeKind::Sphere, ShapeKind::Cylinder}) {
        const ShapeSpan s = hit(k, {0.5f, 0, 5}, {0, 0, -1});
        ASSERT_EQ(s.count, 2) << shape_name(k);
        EXPECT_FLOAT_EQ(s.t[0], 5.0f);
        EXPECT_FLOAT_EQ(s.t[1], 5.0f);
    }
    // Cone: tangent along a generator is the ray-parallel-to-generator case; tangent at
    // y = 0 (radius 0.25) perpendicular to the axis:
    const ShapeSpan s = hit(ShapeKind::Cone, {0.25f, 0, 5}, {0, 0, -1});
    ASSERT_EQ(s.count, 2);
    EXPECT_NEAR(s.t[0], 5.0f, 1e-3f);
    EXPECT_NEAR(s.t[1], 5.0f, 1e-3f);
}

TEST(UnitShapes, GrazingRaysNeverProduceNaN) {
    // Sweep offsets across the silhouette, including the exact tangent and float neighbours.
    for (ShapeKind k : kAllKinds) {
        for (float base : {0.25f, 0.5f}) {
            float x = base;
            for (int i = 0; i < 8; ++i) x = std::nextafter(x, 0.0f);
            for (int i = 0; i < 16; ++i, x = std::nextafter(x, 1.0f)) {
                for (glm::vec3 d : {glm::vec3(0, 0, -1), glm::vec3(0, -1e-7f, -1), glm::vec3(1e-30f, 0, -1)}) {
                    for (float y : {0.0f, 0.5f, -0.5f, 0.4999999f}) {
                        const ShapeSpan s = hit(k, {x, y, 5}, d);
                        if (s.count == 0) continue;
                        EXPECT_TRUE(std::isfinite(s.t[0]) && std::isfinite(s.t[1])) << shape_name(k);
                        EXPECT_LE(s.t[0], s.t[1]);
                    }
                }
            }
        }
    }
}

TEST(UnitShapes, RaysStartingInside) {
    for (ShapeKind k : kAllKinds) {
        for (glm::vec3 d : {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0.3f, -0.7f, 0.2f)}) {
            const ShapeSpan s = hit(k, {0, -0.1f, 0.05f}, d);
            ASSERT_EQ(s.count, 2) << shape_name(k);
            EXPECT_LT(s.t[0], 0.0f);
            EXPECT_GT(s.t[1], 0.0f);
        }
    }
    expect_span(hit(ShapeKind::Sphere, {0, 0, 0}, {1, 0, 0}), -0.5f, kPartSide, 0.5f, kPartSide);
}

TEST(UnitShapes, TIsInTheRaysOwnParametrisation) {
    const glm::vec3 o(0.8f, 1.3f, -1.7f), d = glm::normalize(glm::vec3(-0.5f, -1.0f, 1.2f));
    for (ShapeKind k : kAllKinds) {
        const ShapeSpan ref = hit(k, o, d);
        ASSERT_EQ(ref.count, 2) << shape_name(k);
        for (float scale : {2.0f, 0.5f, 1e-3f, 1e3f}) {
            const ShapeSpan s = hit(k, o, scale * d);
            ASSERT_EQ(s.count, 2);
            for (int i = 0; i < 2; ++i) {
                EXPECT_NEAR(s.t[i] * scale, ref.t[i], 1e-5f) << shape_name(k) << " scale " << scale;
                EXPECT_EQ(s.part[i], ref.part[i]);
            }
        }
    }
}

TEST(UnitShapes, NormalsPerPart) {
    expect_vec(unit_shape_normal(ShapeKind::Sphere, kPartSide, {0, 0, 0.5f}), {0, 0, 1});
    expect_vec(unit_shape_normal(ShapeKind::Sphere, kPartSide, {0.3f, 0.4f, 0}), {0.6f, 0.8f, 0});
    expect_vec(unit_shape_normal(ShapeKind::Cylinder, kPartSide, {0.3f, 0.2f, -0.4f}), {0.6f, 0, -0.8f});
    expect_vec(unit_shape_normal(ShapeKind::Cylinder, kPartTopCap, {0.1f, 0.5f, 0.1f}), {0, 1, 0});
    expect_vec(unit_shape_normal(ShapeKind::Cylinder, kPartBottomCap, {0.1f, -0.5f, 0.1f}), {0, -1, 0});
    expect_vec(unit_shape_normal(ShapeKind::Cone, kPartBottomCap, {0.1f, -0.5f, 0.1f}), {0, -1, 0});
    // Cone side: ∝ (2x/r, 1, 2z/r); y = 1/√5 = 0.4472.
    const float s5 = std::sqrt(5.0f);
    expect_vec(unit_shape_normal(ShapeKind::Cone, kPartSide, {0.25f, 0, 0}), {2 / s5, 1 / s5, 0});
    expect_vec(unit_shape_normal(ShapeKind::Cone, kPartSide, {0, -0.5f, -0.5f}), {0, 1 / s5, -2 / s5});
    expect_vec(unit_shape_normal(ShapeKind::Cone, kPartSide, {0, 0.5f, 0}), {0, 1, 0});  // the apex
    const std::pair<ShapePart, glm::vec3> faces[] = {
        {kPartPosX, {1, 0, 0}}, {kPartNegX, {-1, 0, 0}}, {kPartPosY, {0, 1, 0}},
        {kPartNegY, {0, -1, 0}}, {kPartPosZ, {0, 0, 1}}, {kPartNegZ, {0, 0, -1}}};
    for (const auto& [part, n] : faces) expect_vec(unit_shape_normal(ShapeKind::Cube, part, 0.5f * n), n);
}

// Random rays through the unit box: hits lie on the part they name, the normal there is unit
// and faces against the ray at entry and along it at exit, the middle is inside, and the float
// instance agrees with the double one.
bool on_part(ShapeKind k, ShapePart part, glm::vec3 p, float eps) {
    const float r = std::sqrt(p.x * p.x + p.z * p.z);
    auto in = [eps](float v) { return std::abs(v) <= 0.5f + eps; };
    switch (part) {
        case kPartTopCap: return std::abs(p.y - 0.5f) <= eps && r <= 0.5f + eps;
        case kPartBottomCap: return std::abs(p.y + 0.5f) <= eps && r <= 0.5f + eps;
        case kPartPosX: case kPartNegX: return std::abs(std::abs(p.x) - 0.5f) <= eps && in(p.y) && in(p.z);
        case kPartPosY: case kPartNegY: return std::abs(std::abs(p.y) - 0.5f) <= eps && in(p.x) && in(p.z);
        case kPartPosZ: case kPartNegZ: return std::abs(std::abs(p.z) - 0.5f) <= eps && in(p.x) && in(p.y);
        case kPartSide: break;
    }
    if (k == ShapeKind::Sphere) return std::abs(glm::length(p) - 0.5f) <= eps;
    if (k == ShapeKind::Ellipsoid) return std::abs(p.x * p.x + 4 * p.y * p.y + p.z * p.z - 1) <= 4 * eps;
    if (k == ShapeKind::Cylinder) return std::abs(r - 0.5f) <= eps && in(p.y);
    return k == ShapeKind::Cone && std::abs(r - (0.5f - p.y) / 2) <= eps && in(p.y);
}

bool inside(ShapeKind k, glm::vec3 p) {
    const float r = std::sqrt(p.x * p.x + p.z * p.z);
    const bool slab = std::abs(p.y) <= 0.5f;
    switch (k) {
        case ShapeKind::Cube: return slab && std::abs(p.x) <= 0.5f && std::abs(p.z) <= 0.5f;
        case ShapeKind::Sphere: return glm::length(p) <= 0.5f;
        case ShapeKind::Cylinder: return slab && r <= 0.5f;
        case ShapeKind::Cone: return slab && r <= (0.5f - p.y) / 2;
        case ShapeKind::Ellipsoid: return p.x * p.x + 4 * p.y * p.y + p.z * p.z <= 1;
        case ShapeKind::Mesh: break;  // not a unit shape
    }
    return false;
}

TEST(UnitShapes, RandomRaysAreConsistent) {
    std::mt19937 rng(452);
    std::uniform_real_distribution<float> u(-1, 1);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 o(2 * u(rng), 2 * u(rng), 2 * u(rng));
        const glm::vec3 target(0.6f * u(rng), 0.6f * u(rng), 0.6f * u(rng));
        const glm::vec3 d = (target - o) * (0.2f + std::abs(u(rng)) * 3);
        for (ShapeKind k : kAllKinds) {
            const ShapeSpan s = hit(k, o, d);
            const auto sd = shape_math::intersect<double>(k, glm::dvec3(o), glm::dvec3(d));
            ASSERT_EQ(s.count, sd.count) << shape_name(k) << " ray " << i;
            if (s.count == 0) continue;
            ++hits;
            ASSERT_LE(s.t[0], s.t[1]);
            EXPECT_TRUE(inside(k, Ray{o, d}.at(0.5f * (s.t[0] + s.t[1])))) << shape_name(k) << " ray " << i;
            for (int e = 0; e < 2; ++e) {
                EXPECT_NEAR(s.t[e], sd.t[e], 1e-4f * (1 + std::abs(s.t[e])));
                const glm::vec3 p = Ray{o, d}.at(s.t[e]);
                EXPECT_TRUE(on_part(k, s.part[e], p, 1e-4f)) << shape_name(k) << " ray " << i << " end " << e;
                const glm::vec3 n = unit_shape_normal(k, s.part[e], p);
                EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
                const float facing = glm::dot(n, glm::normalize(d));
                if (s.t[1] - s.t[0] > 1e-3f) {  // skip grazing hits, where the sign is moot
                    if (e == 0) EXPECT_LE(facing, 1e-4f) << shape_name(k) << " ray " << i;
                    else EXPECT_GE(facing, -1e-4f) << shape_name(k) << " ray " << i;
                }
            }
        }
    }
    EXPECT_GT(hits, 20000);  // the test hit things
}

}  // namespace
}  // namespace whitted
