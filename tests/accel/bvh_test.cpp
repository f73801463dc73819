// The BVH against brute force: the same nearest hit (instance, t, part) and the same shadow
// transmittance on random scenes of every shape under random affine maps, plus the structure's
// invariants and the degenerate inputs (empty, all in one place, deep stacks).
#include <atomic>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "accel/bvh.h"
#include "accel/bvh_any_hit.h"
#include "accel/bvh_test_scenes.h"
#include "accel/instance_geometry.h"
#include "accel/mesh_bvh.h"
#include "accel/walk_both_ways.h"

namespace whitted {
namespace {

using namespace test;
constexpr float kInf = std::numeric_limits<float>::infinity();

void expect_same_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& r, float t_min,
                         float t_max, int ray_index) {
    Hit a{}, b{};
    bool ha = intersect_nearest(bvh, instances, r, t_min, t_max, a);
    bool hb = intersect_nearest_brute_force(instances, r, t_min, t_max, b);
    ASSERT_EQ(ha, hb) << "ray " << ray_index;
    if (!ha) return;
    ASSERT_EQ(a.instance, b.instance) << "ray " << ray_index << " t " << a.t << " vs " << b.t;
    ASSERT_EQ(a.t, b.t) << "ray " << ray_index;
    ASSERT_EQ(a.part, b.part) << "ray " << ray_index;
}

// Walks a tree: every instance in exactly one leaf, every box containing what is below it.
template <class Node>
void check_tree(const BasicBvh<Node>& bvh, const std::vector<Instance>& instances) {
    constexpr int W = Node::kWidth;
    ASSERT_FALSE(bvh.nodes.empty());
    std::vector<int> seen(instances.size(), 0);
    struct Item { std::uint32_t node; int depth; };
    std::vector<Item> stack{{0, 0}};
    int max_depth = 0;
    while (!stack.empty()) {
        Item it = stack.back();
        stack.pop_back();
        max_depth = std::max(max_depth, it.depth);
        const Node& n = bvh.nodes.at(it.node);
        for (int s = 0; s < W; ++s) {
            Bounds box;
            box.lo = {n.box[0][s], n.box[1][s], n.box[2][s]};
            box.hi = {n.box[3][s], n.box[4][s], n.box[5][s]};
            if (box.empty()) continue;
            const std::uint32_t ref = n.child[s];
            if (Node::is_leaf(ref)) {
                for (std::uint32_t i = Node::leaf_first(ref); i < Node::leaf_first(ref) + Node::leaf_count(ref); ++i) {
                    ASSERT_LT(i, instances.size());
                    ++seen[i];
                    Bounds b = world_bounds(instances[i]);
                    for (int a = 0; a < 3; ++a) {
                        ASSERT_LE(box.lo[a], b.lo[a]);
                        ASSERT_GE(box.hi[a], b.hi[a]);
                    }
                }
            } else {
                ASSERT_GT(ref, it.node) << "children follow their parent";
                const Node& c = bvh.nodes.at(ref);
                for (int cs = 0; cs < W; ++cs) {
                    if (c.box[0][cs] > c.box[3][cs]) continue;
                    for (int a = 0; a < 3; ++a) {
                        ASSERT_LE(box.lo[a], c.box[a][cs]);
                        ASSERT_GE(box.hi[a], c.box[3 + a][cs]);
                    }
                }
                stack.push_back({ref, it.depth + 1});
            }
        }
    }
    for (std::size_t i = 0; i < seen.size(); ++i) ASSERT_EQ(seen[i], 1) << "instance " << i;
    EXPECT_LT(max_depth, 96);
}

// A scene of unit shapes: the 4-wide tree the packets walk and, where the CPU has AVX2, its 8-wide
// copy for single rays over the same instance order (bvh_node.h).
void check_structure(const Bvh& bvh, const std::vector<Instance>& instances) {
    if (instances.empty()) {
        EXPECT_TRUE(bvh.empty());
        return;
    }
    check_tree(static_cast<const BasicBvh<Bvh4Node>&>(bvh), instances);
    if (mesh_detail::cpu_allows_avx2()) {
        ASSERT_FALSE(bvh.wide.nodes.empty()) << "a CPU with AVX2 gets the 8-wide copy";
        check_tree(bvh.wide, instances);
        for (int a = 0; a < 3; ++a) {
            EXPECT_EQ(bvh.wide.box.lo[a], bvh.box.lo[a]);
            EXPECT_EQ(bvh.wide.box.hi[a], bvh.box.hi[a]);
        }
    }
}

// Single rays walk the 8-wide copy in AVX2 steps where the CPU has it, else the 4-wide tree: the
// walk tests run both ways and must give brute force's answers either way.
class BvhWalk : public WalkBothWays {};
INSTANTIATE_TEST_SUITE_P(BoxTest, BvhWalk, ::testing::Values(true, false), walk_name);

TEST_P(BvhWalk, NearestHitMatchesBruteForceOnRandomScenes) {
    for (std::uint32_t seed : {1u, 2u, 3u, 4u, 5u}) {
        SCOPED_TRACE(seed);
        RandomScene scene = random_scene(seed, 200 + 60 * int(seed), 10.0f);
        Bvh bvh = build_bvh(scene.instances);
        check_structure(bvh, scene.instances);
        std::vector<Ray> rays = random_rays(seed, 1200, 10.0f, scene.instances);
        int hits = 0;
        for (int i = 0; i < int(rays.size()); ++i) {
            expect_same_nearest(bvh, scene.instances, rays[i], 0.0f, kInf, i);
            // A bounded segment, as shadow and secondary rays have.
            expect_same_nearest(bvh, scene.instances, rays[i], 0.5f, 3.0f + float(i % 7), i);
            if (HasFatalFailure()) return;
            Hit h;
            hits += intersect_nearest_brute_force(scene.instances, rays[i], 0.0f, kInf, h);
        }
        EXPECT_GT(hits, int(rays.size()) / 3) << "the rays should mostly hit something";
    }
}

TEST_P(BvhWalk, FarAwayRaysMatchBruteForceAndHitTheSurface) {
    // Small objects seen from ~1000 units away (a big grid scene): in float, the cone's quadratic
    // once gave hits well off the surface from such origins, which the tight boxes then culled,
    // so the BVH and brute force disagreed. Every hit must lie on its shape.
    std::mt19937 rng(77);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    std::vector<Instance> instances;
    for (int i = 0; i < 400; ++i) {
        glm::vec3 c(float(i % 20) - 500.0f, 0.5f, float(i / 20) - 490.0f);
        glm::mat4 m = glm::translate(glm::mat4(1.0f), c);
        m = glm::rotate(m, 3.0f * u(rng), glm::normalize(glm::vec3(u(rng), u(rng), u(rng)) + 1e-3f));
        m = glm::scale(m, glm::vec3(0.4f + 0.3f * u(rng), 0.4f + 0.3f * u(rng), 0.4f + 0.3f * u(rng)));
        instances.push_back(make_instance(m, ShapeKind(i % 4), 0));
    }
    Bvh bvh = build_bvh(instances);
    const glm::vec3 eye(0, 350, 750);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        glm::vec3 target(-500.0f + 20.0f * (0.5f + 0.5f * u(rng)), 0.5f + 0.5f * u(rng), -490.0f + 20.0f * (0.5f + 0.5f * u(rng)));
        Ray r{eye, glm::normalize(target - eye)};
        expect_same_nearest(bvh, instances, r, 0.0f, kInf, i);
        if (HasFatalFailure()) return;
        Hit h;
        if (!intersect_nearest(bvh, instances, r, 0.0f, kInf, h)) continue;
        ++hits;
        const Instance& inst = instances[h.instance];
        const glm::vec3 p = to_object_space(inst, r).at(h.t);
        const float radial = std::sqrt(p.x * p.x + p.z * p.z);
        switch (inst.kind) {
            case ShapeKind::Sphere: EXPECT_NEAR(glm::length(p), 0.5f, 2e-3f) << i; break;
            case ShapeKind::Ellipsoid: EXPECT_NEAR(p.x * p.x + 4 * p.y * p.y + p.z * p.z, 1.0f, 4e-3f) << i; break;
            case ShapeKind::Cone:
                if (h.part == kPartSide) {
                    EXPECT_NEAR(radial, 0.5f * (0.5f - p.y), 2e-3f) << i;
                }
                break;
            case ShapeKind::Cylinder:
                if (h.part == kPartSide) {
                    EXPECT_NEAR(radial, 0.5f, 2e-3f) << i;
                }
                break;
            case ShapeKind::Cube:
                EXPECT_NEAR(std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))), 0.5f, 2e-3f) << i;
                break;
            case ShapeKind::Mesh: ADD_FAILURE() << "no meshes in this scene"; break;
        }
    }
    EXPECT_GT(hits, 1000);
}

