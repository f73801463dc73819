// The time-dependent transform of `velocity` / `angularrate` (data/motion.h) and the boxes that
// bound a moving instance over a shutter (accel/motion_set.h).
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "accel/motion_set.h"
#include "accel/scene.h"
#include "flatten/flatten.h"
#include "parse/parser.h"
#include "shapes/unit_shapes.h"

namespace whitted {
namespace {

void expect_near(const glm::dmat4& a, const glm::dmat4& b, double tol) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tol) << c << "," << r;
}

// §9.4: `velocity x y z` is `translate t·x t·y t·z` and `angularrate ax ay az rate` is
// `rotate ax ay az (rate·t)`, in their places among the block's transforms.
TEST(Motion, IsTheProductInTheOrderWrittenAtEveryTime) {
    Motion m;
    m.then_matrix(glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)));
    m.then_spin(glm::dvec3(0, 0, 2), 90);
    m.then_velocity(glm::dvec3(0.5, 0, -1));
    m.then_matrix(glm::scale(glm::dmat4(1.0), glm::dvec3(2, 1, 1)));
    ASSERT_TRUE(m.moves());
    for (double t : {0.0, 0.25, 1.0, -3.5}) {
        SCOPED_TRACE(t);
        const glm::dmat4 by_hand = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 2, 3)) *
                                   glm::rotate(glm::dmat4(1.0), glm::radians(90.0 * t), glm::dvec3(0, 0, 1)) *
                                   glm::translate(glm::dmat4(1.0), t * glm::dvec3(0.5, 0, -1)) *
                                   glm::scale(glm::dmat4(1.0), glm::dvec3(2, 1, 1));
        expect_near(m.object_to_world(t), by_hand, 1e-12);
        expect_near(m.world_to_object(t) * m.object_to_world(t), glm::dmat4(1.0), 1e-12);
    }
    // At t = 1 a quarter turn about z: the object's (0, 0, 0) goes to (1, 2, 3) + R·(0.5, 0, −1)
    // with R taking x to y.
    const glm::dvec4 p = m.object_to_world(1.0) * glm::dvec4(0, 0, 0, 1);
    EXPECT_NEAR(p.x, 1.0, 1e-12);
    EXPECT_NEAR(p.y, 2.5, 1e-12);
    EXPECT_NEAR(p.z, 2.0, 1e-12);
    Motion still;
    still.then_matrix(glm::dmat4(2.0));
    still.then_velocity(glm::dvec3(0.0));
    EXPECT_FALSE(still.moves());
}

// The chain through a subgraph: the parent block's motion, then the child block's transforms; at
// the load's time it is the matrix the instance was placed with.
TEST(Motion, FlattenKeepsTheChainOfEachMovingInstance) {
    const char* text = "mastersubgraph arm [ trans [ translate 2 0 0 scale 1 3 1 object cube [ ] ] ]\n"
                       "mastersubgraph root [\n"
                       "  trans [ object sphere [ ] ]\n"
                       "  trans [ translate 0 1 0 angularrate 0 1 0 45 velocity 0 0 2 subgraph arm ]\n"
                       "]\n";
    ParseOptions po;
    po.time = 0.6f;
    const ParseResult parsed = parse_scene_text(text, "chain.sc", po);
    ASSERT_TRUE(parsed.ok());
    const FlattenResult flat = flatten(parsed.scene);
    ASSERT_TRUE(flat.ok());
    ASSERT_EQ(flat.scene.instances.size(), 2u);
    ASSERT_EQ(flat.scene.moving.size(), 1u);  // the cube under the moving block; the sphere stands still
    const SceneData::Moving moving = flat.scene.moving[0];
    EXPECT_EQ(flat.scene.instances[moving.instance].kind, ShapeKind::Cube);
    const Motion& chain = flat.scene.motions[moving.motion];
    const glm::dmat4 placed(object_to_world(flat.scene.instances[moving.instance]));
    expect_near(chain.object_to_world(0.6), placed, 1e-5);
    const glm::dmat4 by_hand = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0)) *
                               glm::rotate(glm::dmat4(1.0), glm::radians(45.0 * 2.0), glm::dvec3(0, 1, 0)) *
                               glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 4)) *
                               glm::translate(glm::dmat4(1.0), glm::dvec3(2, 0, 0)) *
                               glm::scale(glm::dmat4(1.0), glm::dvec3(1, 3, 1));
    expect_near(chain.object_to_world(2.0), by_hand, 1e-12);
}

