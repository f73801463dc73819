#pragma once
// The single-ray box test of the 4-wide BVH, shared by the nearest-hit traversal
// (bvh_traverse.cpp) and the any-hit traversal (bvh_any_hit.h): one SSE test gives a ray's
// entry distance into all four child boxes.
#include <algorithm>
#include <cmath>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define WHITTED_BVH_SSE 1
#endif

#include "accel/bvh_node.h"
#include "accel/bvh_ray.h"

namespace whitted::bvh_detail {

// The ray as the box test wants it: origin, reciprocal direction (bvh_ray.h) and which box row
// is the near plane per axis.
// A ray whose origin or direction is not finite (an object-space ray of an object far from the
// origin and scaled far down overflows) meets nothing: its box tests would give NaN, which the
// SIMD min and max can turn into "entered" for a node's unused slots (boxes +inf..-inf), whose
// child 0 is the root, and the walk would go round forever (found by fuzzing).
struct BoxRay {
    float o[3], inv[3];
    int near_row[3], far_row[3];
    bool finite = true;
    explicit BoxRay(const Ray& r) {
        for (int a = 0; a < 3; ++a) {
            o[a] = r.origin[a];
            inv[a] = safe_reciprocal(r.direction[a]);
            const bool neg = std::signbit(inv[a]);
            near_row[a] = neg ? 3 + a : a;
            far_row[a] = neg ? a : 3 + a;
            finite = finite && std::isfinite(r.origin[a]) && std::isfinite(r.direction[a]);
        }
    }
};

// Entry distances of the ray into the node's four boxes (t_near[i]); returns the mask of the
// boxes entered within (t_min, t_max). Near/far planes are chosen by the direction's sign, so no
// min/max per axis is needed.
#ifdef WHITTED_BVH_SSE
// A query's bound on t as the box test wants it (broadcast): the walks make their constant
// bounds once per query rather than once per node.
using BoxLimit = __m128;
inline BoxLimit box_limit(float t) { return _mm_set1_ps(t); }

struct BoxTester {
    using Limit = BoxLimit;
    __m128 o[3], inv[3];
    const BoxRay& r;
    explicit BoxTester(const BoxRay& ray) : r(ray) {
        for (int a = 0; a < 3; ++a) {
            o[a] = _mm_set1_ps(ray.o[a]);
            inv[a] = _mm_set1_ps(ray.inv[a]);
        }
    }
    Limit limit(float t) const { return box_limit(t); }
    // Slots s0 … s0 + 3 of a node of any width.
    template <int W>
    int test_slots(const float (&box)[6][W], int s0, BoxLimit t_min, BoxLimit t_max, float* t_near) const {
        const __m128 nx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&box[r.near_row[0]][s0]), o[0]), inv[0]);
        const __m128 ny = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&box[r.near_row[1]][s0]), o[1]), inv[1]);
        const __m128 nz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&box[r.near_row[2]][s0]), o[2]), inv[2]);
        const __m128 fx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&box[r.far_row[0]][s0]), o[0]), inv[0]);
        const __m128 fy = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&box[r.far_row[1]][s0]), o[1]), inv[1]);
        const __m128 fz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(&box[r.far_row[2]][s0]), o[2]), inv[2]);
        const __m128 enter = _mm_max_ps(_mm_max_ps(nx, ny), _mm_max_ps(nz, t_min));
        const __m128 leave = _mm_min_ps(_mm_min_ps(fx, fy), _mm_min_ps(fz, t_max));
        _mm_storeu_ps(t_near, enter);
        return _mm_movemask_ps(_mm_cmple_ps(enter, leave));
    }
    int test(const Bvh4Node& n, BoxLimit t_min, BoxLimit t_max, float t_near[4]) const {
        return test_slots(n.box, 0, t_min, t_max, t_near);
    }
    // An 8-wide node in two halves (where the CPU lacks AVX2: bvh_box_test_avx2.h).
    int test(const Bvh8Node& n, BoxLimit t_min, BoxLimit t_max, float t_near[8]) const {
        return test_slots(n.box, 0, t_min, t_max, t_near) | test_slots(n.box, 4, t_min, t_max, t_near + 4) << 4;
    }
};
#else
using BoxLimit = float;
inline BoxLimit box_limit(float t) { return t; }

struct BoxTester {
    using Limit = BoxLimit;
    const BoxRay& r;
    explicit BoxTester(const BoxRay& ray) : r(ray) {}
    Limit limit(float t) const { return t; }
    template <int W>
    int test(const BvhNode<W>& n, BoxLimit t_min, BoxLimit t_max, float t_near[W]) const {
        int mask = 0;
        for (int s = 0; s < W; ++s) {
            float enter = t_min, leave = t_max;
            for (int a = 0; a < 3; ++a) {
                enter = std::max((n.box[r.near_row[a]][s] - r.o[a]) * r.inv[a], enter);
                leave = std::min((n.box[r.far_row[a]][s] - r.o[a]) * r.inv[a], leave);
            }
            t_near[s] = enter;
            mask |= int(enter <= leave) << s;
        }
        return mask;
    }
};
#endif

inline int lowest_bit(int mask) { return __builtin_ctz(unsigned(mask)); }

}  // namespace whitted::bvh_detail