// The coloured-glass shadow factor (as integrator/glass_transmittance.h filters the any-hit
// query) over the BVH's crossings and over every instance's: the two must see the same crossings.
struct GlassFilter {
    const std::vector<Material>& materials;
    const std::vector<Instance>& instances;
    glm::vec3 through{1.0f};
    bool operator()(std::uint32_t i, int crossings) {
        const Material& m = materials[instances[i].material];
        if (!m.is_transparent()) {
            through = glm::vec3(0.0f);
            return false;
        }
        through *= crossings == 2 ? m.transparent * m.transparent : m.transparent;
        return true;
    }
};
glm::vec3 transmittance(const Bvh& bvh, const std::vector<Instance>& instances, const std::vector<Material>& materials,
                        const Ray& ray, float t_min, float t_max) {
    GlassFilter f{materials, instances};
    for_each_crossing(bvh, instances, ray, t_min, t_max, f);
    return f.through;
}
glm::vec3 transmittance_brute_force(const std::vector<Instance>& instances, const std::vector<Material>& materials,
                                    const Ray& ray, float t_min, float t_max) {
    GlassFilter f{materials, instances};
    for_each_crossing_brute_force(instances, ray, t_min, t_max, f);
    return f.through;
}

TEST_P(BvhWalk, TransmittanceMatchesBruteForce) {
    for (std::uint32_t seed : {11u, 12u, 13u}) {
        SCOPED_TRACE(seed);
        RandomScene scene = random_scene(seed, 300, 10.0f);
        Bvh bvh = build_bvh(scene.instances);
        std::vector<Ray> rays = random_rays(seed, 2000, 10.0f, scene.instances);
        int blocked = 0, partial = 0;
        for (int i = 0; i < int(rays.size()); ++i) {
            const float t_max = i % 3 == 0 ? kInf : 2.0f + float(i % 11);
            glm::vec3 a = transmittance(bvh, scene.instances, scene.materials, rays[i], 0.0f, t_max);
            glm::vec3 b = transmittance_brute_force(scene.instances, scene.materials, rays[i], 0.0f, t_max);
            // The same factors, multiplied in another order: equal up to rounding.
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], 1e-5f * std::max(1.0f, b[c])) << "ray " << i;
            ASSERT_EQ(a == glm::vec3(0.0f), b == glm::vec3(0.0f)) << "ray " << i;
            blocked += b == glm::vec3(0.0f);
            partial += b != glm::vec3(0.0f) && b != glm::vec3(1.0f);
        }
        EXPECT_GT(blocked, 100);
        EXPECT_GT(partial, 20) << "some rays should pass through glass only";
    }
}

