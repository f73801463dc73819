// The ray–triangle test against hand-computed hits, and the watertightness of a closed mesh: rays
// aimed exactly at its vertices and along its edges never pass between two triangles.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accel/mesh_bvh.h"
#include "accel/watertight_triangle.h"
#include "mesh/mesh_test_support.h"

namespace whitted {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

bool hit(const Ray& ray, glm::vec3 a, glm::vec3 b, glm::vec3 c, TriangleHit& h, float t_max = kInf) {
    return intersect_triangle(WatertightRay(ray), a, b, c, 0.0f, t_max, h);
}

TEST(WatertightTriangle, HitsAtTheAnalyticDistanceAndBarycentrics) {
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
    TriangleHit h;
    // Straight down onto (0.25, 0.25): t = 1, weights of b and c are the point's x and y.
    ASSERT_TRUE(hit(Ray{{0.25f, 0.25f, 1}, {0, 0, -1}}, a, b, c, h));
    EXPECT_FLOAT_EQ(h.t, 1.0f);
    EXPECT_FLOAT_EQ(h.u, 0.25f);
    EXPECT_FLOAT_EQ(h.v, 0.25f);
    // An unnormalised direction keeps its own t: from z = 2 with d = (0, 0, -4), the plane is at t = 0.5.
    ASSERT_TRUE(hit(Ray{{0.2f, 0.3f, 2}, {0, 0, -4}}, a, b, c, h));
    EXPECT_FLOAT_EQ(h.t, 0.5f);
    EXPECT_FLOAT_EQ(h.u, 0.2f);
    EXPECT_FLOAT_EQ(h.v, 0.3f);
    // From behind: triangles are two-sided.
    ASSERT_TRUE(hit(Ray{{0.1f, 0.6f, -3}, {0, 0, 1}}, a, b, c, h));
    EXPECT_FLOAT_EQ(h.t, 3.0f);
    EXPECT_FLOAT_EQ(h.u, 0.1f);
    EXPECT_FLOAT_EQ(h.v, 0.6f);
    // Outside the hypotenuse x + y = 1, and beyond the corners.
    EXPECT_FALSE(hit(Ray{{0.6f, 0.6f, 1}, {0, 0, -1}}, a, b, c, h));
    EXPECT_FALSE(hit(Ray{{-0.1f, 0.5f, 1}, {0, 0, -1}}, a, b, c, h));
    // Parallel to the plane, in it or not.
    EXPECT_FALSE(hit(Ray{{-1, 0.2f, 0}, {1, 0, 0}}, a, b, c, h));
    EXPECT_FALSE(hit(Ray{{-1, 0.2f, 1}, {1, 0, 0}}, a, b, c, h));
    // Behind the origin, and beyond t_max.
    EXPECT_FALSE(hit(Ray{{0.25f, 0.25f, -1}, {0, 0, -1}}, a, b, c, h));
    EXPECT_FALSE(hit(Ray{{0.25f, 0.25f, 1}, {0, 0, -1}}, a, b, c, h, 0.999f));
}

TEST(WatertightTriangle, SlantedTriangleAndRay) {
    // The triangle x + y + z = 1 between the unit axis points; the ray from the origin along
    // (1, 1, 1) meets it at its centroid (1/3, 1/3, 1/3): t = 1/3, all weights 1/3.
    TriangleHit h;
    ASSERT_TRUE(hit(Ray{{0, 0, 0}, {1, 1, 1}}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, h));
    EXPECT_NEAR(h.t, 1.0f / 3.0f, 1e-6f);
    EXPECT_NEAR(h.u, 1.0f / 3.0f, 1e-6f);
    EXPECT_NEAR(h.v, 1.0f / 3.0f, 1e-6f);
    // Along (2, 1, 1) from the origin: the plane at t = 1/4, the point (1/2, 1/4, 1/4), whose
    // weights are its coordinates (a point of the plane is x·e1 + y·e2 + z·e3).
    ASSERT_TRUE(hit(Ray{{0, 0, 0}, {2, 1, 1}}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, h));
    EXPECT_NEAR(h.t, 0.25f, 1e-6f);
    EXPECT_NEAR(h.u, 0.25f, 1e-6f);
    EXPECT_NEAR(h.v, 0.25f, 1e-6f);
    // Every axis as the dominant one, both signs: the same point reached from each side.
    const glm::vec3 p(0.2f, 0.3f, 0.5f);
    for (int axis = 0; axis < 3; ++axis)
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 d(0.1f, -0.2f, 0.15f);
            d[axis] = 2.0f * sign;
            ASSERT_TRUE(hit(Ray{p - d, d}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, h)) << axis << " " << sign;
            EXPECT_NEAR(h.t, 1.0f, 1e-5f);
            EXPECT_NEAR(h.u, 0.3f, 1e-5f);
            EXPECT_NEAR(h.v, 0.5f, 1e-5f);
        }
}

