#pragma once
// Four triangles of a mesh against one ray at once, with SSE: the watertight test of
// watertight_triangle.h done in four lanes, operation for operation as the scalar test does it
// (the same subtractions, products and sums in the same order, IEEE single precision in both, and
// the same double-precision redo of an edge function that comes out zero), so each lane's answer
// is the scalar test's bit for bit and a mesh stays watertight (tests/mesh/watertight_triangle4_test.cpp
// checks it on random rays and on rays through vertices and edges). The leaves of a mesh's BVH
// hold up to eight triangles, tested four at a time from blocks of copied corners
// (triangle_block.h). (Built with FMA contraction — e.g. -march with
// FMA and GCC's default -ffp-contract=fast — the scalar test could fuse products this one does not;
// the test above would say so.)
#include <cstdint>

#include "accel/triangle_block.h"
#include "data/triangle_mesh.h"
#include "accel/watertight_triangle.h"

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define WHITTED_TRIANGLE4_SSE 1
#endif

namespace whitted {

// Copies triangles tris[first], …, tris[first + count − 1] (1 ≤ count ≤ 4) into a block; lanes
// past `count` repeat the last triangle.
inline void fill_triangle_block(TriangleBlock& b, const glm::vec3* p, const TriangleIndices* tris, std::uint32_t first,
                                std::uint32_t count) {
    for (std::uint32_t j = 0; j < 4; ++j) {
        const TriangleIndices& c = tris[first + (j < count ? j : count - 1)];
        for (int corner = 0; corner < 3; ++corner)
            for (int axis = 0; axis < 3; ++axis) b.p[corner][axis][j] = p[c[corner]][axis];
    }
}

// Lane j's t and barycentrics (weights of the second and third corners), where its bit is set.
struct Triangle4Hits {
    alignas(16) float t[4];
    alignas(16) float u[4];
    alignas(16) float v[4];
};

#ifdef WHITTED_TRIANGLE4_SSE

// The per-ray part of WatertightRay, broadcast to four lanes.
// Default-constructed empty, for a walk that sets it up only once a leaf is reached.
struct WatertightRay4 {
    WatertightRay r;
    __m128 sx, sy, sz, ox, oy, oz;
    WatertightRay4() = default;
    explicit WatertightRay4(const WatertightRay& ray)
        : r(ray),
          sx(_mm_set1_ps(ray.sx)),
          sy(_mm_set1_ps(ray.sy)),
          sz(_mm_set1_ps(ray.sz)),
          ox(_mm_set1_ps(ray.ox)),
          oy(_mm_set1_ps(ray.oy)),
          oz(_mm_set1_ps(ray.oz)) {}
};

// The first `count` triangles of block b (1 ≤ count ≤ 4) against the ray, t in (t_min, t_max):
// bit j of the result says lane j is hit, at out.t[j], out.u[j], out.v[j].
[[gnu::always_inline]] inline int intersect_triangles4(const WatertightRay4& r4, const TriangleBlock& b,
                                                       std::uint32_t count, float t_min, float t_max,
                                                       Triangle4Hits& out) {
    const WatertightRay& r = r4.r;
    auto gather = [&b](int corner, int axis) { return _mm_load_ps(b.p[corner][axis]); };
    const __m128 a_z = _mm_sub_ps(gather(0, r.kz), r4.oz);
    const __m128 b_z = _mm_sub_ps(gather(1, r.kz), r4.oz);
    const __m128 c_z = _mm_sub_ps(gather(2, r.kz), r4.oz);
    const __m128 ax = _mm_sub_ps(_mm_sub_ps(gather(0, r.kx), r4.ox), _mm_mul_ps(r4.sx, a_z));
    const __m128 ay = _mm_sub_ps(_mm_sub_ps(gather(0, r.ky), r4.oy), _mm_mul_ps(r4.sy, a_z));
    const __m128 bx = _mm_sub_ps(_mm_sub_ps(gather(1, r.kx), r4.ox), _mm_mul_ps(r4.sx, b_z));
    const __m128 by = _mm_sub_ps(_mm_sub_ps(gather(1, r.ky), r4.oy), _mm_mul_ps(r4.sy, b_z));
    const __m128 cx = _mm_sub_ps(_mm_sub_ps(gather(2, r.kx), r4.ox), _mm_mul_ps(r4.sx, c_z));
    const __m128 cy = _mm_sub_ps(_mm_sub_ps(gather(2, r.ky), r4.oy), _mm_mul_ps(r4.sy, c_z));
    __m128 e0 = _mm_sub_ps(_mm_mul_ps(cx, by), _mm_mul_ps(cy, bx));
    __m128 e1 = _mm_sub_ps(_mm_mul_ps(ax, cy), _mm_mul_ps(ay, cx));
    __m128 e2 = _mm_sub_ps(_mm_mul_ps(bx, ay), _mm_mul_ps(by, ax));
    const __m128 zero = _mm_setzero_ps();
    const int lanes = (1 << count) - 1;
    // An edge function exactly zero: that lane's three are redone in double, as the scalar test does.
    const int redo = lanes & _mm_movemask_ps(_mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(e0, zero), _mm_cmpeq_ps(e1, zero)),
                                                       _mm_cmpeq_ps(e2, zero)));
    if (redo != 0) {
        alignas(16) float fax[4], fay[4], fbx[4], fby[4], fcx[4], fcy[4], f0[4], f1[4], f2[4];
        _mm_store_ps(fax, ax), _mm_store_ps(fay, ay), _mm_store_ps(fbx, bx), _mm_store_ps(fby, by);
        _mm_store_ps(fcx, cx), _mm_store_ps(fcy, cy);
        _mm_store_ps(f0, e0), _mm_store_ps(f1, e1), _mm_store_ps(f2, e2);
        for (int j = 0; j < 4; ++j) {
            if (!((redo >> j) & 1)) continue;
            f0[j] = float(double(fcx[j]) * double(fby[j]) - double(fcy[j]) * double(fbx[j]));
            f1[j] = float(double(fax[j]) * double(fcy[j]) - double(fay[j]) * double(fcx[j]));
            f2[j] = float(double(fbx[j]) * double(fay[j]) - double(fby[j]) * double(fax[j]));
        }
        e0 = _mm_load_ps(f0), e1 = _mm_load_ps(f1), e2 = _mm_load_ps(f2);
    }
    // Inside: no edge function negative, or none positive (two-sided).
    const __m128 neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(e0, zero), _mm_cmplt_ps(e1, zero)), _mm_cmplt_ps(e2, zero));
    const __m128 pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(e0, zero), _mm_cmpgt_ps(e1, zero)), _mm_cmpgt_ps(e2, zero));
    const __m128 det = _mm_add_ps(_mm_add_ps(e0, e1), e2);
    __m128 ok = _mm_andnot_ps(_mm_and_ps(neg, pos), _mm_cmpneq_ps(det, zero));
    if ((_mm_movemask_ps(ok) & lanes) == 0) return 0;
    const __m128 az = _mm_mul_ps(r4.sz, a_z), bz = _mm_mul_ps(r4.sz, b_z), cz = _mm_mul_ps(r4.sz, c_z);
    const __m128 inv_det = _mm_div_ps(_mm_set1_ps(1.0f), det);
    const __m128 t = _mm_mul_ps(
        _mm_add_ps(_mm_add_ps(_mm_mul_ps(e0, az), _mm_mul_ps(e1, bz)), _mm_mul_ps(e2, cz)), inv_det);
    ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmpgt_ps(t, _mm_set1_ps(t_min)), _mm_cmplt_ps(t, _mm_set1_ps(t_max))));
    const int mask = _mm_movemask_ps(ok) & lanes;
    if (mask == 0) return 0;
    _mm_store_ps(out.t, t);
    _mm_store_ps(out.u, _mm_mul_ps(e1, inv_det));
    _mm_store_ps(out.v, _mm_mul_ps(e2, inv_det));
    return mask;
}

#else  // no SSE: the scalar test, one lane at a time

struct WatertightRay4 {
    WatertightRay r;
    WatertightRay4() = default;
    explicit WatertightRay4(const WatertightRay& ray) : r(ray) {}
};

[[gnu::always_inline]] inline int intersect_triangles4(const WatertightRay4& r4, const TriangleBlock& b,
                                                       std::uint32_t count, float t_min, float t_max,
                                                       Triangle4Hits& out) {
    int mask = 0;
    for (std::uint32_t j = 0; j < count; ++j) {
        auto corner = [&](int c) { return glm::vec3(b.p[c][0][j], b.p[c][1][j], b.p[c][2][j]); };
        TriangleHit h;
        if (!intersect_triangle(r4.r, corner(0), corner(1), corner(2), t_min, t_max, h)) continue;
        out.t[j] = h.t, out.u[j] = h.u, out.v[j] = h.v;
        mask |= 1 << j;
    }
    return mask;
}

#endif

}  // namespace whitted
