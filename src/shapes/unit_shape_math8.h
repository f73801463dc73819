#pragma once
// The unit shapes' ray intersection eight rays at a time (AVX2 lanes): unit_shape_math4.h with
// each SSE operation replaced by its AVX2 twin, operation for operation and operand for operand,
// so that every lane gets the bits the scalar code gives (comparisons keep SSE's treatment of
// NaN: _mm_cmpge_ps is _CMP_GE_OS, _mm_cmpneq_ps _CMP_NEQ_UQ, _mm_cmpngt_ps _CMP_NGT_US). Every
// function carries GCC's target attribute, so the rest of whitted stays baseline x86-64: the
// packet walk that uses them is compiled into a function with the same attribute and
// [[gnu::flatten]] (accel/bvh_packet.cpp), run only where the CPU has AVX2. No FMA: a contracted
// multiply-add would round differently from the scalar code.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>

#include <limits>

#include "data/instance.h"
#include "shapes/unit_shapes.h"

#define WHITTED_SHAPES_AVX2 1

namespace whitted::packet_shapes {

#define WHITTED_AVX2 [[gnu::target("avx2")]] inline

// Eight lanes' intervals, as Span4.
struct Span8 {
    __m256 ok, t0, t1;
    __m256i part0, part1;
};

WHITTED_AVX2 __m256 select(__m256 mask, __m256 a, __m256 b) {
    return _mm256_or_ps(_mm256_and_ps(mask, a), _mm256_andnot_ps(mask, b));
}
WHITTED_AVX2 __m256i select(__m256 mask, __m256i a, __m256i b) {
    const __m256i m = _mm256_castps_si256(mask);
    return _mm256_or_si256(_mm256_and_si256(m, a), _mm256_andnot_si256(m, b));
}
WHITTED_AVX2 __m256 sign_bit8() { return _mm256_set1_ps(-0.0f); }
WHITTED_AVX2 __m256 infinity8() { return _mm256_set1_ps(std::numeric_limits<float>::infinity()); }
WHITTED_AVX2 __m256i part8(ShapePart p) { return _mm256_set1_epi32(int(p)); }

WHITTED_AVX2 __m256 dot3(__m256 ax, __m256 ay, __m256 az, __m256 bx, __m256 by, __m256 bz) {
    return _mm256_add_ps(_mm256_add_ps(_mm256_mul_ps(ax, bx), _mm256_mul_ps(ay, by)), _mm256_mul_ps(az, bz));
}

// to_object_space4.
WHITTED_AVX2 void to_object_space8(const Instance& inst, const __m256 (&o)[3], const __m256 (&d)[3], __m256 (&oo)[3],
                                   __m256 (&od)[3]) {
    const glm::vec4* w = inst.world_to_object;
    for (int k = 0; k < 3; ++k) {
        const __m256 wx = _mm256_set1_ps(w[k].x), wy = _mm256_set1_ps(w[k].y), wz = _mm256_set1_ps(w[k].z);
        oo[k] = _mm256_add_ps(dot3(wx, wy, wz, o[0], o[1], o[2]), _mm256_set1_ps(w[k].w));
        od[k] = dot3(wx, wy, wz, d[0], d[1], d[2]);
    }
}

// solve_quadratic4.
WHITTED_AVX2 void solve_quadratic8(__m256 a, __m256 hb, __m256 c, __m256 disc, __m256& t0, __m256& t1) {
    const __m256 sign = sign_bit8();
    const __m256 root = _mm256_sqrt_ps(disc);
    const __m256 q =
        _mm256_xor_ps(_mm256_add_ps(hb, _mm256_or_ps(_mm256_andnot_ps(sign, root), _mm256_and_ps(sign, hb))), sign);
    const __m256 r0 = _mm256_div_ps(q, a);
    const __m256 r1 = _mm256_and_ps(_mm256_cmp_ps(q, _mm256_setzero_ps(), _CMP_NEQ_UQ), _mm256_div_ps(c, q));
    t0 = _mm256_min_ps(r1, r0);
    t1 = _mm256_max_ps(r1, r0);
}

// clip_slab4.
WHITTED_AVX2 void clip_slab8(__m256 o, __m256 d, ShapePart lo_part, ShapePart hi_part, __m256& tin, __m256& tout,
                             __m256i& pin, __m256i& pout) {
    const __m256 sign = sign_bit8();
    const __m256 inv = _mm256_div_ps(_mm256_set1_ps(1.0f), d);
    const __m256 far_plane = _mm256_or_ps(_mm256_and_ps(sign, inv), _mm256_set1_ps(0.5f));
    const __m256 tn = _mm256_mul_ps(_mm256_sub_ps(_mm256_xor_ps(far_plane, sign), o), inv);
    const __m256 tf = _mm256_mul_ps(_mm256_sub_ps(far_plane, o), inv);
    const __m256 neg = _mm256_castsi256_ps(_mm256_srai_epi32(_mm256_castps_si256(inv), 31));
    const __m256i pn = select(neg, part8(hi_part), part8(lo_part)), pf = select(neg, part8(lo_part), part8(hi_part));
    const __m256 take_n = _mm256_cmp_ps(tn, tin, _CMP_GT_OS), take_f = _mm256_cmp_ps(tf, tout, _CMP_LT_OS);
    tin = _mm256_max_ps(tn, tin);
    tout = _mm256_min_ps(tf, tout);
    pin = select(take_n, pn, pin);
    pout = select(take_f, pf, pout);
}

// finish4.
WHITTED_AVX2 __m256 finish8(__m256 tin, __m256 tout) {
    const __m256 sign = sign_bit8(), inf = infinity8();
    return _mm256_and_ps(_mm256_cmp_ps(tin, tout, _CMP_LE_OS),
                         _mm256_and_ps(_mm256_cmp_ps(_mm256_andnot_ps(sign, tin), inf, _CMP_LT_OS),
                                       _mm256_cmp_ps(_mm256_andnot_ps(sign, tout), inf, _CMP_LT_OS)));
}

// sphere4.
WHITTED_AVX2 Span8 sphere8(const __m256 (&o)[3], const __m256 (&d)[3], int lanes) {
    Span8 s;
    s.part0 = s.part1 = part8(kPartSide);
    const __m256 quarter = _mm256_set1_ps(0.25f);
    const __m256 a = dot3(d[0], d[1], d[2], d[0], d[1], d[2]);
    const __m256 hb = dot3(o[0], o[1], o[2], d[0], d[1], d[2]);
    const __m256 k = _mm256_div_ps(hb, a);
    const __m256 lx = _mm256_sub_ps(o[0], _mm256_mul_ps(k, d[0]));
    const __m256 ly = _mm256_sub_ps(o[1], _mm256_mul_ps(k, d[1]));
    const __m256 lz = _mm256_sub_ps(o[2], _mm256_mul_ps(k, d[2]));
    const __m256 disc = _mm256_mul_ps(a, _mm256_sub_ps(quarter, dot3(lx, ly, lz, lx, ly, lz)));
    const __m256 meets = _mm256_cmp_ps(disc, _mm256_setzero_ps(), _CMP_GE_OS);
    if ((_mm256_movemask_ps(meets) & lanes) == 0) {
        s.ok = s.t0 = s.t1 = _mm256_setzero_ps();  // (t0, t1: defined, though no lane reads them)
        return s;
    }
    const __m256 c = _mm256_sub_ps(dot3(o[0], o[1], o[2], o[0], o[1], o[2]), quarter);
    solve_quadratic8(a, hb, c, disc, s.t0, s.t1);
    s.ok = _mm256_and_ps(meets, finish8(s.t0, s.t1));
    return s;
}

// ellipsoid4.
WHITTED_AVX2 Span8 ellipsoid8(const __m256 (&o)[3], const __m256 (&d)[3], int lanes) {
    const __m256 half = _mm256_set1_ps(0.5f);
    const __m256 so[3] = {_mm256_mul_ps(o[0], half), o[1], _mm256_mul_ps(o[2], half)};
    const __m256 sd[3] = {_mm256_mul_ps(d[0], half), d[1], _mm256_mul_ps(d[2], half)};
    return sphere8(so, sd, lanes);
}

// cube4.
WHITTED_AVX2 Span8 cube8(const __m256 (&o)[3], const __m256 (&d)[3]) {
    Span8 s;
    s.t0 = _mm256_xor_ps(infinity8(), sign_bit8());
    s.t1 = infinity8();
    s.part0 = part8(kPartNegX);
    s.part1 = part8(kPartPosX);
    clip_slab8(o[0], d[0], kPartNegX, kPartPosX, s.t0, s.t1, s.part0, s.part1);
    clip_slab8(o[1], d[1], kPartNegY, kPartPosY, s.t0, s.t1, s.part0, s.part1);
    clip_slab8(o[2], d[2], kPartNegZ, kPartPosZ, s.t0, s.t1, s.part0, s.part1);
    s.ok = finish8(s.t0, s.t1);
    return s;
}

// cylinder4.
WHITTED_AVX2 Span8 cylinder8(const __m256 (&o)[3], const __m256 (&d)[3]) {
    const __m256 quarter = _mm256_set1_ps(0.25f), zero = _mm256_setzero_ps();
    const __m256 a = _mm256_add_ps(_mm256_mul_ps(d[0], d[0]), _mm256_mul_ps(d[2], d[2]));
    const __m256 c = _mm256_sub_ps(_mm256_add_ps(_mm256_mul_ps(o[0], o[0]), _mm256_mul_ps(o[2], o[2])), quarter);
    const __m256 hb = _mm256_add_ps(_mm256_mul_ps(o[0], d[0]), _mm256_mul_ps(o[2], d[2]));
    const __m256 k = _mm256_div_ps(hb, a);
    const __m256 lx = _mm256_sub_ps(o[0], _mm256_mul_ps(k, d[0]));
    const __m256 lz = _mm256_sub_ps(o[2], _mm256_mul_ps(k, d[2]));
    const __m256 disc =
        _mm256_mul_ps(a, _mm256_sub_ps(quarter, _mm256_add_ps(_mm256_mul_ps(lx, lx), _mm256_mul_ps(lz, lz))));
    const __m256 tube = _mm256_cmp_ps(a, zero, _CMP_GT_OS);
    const __m256 meets = select(tube, _mm256_cmp_ps(disc, zero, _CMP_GE_OS), _mm256_cmp_ps(c, zero, _CMP_NGT_US));
    __m256 r0, r1;
    solve_quadratic8(a, hb, c, disc, r0, r1);
    Span8 s;
    s.t0 = select(tube, r0, _mm256_xor_ps(infinity8(), sign_bit8()));
    s.t1 = select(tube, r1, infinity8());
    s.part0 = s.part1 = part8(kPartSide);
    clip_slab8(o[1], d[1], kPartBottomCap, kPartTopCap, s.t0, s.t1, s.part0, s.part1);
    s.ok = _mm256_and_ps(meets, finish8(s.t0, s.t1));
    return s;
}

#undef WHITTED_AVX2

}  // namespace whitted::packet_shapes

#endif