// The swept box holds the instance's world box at every time of the shutter (sampled densely and
// at random here, far finer than the box's own 32 steps), for spins far from the origin too.
TEST(MotionSet, SweptBoundsHoldEveryTimeOfTheShutter) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 40; ++trial) {
        Motion m;
        m.then_matrix(glm::translate(glm::dmat4(1.0), glm::dvec3(3 * u(rng), 3 * u(rng), 3 * u(rng))));
        m.then_spin(glm::dvec3(u(rng), u(rng), u(rng)) + glm::dvec3(0, 0, 1.5), 400 * u(rng));
        m.then_matrix(glm::translate(glm::dmat4(1.0), glm::dvec3(4 * u(rng), 0, 0)));
        m.then_velocity(glm::dvec3(2 * u(rng), 2 * u(rng), 0));
        m.then_spin(glm::dvec3(1, u(rng), 0), 200 * u(rng));
        m.then_matrix(glm::scale(glm::dmat4(1.0), glm::dvec3(1 + u(rng) * 0.5, 2, 0.5)));
        const ShapeKind kind = ShapeKind(trial % 5);  // every unit shape
        const Instance base = make_instance(m.object_to_world(0.0), kind, 0);
        const Shutter shutter{-0.3 + 0.1 * u(rng), 0.7 + 0.2 * u(rng)};
        const Bounds swept = swept_bounds(m, base, nullptr, shutter);
        std::uniform_real_distribution<double> when(shutter.open, shutter.close);
        for (int k = 0; k < 400; ++k) {
            const double t = k < 200 ? shutter.open + (shutter.close - shutter.open) * k / 199.0 : when(rng);
            const Bounds at = unit_shape_world_bounds(kind, glm::mat4(m.object_to_world(t)));
            for (int a = 0; a < 3; ++a) {
                ASSERT_LE(swept.lo[a], at.lo[a]) << trial << " t=" << t;
                ASSERT_GE(swept.hi[a], at.hi[a]) << trial << " t=" << t;
            }
        }
    }
}

// A ray meets a moving instance where it is at the ray's time, and misses it elsewhere: the
// sphere moving along x at 2 units per time, the shutter [0, 1], rays down the z axis at x = 1.
TEST(MotionSet, RaysMeetTheInstanceAtTheirTime) {
    SceneData data;
    Motion m;
    m.then_matrix(glm::dmat4(1.0));
    m.then_velocity(glm::dvec3(2, 0, 0));
    data.instances.push_back(make_instance(glm::dmat4(1.0), ShapeKind::Sphere, 0));
    data.materials.resize(1);
    data.motions.push_back(m);
    data.moving.push_back({0, 0});
    const Shutter shutter{0.0, 1.0};
    const Scene scene = accelerate(std::move(data), 1, nullptr, &shutter);
    ASSERT_EQ(scene.motion.count(), 1u);
    Hit hit;
    // At fraction 0.5 (t = 0.5) the sphere of radius 0.5 is centred at x = 1: hit at z = 0.5.
    EXPECT_TRUE(scene.intersect(Ray{{1, 0, 5}, {0, 0, -1}, 0.5f}, hit));
    EXPECT_NEAR(hit.t, 4.5f, 1e-5f);
    EXPECT_FALSE(scene.intersect(Ray{{1, 0, 5}, {0, 0, -1}, 0.0f}, hit));  // at x = 0 then
    EXPECT_FALSE(scene.intersect(Ray{{1, 0, 5}, {0, 0, -1}, 1.0f}, hit));  // at x = 2
    EXPECT_TRUE(scene.occluded(Ray{{1, 0, 5}, {0, 0, -1}, 0.6f}, 10.0f));
    EXPECT_FALSE(scene.occluded(Ray{{1, 0, 5}, {0, 0, -1}, 0.1f}, 10.0f));
    // The instance as shading reads it: moved to the ray's time.
    const glm::mat4 at = object_to_world(scene.instance_at(0, 0.25f));
    EXPECT_NEAR(at[3][0], 0.5f, 1e-6f);
}