TEST(Bvh, EmptyScene) {
    std::vector<Instance> none;
    Bvh bvh = build_bvh(none);
    EXPECT_TRUE(bvh.empty());
    EXPECT_TRUE(bvh.bounds().empty());
    Hit h;
    EXPECT_FALSE(intersect_nearest(bvh, none, Ray{}, 0.0f, kInf, h));
    EXPECT_EQ(transmittance(bvh, none, {}, Ray{}, 0.0f, kInf), glm::vec3(1.0f));
}

TEST(Bvh, SingleInstance) {
    std::vector<Instance> one{make_instance(glm::mat4(1.0f), ShapeKind::Sphere, 0)};
    Bvh bvh = build_bvh(one);
    check_structure(bvh, one);
    Hit h;
    ASSERT_TRUE(intersect_nearest(bvh, one, Ray{{0, 0, 5}, {0, 0, -1}}, 0.0f, kInf, h));
    EXPECT_FLOAT_EQ(h.t, 4.5f);
    EXPECT_FALSE(intersect_nearest(bvh, one, Ray{{0, 2, 5}, {0, 0, -1}}, 0.0f, kInf, h));
}

TEST_P(BvhWalk, AllInstancesInOnePlace) {
    // Identical instances: equal distances everywhere, so the lowest index must win, as in the
    // brute-force loop; nothing separates the centres, so the build splits at the median.
    std::vector<Instance> same;
    std::mt19937 rng(3);
    glm::mat4 m = random_affine(rng, 1.0f);
    for (int i = 0; i < 1000; ++i) same.push_back(make_instance(m, ShapeKind(i % 4 == 3 ? 3 : 0), 0));
    Bvh bvh = build_bvh(same);
    check_structure(bvh, same);
    std::vector<Ray> rays = random_rays(3, 300, 2.0f, same);
    for (int i = 0; i < int(rays.size()); ++i) {
        expect_same_nearest(bvh, same, rays[i], 0.0f, kInf, i);
        if (HasFatalFailure()) return;
    }
}

