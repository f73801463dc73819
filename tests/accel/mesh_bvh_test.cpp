// The two-level BVH with meshes: the bottom level against testing every triangle, the top level
// with mesh instances against testing every instance, packets against single rays bit for bit,
// any-hit crossings, and the memory a mesh and many instances of it take.
#include <algorithm>
#include <bit>
#include <limits>
#include <cstring>
#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

#include "accel/bvh_any_hit.h"
#include "accel/bvh_test_scenes.h"
#include "accel/scene.h"
#include "integrator/surface.h"
#include "accel/mesh_bvh.h"
#include "accel/walk_both_ways.h"
#include "mesh/mesh_test_support.h"

namespace whitted {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

Ray random_ray(std::mt19937& rng, float spread) {
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    const glm::vec3 o = spread * glm::vec3(u(rng), u(rng), u(rng));
    const glm::vec3 target = 0.8f * glm::vec3(u(rng), u(rng), u(rng));
    return Ray{o, target - o};
}

// The mesh walks test a node's eight boxes in one AVX2 step where the CPU has it, else in two SSE
// steps (mesh_bvh.h): the walk tests run both ways, and must give the same answers.
class MeshBvhWalk : public test::WalkBothWays {};
INSTANTIATE_TEST_SUITE_P(BoxTest, MeshBvhWalk, ::testing::Values(true, false), test::walk_name);

TEST_P(MeshBvhWalk, NearestHitIsTheBruteForceOneOnRandomMeshes) {
    for (unsigned seed = 1; seed <= 4; ++seed) {
        TriangleMesh mesh = test::random_soup(seed == 1 ? 3 : 800 * int(seed), seed);
        const MeshBvh bvh = build_mesh_bvh(mesh, 1);
        std::mt19937 rng(seed);
        int hits = 0;
        for (int i = 0; i < 3000; ++i) {
            const Ray ray = random_ray(rng, 3.0f);
            const float t_min = (i % 4 == 0) ? 0.7f : 0.0f, t_max = (i % 5 == 0) ? 1.1f : kInf;
            MeshHit got{}, want{};
            const bool g = mesh_intersect_nearest(bvh, ray, t_min, t_max, got);
            const bool w = mesh_intersect_nearest_brute_force(mesh, ray, t_min, t_max, want);
            ASSERT_EQ(g, w) << "seed " << seed << " ray " << i;
            if (!g) continue;
            ++hits;
            EXPECT_EQ(got.triangle, want.triangle) << "seed " << seed << " ray " << i;
            EXPECT_EQ(bits(got.t), bits(want.t));
            EXPECT_EQ(bits(got.u), bits(want.u));
            EXPECT_EQ(bits(got.v), bits(want.v));
        }
        EXPECT_GT(hits, seed == 1 ? 0 : 300) << "the rays must hit something for the test to mean anything";
    }
}

TEST_P(MeshBvhWalk, AnyHitVisitsExactlyTheTrianglesCrossed) {
    TriangleMesh mesh = test::random_soup(2000, 7);
    const MeshBvh bvh = build_mesh_bvh(mesh, 1);
    std::mt19937 rng(7);
    for (int i = 0; i < 500; ++i) {
        const Ray ray = random_ray(rng, 3.0f);
        std::multiset<std::uint32_t> got, want;
        mesh_for_each_crossing(bvh, ray, 0.0f, 2.0f, [&](std::uint32_t t) { got.insert(t); return true; });
        const WatertightRay wr(ray);
        for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
            const TriangleIndices& c = mesh.triangles[t];
            TriangleHit h;
            if (intersect_triangle(wr, mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]], 0.0f, 2.0f, h))
                want.insert(t);
        }
        EXPECT_EQ(got, want) << "ray " << i;
    }
}

TEST(MeshBvh, BuildIsTheSameForAnyThreadCount) {
    TriangleMesh one = test::uv_sphere(300, 300), two = one;  // ~180,000 triangles: the parallel build
    const MeshBvh b1 = build_mesh_bvh(one, 1), b2 = build_mesh_bvh(two, 2);
    ASSERT_EQ(b1.bvh.nodes.size(), b2.bvh.nodes.size());
    EXPECT_EQ(std::memcmp(b1.bvh.nodes.data(), b2.bvh.nodes.data(), b1.bvh.nodes.size() * sizeof(b1.bvh.nodes[0])), 0);
    EXPECT_EQ(one.triangles, two.triangles);
}