// Many moving instances among still ones: the nearest hit through the BVHs (the still one and
// the one over the swept boxes) is the one found by testing every instance placed at the ray's
// time, and single rays and packets agree.
TEST(MotionSet, NearestHitIsTheBruteForceOneAtTheRaysTime) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    SceneData data;
    data.materials.resize(1);
    for (int i = 0; i < 300; ++i) {
        const glm::dmat4 place = glm::translate(glm::dmat4(1.0), glm::dvec3(8 * u(rng), 8 * u(rng), 8 * u(rng))) *
                                 glm::scale(glm::dmat4(1.0), glm::dvec3(0.5 + 0.4 * u(rng)));
        const ShapeKind kind = ShapeKind(i % 5);
        data.instances.push_back(make_instance(place, kind, 0));
        if (i % 3 == 0) continue;  // a third stand still
        Motion m;
        m.then_matrix(place);
        if (i % 2) m.then_velocity(glm::dvec3(3 * u(rng), 3 * u(rng), 3 * u(rng)));
        else m.then_spin(glm::dvec3(u(rng), 1.0, u(rng)), 300 * u(rng));
        data.motions.push_back(m);
        data.moving.push_back({std::uint32_t(i), std::uint32_t(data.motions.size() - 1)});
    }
    const std::size_t moving = data.moving.size();
    const Shutter shutter{-0.5, 1.0};
    const Scene scene = accelerate(std::move(data), 2, nullptr, &shutter);
    ASSERT_EQ(scene.motion.count(), moving);
    ASSERT_EQ(scene.motion.first, 300u - moving);
    int hits = 0;
    for (int n = 0; n < 40; ++n) {
        Ray rays[kPacketSize];
        const glm::vec3 origin(12 * u(rng), 12 * u(rng), 20);
        for (Ray& ray : rays) {
            ray = Ray{origin, glm::normalize(glm::vec3(0.5f * u(rng), 0.5f * u(rng), -1.0f)), float(0.5 + 0.5 * u(rng))};
        }
        Hit packet[kPacketSize];
        const unsigned found = scene.intersect(rays, (1u << kPacketSize) - 1, packet);
        for (int l = 0; l < kPacketSize; ++l) {
            std::vector<Instance> placed;
            for (std::uint32_t i = 0; i < scene.data.instances.size(); ++i)
                placed.push_back(scene.instance_at(i, rays[l].time));
            Hit want, got;
            const bool hit = intersect_nearest_brute_force(placed, rays[l], 0.0f, Scene::kInfinity, want);
            ASSERT_EQ(scene.intersect(rays[l], got), hit) << n << "/" << l;
            ASSERT_EQ(bool((found >> l) & 1), hit);
            EXPECT_EQ(scene.occluded(rays[l], Scene::kInfinity), hit);
            if (!hit) continue;
            ++hits;
            EXPECT_EQ(got.instance, want.instance);
            EXPECT_EQ(got.t, want.t);
            EXPECT_EQ(packet[l].instance, want.instance);
            EXPECT_EQ(packet[l].t, want.t);
        }
    }
    EXPECT_GT(hits, 40);  // enough of the rays meet something for the comparison to say something
}

}  // namespace
}  // namespace whitted
