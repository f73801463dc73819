// The box tests of the wide nodes: an 8-wide node tested in two SSE halves and in one AVX2 step
// (accel/bvh_box_test_avx2.h) against the slab test written out in scalar floats, slot by slot:
// the same mask and the same entry distances, bit for bit, on random boxes (some empty, some
// flat) and random rays, some with a zero direction component; and where a slot is entered, the
// ray at its entry distance is in the box.
#include <bit>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "accel/bvh_box_test_avx2.h"

namespace whitted::bvh_detail {
namespace {

// SSE's maxps / minps: the second operand unless the first is strictly greater / smaller.
float max_ps(float a, float b) { return a > b ? a : b; }
float min_ps(float a, float b) { return a < b ? a : b; }

// Slot s by the slab test: entry = the farthest near plane (and t_min), exit = the nearest far
// plane (and t_max), entered when entry <= exit; in the order the SIMD tests combine them.
bool slab(const Bvh8Node& n, int s, const BoxRay& r, float t_min, float t_max, float& entry) {
    float near[3], far[3];
    for (int a = 0; a < 3; ++a) {
        near[a] = (n.box[r.near_row[a]][s] - r.o[a]) * r.inv[a];
        far[a] = (n.box[r.far_row[a]][s] - r.o[a]) * r.inv[a];
    }
    entry = max_ps(max_ps(near[0], near[1]), max_ps(near[2], t_min));
    const float exit = min_ps(min_ps(far[0], far[1]), min_ps(far[2], t_max));
    return entry <= exit;
}

Bvh8Node random_node(std::mt19937& rng) {
    std::uniform_real_distribution<float> u(-4.0f, 4.0f), size(0.0f, 3.0f);
    Bvh8Node n{};
    for (int s = 0; s < 8; ++s) {
        const unsigned kind = rng() % 8;
        for (int a = 0; a < 3; ++a) {
            const float lo = u(rng);
            n.box[a][s] = lo;
            n.box[3 + a][s] = kind == 1 && a == 1 ? lo : lo + size(rng);  // kind 1: flat in y
        }
        if (kind == 0)  // an unused slot: the empty box
            for (int a = 0; a < 3; ++a) n.box[a][s] = INFINITY, n.box[3 + a][s] = -INFINITY;
    }
    return n;
}

Ray random_ray(std::mt19937& rng, int i) {
    std::uniform_real_distribution<float> u(-6.0f, 6.0f);
    Ray r{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}};
    if (i % 5 == 0) r.direction[i % 3] = 0.0f;  // parallel to a slab: the huge finite reciprocal
    return r;
}

TEST(WideBoxTest, EightWideNodeInSseHalvesAndInAvx2IsTheSlabTestBitForBit) {
    std::mt19937 rng(8);
    int entered = 0, missed = 0;
#ifdef WHITTED_BVH_AVX2
    const bool avx2 = cpu_has_avx2();
#endif
    for (int i = 0; i < 20000; ++i) {
        const Bvh8Node n = random_node(rng);
        Ray ray = random_ray(rng, i);
        const int aim = i % 8;  // half the rays aimed at a slot's centre, so that many enter
        if (i % 2 == 0 && n.box[0][aim] <= n.box[3][aim])
            ray.direction = 0.5f * glm::vec3(n.box[0][aim] + n.box[3][aim], n.box[1][aim] + n.box[4][aim],
                                             n.box[2][aim] + n.box[5][aim]) - ray.origin;
        const float t_min = i % 3 == 0 ? 0.5f : 0.0f, t_max = i % 4 == 0 ? 1.5f : INFINITY;
        const BoxRay box_ray(ray);
        const BoxTester sse(box_ray);
        float t_sse[8];
        const int mask_sse = sse.test(n, sse.limit(t_min), sse.limit(t_max), t_sse);
        for (int s = 0; s < 8; ++s) {
            float entry;
            const bool want = slab(n, s, box_ray, t_min, t_max, entry);
            ASSERT_EQ(bool((mask_sse >> s) & 1), want) << "ray " << i << " slot " << s;
            if (!want) {
                ++missed;
                continue;
            }
            ++entered;
            EXPECT_EQ(std::bit_cast<std::uint32_t>(t_sse[s]), std::bit_cast<std::uint32_t>(entry));
            // Entered: the ray at its entry distance lies in the box (to rounding).
            if (std::isfinite(entry) && ray.direction != glm::vec3(0.0f)) {
                const glm::vec3 p = ray.at(entry);
                for (int a = 0; a < 3; ++a) {
                    const float tol = 1e-4f * (1.0f + std::fabs(p[a]));
                    if (ray.direction[a] == 0.0f) continue;  // the huge reciprocal: no meaningful point
                    EXPECT_GE(p[a], n.box[a][s] - tol) << "ray " << i << " slot " << s;
                    EXPECT_LE(p[a], n.box[3 + a][s] + tol) << "ray " << i << " slot " << s;
                }
            }
        }
#ifdef WHITTED_BVH_AVX2
        if (!avx2) continue;
        const BoxTesterAvx2 wide(box_ray);
        float t_avx[8];
        const int mask_avx = wide.test(n, wide.limit(t_min), wide.limit(t_max), t_avx);
        ASSERT_EQ(mask_avx, mask_sse) << "ray " << i;
        for (int s = 0; s < 8; ++s) {
            if ((mask_sse >> s) & 1) {
                EXPECT_EQ(std::bit_cast<std::uint32_t>(t_avx[s]), std::bit_cast<std::uint32_t>(t_sse[s])) << s;
            }
        }
#endif
    }
    EXPECT_GT(entered, 8000);
    EXPECT_GT(missed, 8000);
}

}  // namespace
}  // namespace whitted::bvh_detail