// A scene of unit shapes and instances of two meshes under random affine maps.
SceneData mixed_scene(unsigned seed, int n) {
    test::RandomScene rs = test::random_scene(seed, n, 4.0f);
    SceneData flat;
    flat.instances = rs.instances;
    flat.materials = rs.materials;
    flat.meshes.push_back(test::uv_sphere(12, 24));
    flat.meshes.push_back(test::random_soup(300, seed));
    std::mt19937 rng(seed + 100);
    for (int i = 0; i < n; ++i) {
        Instance inst = make_instance(test::random_affine(rng, 4.0f), ShapeKind::Mesh, std::uint32_t(i % 3));
        inst.mesh = std::uint32_t(i % 2);
        flat.instances.push_back(inst);
    }
    return flat;
}

void expect_same_hit(const Hit& got, const Hit& want, const char* what, int i) {
    EXPECT_EQ(got.instance, want.instance) << what << " " << i;
    EXPECT_EQ(bits(got.t), bits(want.t)) << what << " " << i << ": " << got.t << " vs " << want.t;
    EXPECT_EQ(got.part, want.part) << what << " " << i;
    EXPECT_EQ(got.triangle, want.triangle) << what << " " << i;
    EXPECT_EQ(bits(got.u), bits(want.u)) << what << " " << i;
    EXPECT_EQ(bits(got.v), bits(want.v)) << what << " " << i;
}

// The top level of a scene with meshes is walked 8-wide too (accel/bvh_node.h), both ways.
class TwoLevelBvhWalk : public MeshBvhWalk {};
INSTANTIATE_TEST_SUITE_P(BoxTest, TwoLevelBvhWalk, ::testing::Values(true, false), test::walk_name);

TEST_P(TwoLevelBvhWalk, NearestHitWithMeshInstancesIsTheBruteForceOne) {
    const Scene scene = accelerate(mixed_scene(3, 60), 1);
    const auto& inst = scene.data.instances;
    std::mt19937 rng(3);
    int mesh_hits = 0;
    for (int i = 0; i < 4000; ++i) {
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        const glm::vec3 o = 9.0f * glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 target = 4.0f * glm::vec3(u(rng), u(rng), u(rng));
        const Ray ray{o, target - o};
        Hit got{}, want{};
        const bool g = scene.intersect(ray, got);
        const bool w = intersect_nearest_brute_force(inst, ray, 0.0f, kInf, want, &scene.data.meshes);
        ASSERT_EQ(g, w) << "ray " << i;
        if (!g) continue;
        expect_same_hit(got, want, "ray", i);
        mesh_hits += inst[got.instance].kind == ShapeKind::Mesh;
    }
    EXPECT_GT(mesh_hits, 200);
}

TEST_P(TwoLevelBvhWalk, AnyHitCountsEveryTriangleCrossedOfEveryMeshInstance) {
    const Scene scene = accelerate(mixed_scene(5, 40), 1);
    std::mt19937 rng(5);
    for (int i = 0; i < 1000; ++i) {
        std::uniform_real_distribution<float> u(-1.0f, 1.0f);
        const glm::vec3 o = 9.0f * glm::vec3(u(rng), u(rng), u(rng));
        const Ray ray{o, 4.0f * glm::vec3(u(rng), u(rng), u(rng)) - o};
        std::multiset<std::pair<std::uint32_t, int>> got, want;
        scene.visit_crossings(ray, 1.5f, [&](std::uint32_t k, int n) { got.insert({k, n}); return true; });
        for_each_crossing_brute_force(
            scene.data.instances, ray, 0.0f, 1.5f, [&](std::uint32_t k, int n) { want.insert({k, n}); return true; },
            &scene.mesh_bvhs);
        EXPECT_EQ(got, want) << "ray " << i;
        Hit h;
        EXPECT_EQ(scene.occluded(ray, 1.5f), scene.intersect(ray, h, 1.5f)) << "ray " << i;
    }
}

