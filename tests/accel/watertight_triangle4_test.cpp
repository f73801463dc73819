// The four-lane triangle test (mesh/watertight_triangle4.h) against the scalar watertight test it
// must reproduce bit for bit: random triangles and rays, rays through the corners and along the
// edges of a closed mesh (where edge functions come out zero and are redone in double), rays along
// each axis in both directions, groups of one to four triangles, and t ranges that cut hits off.
#include <bit>
#include <cstdint>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accel/watertight_triangle4.h"
#include "mesh/mesh_test_support.h"

namespace whitted {
namespace {

std::uint32_t bits(float f) { return std::bit_cast<std::uint32_t>(f); }

struct Counts {
    int hits = 0, misses = 0;
};

// Every group of `count` consecutive triangles from `first`, lane by lane against the scalar test.
void expect_lanes_match(const TriangleMesh& mesh, const Ray& ray, std::uint32_t first, std::uint32_t count,
                        float t_min, float t_max, Counts& counts, const char* what, int i) {
    const WatertightRay wr(ray);
    const WatertightRay4 wr4(wr);
    Triangle4Hits h4;
    TriangleBlock block;
    fill_triangle_block(block, mesh.positions.data(), mesh.triangles.data(), first, count);
    const int mask = intersect_triangles4(wr4, block, count, t_min, t_max, h4);
    EXPECT_EQ(mask >> count, 0) << what << " " << i << ": lanes past the group set";
    for (std::uint32_t j = 0; j < count; ++j) {
        const TriangleIndices& c = mesh.triangles[first + j];
        TriangleHit h{};
        const bool want =
            intersect_triangle(wr, mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]], t_min, t_max, h);
        ASSERT_EQ(bool((mask >> j) & 1), want) << what << " " << i << " lane " << j;
        if (!want) {
            ++counts.misses;
            continue;
        }
        ++counts.hits;
        EXPECT_EQ(bits(h4.t[j]), bits(h.t)) << what << " " << i << " lane " << j;
        EXPECT_EQ(bits(h4.u[j]), bits(h.u)) << what << " " << i << " lane " << j;
        EXPECT_EQ(bits(h4.v[j]), bits(h.v)) << what << " " << i << " lane " << j;
    }
}

TEST(WatertightTriangle4, RandomTrianglesAndRaysAreTheScalarTestBitForBit) {
    const TriangleMesh soup = test::random_soup(400, 21);
    std::mt19937 rng(21);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Counts counts;
    for (int i = 0; i < 4000; ++i) {
        const std::uint32_t count = 1 + std::uint32_t(i % 4);
        const std::uint32_t first = std::uint32_t(rng() % (soup.triangles.size() - 3));
        // Aim at a point of one of the group's triangles half the time, so that lanes hit.
        glm::vec3 target = 0.8f * glm::vec3(u(rng), u(rng), u(rng));
        if (i % 2 == 0) {
            const TriangleIndices& c = soup.triangles[first + std::uint32_t(i / 2) % count];
            const float a = 0.5f * (u(rng) + 1.0f), b = 0.5f * (u(rng) + 1.0f) * (1.0f - a);
            target = soup.positions[c[0]] + a * (soup.positions[c[1]] - soup.positions[c[0]]) +
                     b * (soup.positions[c[2]] - soup.positions[c[0]]);
        }
        const glm::vec3 o = 3.0f * glm::vec3(u(rng), u(rng), u(rng));
        const float t_min = i % 7 == 0 ? 0.9f : 0.0f, t_max = i % 5 == 0 ? 1.0f : 1e30f;
        expect_lanes_match(soup, Ray{o, target - o}, first, count, t_min, t_max, counts, "ray", i);
    }
    EXPECT_GT(counts.hits, 1500);
    EXPECT_GT(counts.misses, 1500);
}

TEST(WatertightTriangle4, RaysThroughCornersAndEdgesAreTheScalarTestBitForBit) {
    // A closed sphere: rays from outside aimed exactly at a vertex or at an edge's midpoint (a
    // point the rounding may put on either side, or exactly on the edge), and axis-aligned rays
    // (whose shear is zero, so that edge functions are often exactly zero), both directions.
    const TriangleMesh sphere = test::uv_sphere(10, 20);
    const std::uint32_t n = std::uint32_t(sphere.triangles.size());
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-1.0f, 1.0f);
    Counts counts;
    int ray_index = 0;
    for (std::uint32_t t = 0; t < n; ++t) {
        const TriangleIndices& c = sphere.triangles[t];
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 a = sphere.positions[c[k]], b = sphere.positions[c[(k + 1) % 3]];
            for (const glm::vec3& target : {a, 0.5f * (a + b)}) {
                const glm::vec3 o = 2.0f * glm::vec3(u(rng), u(rng), u(rng));
                const glm::vec3 dir = target - o;
                glm::vec3 axis_dir(0.0f);
                const int axis = int(rng() % 3);
                axis_dir[axis] = rng() % 2 ? 1.0f : -1.0f;
                // Every group containing t, in each of its lane positions.
                for (const Ray& ray : {Ray{o, dir}, Ray{target - 3.0f * axis_dir, axis_dir}}) {
                    for (std::uint32_t count = 1; count <= 4; ++count) {
                        const std::uint32_t first = t >= count - 1 ? t - (t % count) : 0;
                        if (first + count > n) continue;
                        expect_lanes_match(sphere, ray, first, count, 0.0f, 1e30f, counts, "ray", ray_index);
                    }
                    ++ray_index;
                }
            }
        }
    }
    EXPECT_GT(counts.hits, 2000);
}

}  // namespace
}  // namespace whitted