// The distinct surface crossings of the ray: all crossing distances, those within `merge` of the
// previous one counted once (a ray through a vertex or an edge meets every triangle around it
// at the same point).
int distinct_crossings(const TriangleMesh& mesh, const MeshBvh& bvh, const Ray& ray, float t_max, float merge) {
    std::vector<float> ts;
    const WatertightRay wr(ray);
    mesh_for_each_crossing(bvh, ray, 0.0f, t_max, [&](std::uint32_t t) {
        const TriangleIndices& c = mesh.triangles[t];
        TriangleHit h;
        if (intersect_triangle(wr, mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]], 0.0f, t_max, h))
            ts.push_back(h.t);
        return true;
    });
    std::sort(ts.begin(), ts.end());
    int n = 0;
    for (std::size_t i = 0; i < ts.size(); ++i)
        if (i == 0 || ts[i] - ts[i - 1] > merge) ++n;
    return n;
}

#if defined(__SANITIZE_ADDRESS__)
constexpr int kWatertightRays = 1 << 16;  // the sanitizer build is ~10x slower
#else
constexpr int kWatertightRays = 1 << 19;  // three queries each: 1.5 million
#endif

TEST(WatertightMesh, RaysThroughVerticesAndEdgesEnterAndLeaveExactlyOnce) {
    TriangleMesh sphere = test::uv_sphere(24, 48, 0.5f);
    const MeshBvh bvh = build_mesh_bvh(sphere, 1);
    std::mt19937 rng(16);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), frac(0.0f, 1.0f);
    std::uniform_int_distribution<std::size_t> pick(0, sphere.triangles.size() - 1);
    int failures = 0;
    for (int i = 0; i < kWatertightRays && failures < 10; ++i) {
        // A point exactly on a vertex (half the rays) or on an edge (in float, as near as it gets),
        // and a line from a random point well inside through it.
        const TriangleIndices& tri = sphere.triangles[pick(rng)];
        const int k = i % 3;
        const glm::vec3 a = sphere.positions[tri[k]], b = sphere.positions[tri[(k + 1) % 3]];
        const glm::vec3 target = (i & 1) ? a : a + frac(rng) * (b - a);
        const glm::vec3 inside = 0.2f * glm::vec3(unit(rng), unit(rng), unit(rng));
        const glm::vec3 dir = target - inside;
        // From outside, through the target and on through the inside point: in once, out once.
        const Ray through{target + 2.0f * dir, -dir};
        const int n_through = distinct_crossings(sphere, bvh, through, kInf, 1e-4f);
        // From inside out through the target: once.
        const Ray out{inside, dir};
        const int n_out = distinct_crossings(sphere, bvh, out, kInf, 1e-4f);
        MeshHit h;
        const bool entered = mesh_intersect_nearest(bvh, through, 0.0f, kInf, h);
        if (n_through != 2 || n_out != 1 || !entered || std::abs(h.t - 2.0f) > 1e-3f) {
            ++failures;
            ADD_FAILURE() << "ray " << i << ": " << n_through << " crossings through, " << n_out << " out, entered "
                          << entered << " at " << h.t << " (want 2)";
        }
    }
    EXPECT_EQ(failures, 0);
}

}  // namespace
}  // namespace whitted