TEST_P(TwoLevelBvhWalk, PacketsWithMeshInstancesAreSingleRaysBitForBit) {
    const Scene scene = accelerate(mixed_scene(9, 50), 1);
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    int mesh_hits = 0;
    for (int p = 0; p < 400; ++p) {
        Ray rays[kPacketSize];
        // Camera-like packets (one origin, a small fan) and unrelated rays, alternately.
        const glm::vec3 eye = 10.0f * glm::vec3(u(rng), u(rng), u(rng));
        const glm::vec3 centre = 3.0f * glm::vec3(u(rng), u(rng), u(rng)) - eye;
        for (int l = 0; l < kPacketSize; ++l) {
            if (p % 2 == 0) {
                rays[l] = Ray{eye, centre + 0.3f * glm::vec3(float(l % 4) - 1.5f, float(l / 4) - 1.5f, 0.0f)};
            } else {
                const glm::vec3 o = 9.0f * glm::vec3(u(rng), u(rng), u(rng));
                rays[l] = Ray{o, 4.0f * glm::vec3(u(rng), u(rng), u(rng)) - o};
            }
        }
        const unsigned active = p % 3 == 0 ? 0xA5F3u : 0xFFFFu;
        const float t_max = p % 4 == 0 ? 1.0f : kInf;
        Hit hits[kPacketSize];
        const unsigned got = scene.intersect(rays, active, hits, t_max);
        for (int l = 0; l < kPacketSize; ++l) {
            if (!((active >> l) & 1)) {
                EXPECT_FALSE((got >> l) & 1);
                continue;
            }
            Hit want{};
            const bool w = scene.intersect(rays[l], want, t_max);
            ASSERT_EQ(bool((got >> l) & 1), w) << "packet " << p << " lane " << l;
            if (!w) continue;
            expect_same_hit(hits[l], want, "packet lane", p * kPacketSize + l);
            mesh_hits += scene.data.instances[want.instance].kind == ShapeKind::Mesh;
        }
    }
    EXPECT_GT(mesh_hits, 300);
}

TEST(TwoLevelBvh, SurfaceOfAMeshHitHasTheInterpolatedNormalInWorldSpace) {
    // A finely tessellated sphere with its vertex normals, placed at (1, 2, 3) and stretched 2× along
    // x: the shading normal at a hit is the ellipsoid's, (M⁻¹)ᵀ of the sphere's, to the
    // tessellation's accuracy (normals interpolated across 2° triangles).
    SceneData flat;
    flat.materials.push_back(Material{});
    flat.meshes.push_back(test::uv_sphere(90, 180));
    const glm::mat4 m = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)), glm::vec3(2, 1, 1));
    flat.instances.push_back(make_instance(m, ShapeKind::Mesh, 0));
    const Scene scene = accelerate(std::move(flat), 1);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    for (int i = 0; i < 200; ++i) {
        const glm::vec3 dir = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
        const Ray ray{glm::vec3(1, 2, 3) + 5.0f * dir, -dir};
        Hit h;
        ASSERT_TRUE(scene.intersect(ray, h)) << i;
        const Surface s = surface_at(scene, ray, h);
        // The object-space point on the unit sphere (radius 0.5), its analytic normal through (M⁻¹)ᵀ.
        const glm::vec3 p = glm::vec3(glm::inverse(m) * glm::vec4(s.point, 1.0f));
        EXPECT_NEAR(glm::length(p), 0.5f, 1e-3f) << i;
        const glm::vec3 want = glm::normalize(glm::transpose(glm::mat3(glm::inverse(m))) * glm::normalize(p));
        EXPECT_GT(glm::dot(s.normal, want), 0.9995f) << i;
        EXPECT_EQ(s.uv, glm::vec2(0.0f));  // the sphere has no vt
    }
}

TEST(MeshMemory, MeshAndItsBvhTakeAtMost100BytesPerTriangle) {
    // With normals and uvs on every corner, as a smooth textured model has.
    TriangleMesh mesh = test::uv_sphere(400, 400);  // 319,200 triangles
    mesh.uvs.assign(mesh.positions.size(), glm::vec2(0.5f));
    const MeshBvh bvh = build_mesh_bvh(mesh);
    const double per_triangle = double(mesh.memory_bytes() + bvh.memory_bytes()) / double(mesh.triangle_count());
    RecordProperty("bytes_per_triangle", std::to_string(per_triangle));
    EXPECT_LE(per_triangle, 100.0) << bvh.bvh.nodes.size() << " nodes for " << mesh.triangle_count() << " triangles";
    // Without normals and uvs (a flat, untextured mesh) it costs their values less: 12 and 8
    // bytes per vertex (the corners share one index array).
    TriangleMesh flat = test::uv_sphere(400, 400);
    BigVector<glm::vec3>().swap(flat.normals);  // (= {} would keep the capacity)
    const MeshBvh flat_bvh = build_mesh_bvh(flat);
    const double attributes = 20.0 * double(flat.positions.size()) / double(flat.triangle_count());
    EXPECT_NEAR(double(flat.memory_bytes() + flat_bvh.memory_bytes()) / double(flat.triangle_count()),
                per_triangle - attributes, 0.01);
}

