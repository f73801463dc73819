#pragma once
// The 8-wide node's box test in one AVX2 step (Embree's BVH8 does the same), for the CPUs that
// have it; the same operations as the SSE test (bvh_box_test.h), so the same masks and entry
// distances. The member functions carry GCC's target attribute, so the rest of whitted stays
// baseline x86-64: a walk that uses this tester is compiled into a function with the same
// attribute and [[gnu::flatten]] (mesh/mesh_bvh.h), and runs only where the CPU reports AVX2.
#include "accel/bvh_box_test.h"

#if defined(WHITTED_BVH_SSE) && defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define WHITTED_BVH_AVX2 1

namespace whitted::bvh_detail {

// Whether this CPU runs AVX2 code.
inline bool cpu_has_avx2() { return __builtin_cpu_supports("avx2"); }

struct BoxTesterAvx2 {
    // Broadcast inside the test: a __m256 passed through the walk template (compiled for the
    // baseline) would change its calling convention.
    using Limit = float;
    __m256 o[3], inv[3];
    const BoxRay& r;
    [[gnu::target("avx2")]] explicit BoxTesterAvx2(const BoxRay& ray) : r(ray) {
        for (int a = 0; a < 3; ++a) {
            o[a] = _mm256_set1_ps(ray.o[a]);
            inv[a] = _mm256_set1_ps(ray.inv[a]);
        }
    }
    Limit limit(float t) const { return t; }
    [[gnu::target("avx2")]] int test(const Bvh8Node& n, Limit t_min, Limit t_max, float t_near[8]) const {
        const __m256 nx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.box[r.near_row[0]]), o[0]), inv[0]);
        const __m256 ny = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.box[r.near_row[1]]), o[1]), inv[1]);
        const __m256 nz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.box[r.near_row[2]]), o[2]), inv[2]);
        const __m256 fx = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.box[r.far_row[0]]), o[0]), inv[0]);
        const __m256 fy = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.box[r.far_row[1]]), o[1]), inv[1]);
        const __m256 fz = _mm256_mul_ps(_mm256_sub_ps(_mm256_load_ps(n.box[r.far_row[2]]), o[2]), inv[2]);
        const __m256 enter = _mm256_max_ps(_mm256_max_ps(nx, ny), _mm256_max_ps(nz, _mm256_set1_ps(t_min)));
        const __m256 leave = _mm256_min_ps(_mm256_min_ps(fx, fy), _mm256_min_ps(fz, _mm256_set1_ps(t_max)));
        _mm256_storeu_ps(t_near, enter);
        return _mm256_movemask_ps(_mm256_cmp_ps(enter, leave, _CMP_LE_OS));
    }
};

}  // namespace whitted::bvh_detail
#endif
