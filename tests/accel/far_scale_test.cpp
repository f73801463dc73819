// Objects scaled far beyond the unit shapes: a sphere scaled by 1e23 sees a
// unit ray as a direction of 1e-23, whose square is 0 in float, and vanished (exit 0) although the
// documented limit is 1e30. Such instances are intersected with the direction rescaled by a power
// of two, which gives the same bits wherever the plain arithmetic worked.
#include <random>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "shapes/unit_shape_math.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

const ShapeKind kKinds[] = {ShapeKind::Cube, ShapeKind::Sphere, ShapeKind::Cylinder, ShapeKind::Cone,
                            ShapeKind::Ellipsoid};

TEST(FarScale, ShapesScaledBy1e23AreSeenOneByOneAndInPackets) {
    for (const float scale : {1e23f, 1e29f, 1e-10f}) {
        for (ShapeKind kind : kKinds) {
            test::SceneBuilder b;
            b.add(kind, glm::scale(glm::mat4(1.0f), glm::vec3(scale)), Material{});
            const Scene scene = b.build();
            ASSERT_TRUE(scene.data.instances[0].rescale || scale == 1e-10f);
            // From 3 sizes away along +z, straight at it: the near face or side is 2.5 sizes away
            // (the cone's side at the centre's height is at 0.25: 2.75; the ellipsoid
            // x² + 4y² + z² = 1 reaches z = 1: 2).
            const float near = kind == ShapeKind::Cone ? 2.75f : kind == ShapeKind::Ellipsoid ? 2.0f : 2.5f;
            const Ray ray{{0, 0, 3 * scale}, {0, 0, -1}};
            Hit hit;
            ASSERT_TRUE(scene.intersect(ray, hit)) << int(kind) << " at scale " << scale;
            EXPECT_NEAR(hit.t / scale, near, 1e-5f) << int(kind) << " at scale " << scale;
            Ray rays[kPacketSize];
            for (Ray& r : rays) r = ray;
            Hit hits[kPacketSize];
            ASSERT_EQ(scene.intersect(rays, 0xffffu, hits), 0xffffu) << int(kind);
            for (const Hit& h : hits) EXPECT_EQ(h.t, hit.t);
        }
    }
}

// Scaling the direction by a power of two scales every intermediate by the same power: wherever
// the plain arithmetic stayed in range the distances are bit for bit the same (so scenes that
// rendered before render the same).
TEST(FarScale, RescaledIntersectionIsBitIdenticalWhereThePlainOneWorked) {
    std::mt19937 rng(31);
    std::uniform_real_distribution<float> pos(-3.0f, 3.0f), len(-20.0f, 20.0f);
    int hits = 0;
    for (int i = 0; i < 200000; ++i) {
        const glm::vec3 o(pos(rng), pos(rng), pos(rng));
        const glm::vec3 d = glm::vec3(pos(rng), pos(rng), pos(rng)) * std::exp2(std::round(len(rng)));
        for (ShapeKind kind : kKinds) {
            const auto a = shape_math::intersect<float>(kind, o, d);
            const auto b = shape_math::intersect_rescaled<float>(kind, o, d);
            ASSERT_EQ(a.count, b.count) << int(kind);
            for (int k = 0; k < a.count; ++k) {
                ASSERT_EQ(a.t[k], b.t[k]) << int(kind) << " ray " << i;
                ASSERT_EQ(a.part[k], b.part[k]) << int(kind);
            }
            hits += a.count > 0;
        }
    }
    EXPECT_GT(hits, 20000);  // (a fifth of the rays meet the shapes: the test is of those)
}

}  // namespace
}  // namespace whitted