TEST(MeshMemory, TenThousandInstancesShareOneMesh) {
    SceneData flat;
    flat.instances.reserve(10000);  // as flatten does, from its count
    flat.materials.push_back(Material{});
    flat.meshes.push_back(test::uv_sphere(50, 100));  // 9,900 triangles
    for (int i = 0; i < 10000; ++i) {
        Instance inst = make_instance(test::translate_scale_for_grid(i), ShapeKind::Mesh, 0);
        flat.instances.push_back(inst);
    }
    const Scene scene = accelerate(std::move(flat), 1);
    ASSERT_EQ(scene.data.meshes.size(), 1u);
    const std::size_t mesh_bytes = scene.data.meshes[0].memory_bytes() + scene.mesh_bvhs[0].memory_bytes();
    const std::size_t top_bytes = scene.data.instances.capacity() * sizeof(Instance) +
                                  scene.bvh.nodes.capacity() * sizeof(Bvh4Node) +
                                  scene.bvh.wide.nodes.capacity() * sizeof(Bvh8Node);
    EXPECT_TRUE(scene.bvh.nodes.empty()) << "a scene with meshes has its top level 8-wide only";
    // The grid's instances are apart, so every leaf holds one: 10,000 leaves need at least
    // 10,000 / 7 = 1,429 eight-wide nodes. Opening the children by area alone made 4,681, the
    // last level's nodes half empty (bvh_build.cpp's fill rule).
    EXPECT_LT(scene.bvh.wide.nodes.size(), 2 * 1429u);
    // The instances cost their records and the top-level tree, ~100 bytes each, not the mesh's
    // ~70 bytes times 9,900 triangles (the mesh is stored once).
    EXPECT_LT(top_bytes, 10000u * 200u);
    EXPECT_LT(mesh_bytes, 9900u * 100u);
    // And a ray finds the instance it aims at.
    Hit h;
    const glm::vec3 c = glm::vec3(test::translate_scale_for_grid(1234)[3]);
    ASSERT_TRUE(scene.intersect(Ray{c + glm::vec3(0, 0, 5), {0, 0, -1}}, h));
    EXPECT_NEAR(h.t, 5.0f - 0.5f, 1e-3f);
}

}  // namespace
}  // namespace whitted

namespace whitted {
namespace {

// Found by fuzzing the OBJ target: a ray whose origin had overflowed to infinity gave
// NaN in the box tests, which the SIMD min and max turned into "entered" for a wide node's unused
// slots, whose child 0 is the root: the walk went round, overflowing its stack. A ray that is not
// finite meets nothing, in every walk.
TEST(MeshBvh, ARayThatIsNotFiniteMeetsNothing) {
    TriangleMesh mesh = test::uv_sphere(6, 8);  // a few leaves under one node: unused slots too
    const MeshBvh bvh = build_mesh_bvh(mesh, 1);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (const Ray& ray : {Ray{{inf, 0.1f, 0.2f}, {-1, 0, 0}}, Ray{{3, 0.1f, 0.2f}, {-inf, 0, 0}},
                           Ray{{3, nan, 0.2f}, {-1, 0, 0}}, Ray{{3, 0.1f, 0.2f}, {nan, 0, 0}},
                           Ray{{-inf, -inf, -inf}, {inf, inf, inf}}}) {
        MeshHit hit;
        EXPECT_FALSE(mesh_intersect_nearest(bvh, ray, 0.0f, inf, hit));
        EXPECT_TRUE(mesh_for_each_crossing(bvh, ray, 0.0f, inf, [](std::uint32_t) { return false; }));
    }
    MeshHit hit;  // and a finite ray still does
    EXPECT_TRUE(mesh_intersect_nearest(bvh, Ray{{3, 0.1f, 0.2f}, {-1, 0, 0}}, 0.0f, inf, hit));
    // The top level too.
    std::vector<Instance> instances;
    for (int i = 0; i < 40; ++i)
        instances.push_back(make_instance(glm::translate(glm::mat4(1.0f), glm::vec3(float(i), 0, 0)), ShapeKind::Sphere, 0));
    const Bvh top = build_bvh(instances);
    Hit h;
    EXPECT_FALSE(intersect_nearest(top, instances, Ray{{nan, 0, 0}, {1, 0, 0}}, 0.0f, inf, h));
    EXPECT_FALSE(intersect_nearest(top, instances, Ray{{-5, 0, 0}, {inf, 0, 0}}, 0.0f, inf, h));
    EXPECT_TRUE(intersect_nearest(top, instances, Ray{{-5, 0, 0}, {1, 0, 0}}, 0.0f, inf, h));
}

}  // namespace
}  // namespace whitted