TEST_P(BvhWalk, DeepStacksOf100kInstances) {
    // Centres on a geometric progression make every SAH split peel off a few instances: the tree
    // would be ~n deep without the depth limit; traversal's fixed stack must still suffice.
    std::vector<Instance> stack;
    const int n = 100000;
    stack.reserve(n);
    for (int i = 0; i < n; ++i) {
        float x = std::pow(1.0002f, float(i)) - 1.0f;  // 0 … ~4.8e8, ever sparser
        float s = 0.5f + 0.001f * float(i % 1000);
        stack.push_back(make_instance(glm::scale(glm::translate(glm::mat4(1.0f), {x, 0, 0}), glm::vec3(s)), ShapeKind(i % 4), 0));
    }
    Bvh bvh = build_bvh(stack);
    check_structure(bvh, stack);
    // Rays along the stack (crossing every instance's box) and across it.
    std::vector<Ray> rays;
    for (int i = 0; i < 16; ++i) {
        rays.push_back(Ray{{-10.0f, 0.01f * float(i % 5), 0.0f}, glm::normalize(glm::vec3(1, 1e-4f * float(i), 0))});
        rays.push_back(Ray{{std::pow(1.0002f, float(i * 6000)) - 1.0f, 10.0f, 0.1f}, {0, -1, 0}});
    }
    for (int i = 0; i < int(rays.size()); ++i) {
        expect_same_nearest(bvh, stack, rays[i], 0.0f, kInf, i);
        if (HasFatalFailure()) return;
        EXPECT_EQ(transmittance(bvh, stack, {Material{}}, rays[i], 0.0f, kInf),
                  transmittance_brute_force(stack, {Material{}}, rays[i], 0.0f, kInf));
    }
}

// A build of millions looks at the cancel flag every few nodes (a 10M-instance
// build ran 10 s after the signal); cancelled, it leaves an empty tree and the instances as they were.
TEST(Bvh, ACancelledBuildLeavesNothingHalfMade) {
    RandomScene scene = random_scene(5, 20000, 50.0f);
    const std::vector<Instance> before = scene.instances;
    const std::atomic<bool> cancel{true};
    std::vector<std::uint32_t> order;
    const Bvh bvh = build_bvh(scene.instances, 1, nullptr, &order, &cancel);
    EXPECT_TRUE(bvh.empty());
    EXPECT_TRUE(order.empty());
    for (std::size_t i = 0; i < before.size(); ++i)
        ASSERT_EQ(std::memcmp(&scene.instances[i], &before[i], sizeof(Instance)), 0);
    // Not cancelled: the whole tree.
    const std::atomic<bool> go{false};
    const Bvh whole = build_bvh(scene.instances, 1, nullptr, nullptr, &go);
    check_structure(whole, scene.instances);
}

}  // namespace
}  // namespace whitted
