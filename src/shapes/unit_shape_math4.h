#pragma once
// The unit shapes' ray intersection four rays at a time (SSE lanes), for the packet traversal's
// leaves: shape_math (shapes/unit_shape_math.h) rewritten with branches turned into lane masks,
// operation for operation, so that every lane gets the bits the scalar code gives (the same
// IEEE operations in the same order round the same way). Mapping used throughout:
//   std::min(a, b) = (b < a) ? b : a = _mm_min_ps(b, a);  std::max(a, b) = _mm_max_ps(b, a);
//   glm::dot(a, b) = (a.x·b.x + a.y·b.y) + a.z·b.z.
// Built without FMA (no -march): a contracted multiply-add would round differently from the
// scalar code. The packet tests compare every lane with the single-ray query.
// The cone (a far-origin restart and several cases) stays scalar.
#include <emmintrin.h>

#include <limits>

#include "data/instance.h"
#include "shapes/unit_shapes.h"

namespace whitted::packet_shapes {

// Four lanes' intervals: `ok` = all-ones where the line meets the shape (shape_math's count = 2),
// entering at t0 through part0 and leaving at t1 through part1 (parts as 32-bit lanes).
struct Span4 {
    __m128 ok, t0, t1;
    __m128i part0, part1;
};

inline __m128 select(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }
inline __m128i select(__m128 mask, __m128i a, __m128i b) {
    const __m128i m = _mm_castps_si128(mask);
    return _mm_or_si128(_mm_and_si128(m, a), _mm_andnot_si128(m, b));
}
inline __m128 sign_bit() { return _mm_set1_ps(-0.0f); }
inline __m128 infinity() { return _mm_set1_ps(std::numeric_limits<float>::infinity()); }
inline __m128i part(ShapePart p) { return _mm_set1_epi32(int(p)); }

inline __m128 dot3(__m128 ax, __m128 ay, __m128 az, __m128 bx, __m128 by, __m128 bz) {
    return _mm_add_ps(_mm_add_ps(_mm_mul_ps(ax, bx), _mm_mul_ps(ay, by)), _mm_mul_ps(az, bz));
}

// to_object_space (accel/instance_geometry.h) of four world rays (o, d: x, y, z rows).
inline void to_object_space4(const Instance& inst, const __m128 (&o)[3], const __m128 (&d)[3], __m128 (&oo)[3],
                             __m128 (&od)[3]) {
    const glm::vec4* w = inst.world_to_object;
    for (int k = 0; k < 3; ++k) {
        const __m128 wx = _mm_set1_ps(w[k].x), wy = _mm_set1_ps(w[k].y), wz = _mm_set1_ps(w[k].z);
        oo[k] = _mm_add_ps(dot3(wx, wy, wz, o[0], o[1], o[2]), _mm_set1_ps(w[k].w));
        od[k] = dot3(wx, wy, wz, d[0], d[1], d[2]);
    }
}

// shape_math::solve_quadratic.
inline void solve_quadratic4(__m128 a, __m128 hb, __m128 c, __m128 disc, __m128& t0, __m128& t1) {
    const __m128 sign = sign_bit();
    const __m128 root = _mm_sqrt_ps(disc);
    const __m128 q = _mm_xor_ps(_mm_add_ps(hb, _mm_or_ps(_mm_andnot_ps(sign, root), _mm_and_ps(sign, hb))), sign);
    const __m128 r0 = _mm_div_ps(q, a);
    const __m128 r1 = _mm_and_ps(_mm_cmpneq_ps(q, _mm_setzero_ps()), _mm_div_ps(c, q));  // q == 0: +0
    t0 = _mm_min_ps(r1, r0);
    t1 = _mm_max_ps(r1, r0);
}

// shape_math::clip_slab.
inline void clip_slab4(__m128 o, __m128 d, ShapePart lo_part, ShapePart hi_part, __m128& tin, __m128& tout,
                       __m128i& pin, __m128i& pout) {
    const __m128 sign = sign_bit();
    const __m128 inv = _mm_div_ps(_mm_set1_ps(1.0f), d);
    const __m128 far_plane = _mm_or_ps(_mm_and_ps(sign, inv), _mm_set1_ps(0.5f));  // copysign(0.5, inv)
    const __m128 tn = _mm_mul_ps(_mm_sub_ps(_mm_xor_ps(far_plane, sign), o), inv);
    const __m128 tf = _mm_mul_ps(_mm_sub_ps(far_plane, o), inv);
    const __m128 neg = _mm_castsi128_ps(_mm_srai_epi32(_mm_castps_si128(inv), 31));  // signbit(inv)
    const __m128i pn = select(neg, part(hi_part), part(lo_part)), pf = select(neg, part(lo_part), part(hi_part));
    const __m128 take_n = _mm_cmpgt_ps(tn, tin), take_f = _mm_cmplt_ps(tf, tout);
    tin = _mm_max_ps(tn, tin);
    tout = _mm_min_ps(tf, tout);
    pin = select(take_n, pn, pin);
    pout = select(take_f, pf, pout);
}

// shape_math::finish: an interval if tin <= tout and both are finite.
inline __m128 finish4(__m128 tin, __m128 tout) {
    const __m128 sign = sign_bit(), inf = infinity();
    return _mm_and_ps(_mm_cmple_ps(tin, tout), _mm_and_ps(_mm_cmplt_ps(_mm_andnot_ps(sign, tin), inf),
                                                          _mm_cmplt_ps(_mm_andnot_ps(sign, tout), inf)));
}

// shape_math::intersect_sphere. Returns early (ok = 0) when no lane in `lanes` meets it.
inline Span4 sphere4(const __m128 (&o)[3], const __m128 (&d)[3], int lanes) {
    Span4 s;
    s.part0 = s.part1 = part(kPartSide);
    const __m128 quarter = _mm_set1_ps(0.25f);
    const __m128 a = dot3(d[0], d[1], d[2], d[0], d[1], d[2]);
    const __m128 hb = dot3(o[0], o[1], o[2], d[0], d[1], d[2]);
    const __m128 k = _mm_div_ps(hb, a);
    const __m128 lx = _mm_sub_ps(o[0], _mm_mul_ps(k, d[0]));
    const __m128 ly = _mm_sub_ps(o[1], _mm_mul_ps(k, d[1]));
    const __m128 lz = _mm_sub_ps(o[2], _mm_mul_ps(k, d[2]));
    const __m128 disc = _mm_mul_ps(a, _mm_sub_ps(quarter, dot3(lx, ly, lz, lx, ly, lz)));
    const __m128 meets = _mm_cmpge_ps(disc, _mm_setzero_ps());  // false for NaN, as !(disc >= 0)
    if ((_mm_movemask_ps(meets) & lanes) == 0) {
        s.ok = s.t0 = s.t1 = _mm_setzero_ps();  // (t0, t1: defined, though no lane reads them)
        return s;
    }
    const __m128 c = _mm_sub_ps(dot3(o[0], o[1], o[2], o[0], o[1], o[2]), quarter);
    solve_quadratic4(a, hb, c, disc, s.t0, s.t1);
    s.ok = _mm_and_ps(meets, finish4(s.t0, s.t1));
    return s;
}

// shape_math::intersect_ellipsoid: the sphere on the halved x and z lanes (halving is exact).
inline Span4 ellipsoid4(const __m128 (&o)[3], const __m128 (&d)[3], int lanes) {
    const __m128 half = _mm_set1_ps(0.5f);
    const __m128 so[3] = {_mm_mul_ps(o[0], half), o[1], _mm_mul_ps(o[2], half)};
    const __m128 sd[3] = {_mm_mul_ps(d[0], half), d[1], _mm_mul_ps(d[2], half)};
    return sphere4(so, sd, lanes);
}

// shape_math::intersect_cube.
inline Span4 cube4(const __m128 (&o)[3], const __m128 (&d)[3]) {
    Span4 s;
    s.t0 = _mm_xor_ps(infinity(), sign_bit());
    s.t1 = infinity();
    s.part0 = part(kPartNegX);
    s.part1 = part(kPartPosX);
    clip_slab4(o[0], d[0], kPartNegX, kPartPosX, s.t0, s.t1, s.part0, s.part1);
    clip_slab4(o[1], d[1], kPartNegY, kPartPosY, s.t0, s.t1, s.part0, s.part1);
    clip_slab4(o[2], d[2], kPartNegZ, kPartPosZ, s.t0, s.t1, s.part0, s.part1);
    s.ok = finish4(s.t0, s.t1);
    return s;
}

// shape_math::intersect_cylinder: the tube's quadratic where a > 0, else the whole line if it
// runs inside the tube, then the y slab.
inline Span4 cylinder4(const __m128 (&o)[3], const __m128 (&d)[3]) {
    const __m128 quarter = _mm_set1_ps(0.25f), zero = _mm_setzero_ps();
    const __m128 a = _mm_add_ps(_mm_mul_ps(d[0], d[0]), _mm_mul_ps(d[2], d[2]));
    const __m128 c = _mm_sub_ps(_mm_add_ps(_mm_mul_ps(o[0], o[0]), _mm_mul_ps(o[2], o[2])), quarter);
    const __m128 hb = _mm_add_ps(_mm_mul_ps(o[0], d[0]), _mm_mul_ps(o[2], d[2]));
    const __m128 k = _mm_div_ps(hb, a);
    const __m128 lx = _mm_sub_ps(o[0], _mm_mul_ps(k, d[0]));
    const __m128 lz = _mm_sub_ps(o[2], _mm_mul_ps(k, d[2]));
    const __m128 disc = _mm_mul_ps(a, _mm_sub_ps(quarter, _mm_add_ps(_mm_mul_ps(lx, lx), _mm_mul_ps(lz, lz))));
    const __m128 tube = _mm_cmpgt_ps(a, zero);
    // Missed: the quadratic has no root (tube), or the line runs outside the tube (not tube).
    const __m128 meets = select(tube, _mm_cmpge_ps(disc, zero), _mm_cmpngt_ps(c, zero));
    __m128 r0, r1;
    solve_quadratic4(a, hb, c, disc, r0, r1);
    Span4 s;
    s.t0 = select(tube, r0, _mm_xor_ps(infinity(), sign_bit()));
    s.t1 = select(tube, r1, infinity());
    s.part0 = s.part1 = part(kPartSide);
    clip_slab4(o[1], d[1], kPartBottomCap, kPartTopCap, s.t0, s.t1, s.part0, s.part1);
    s.ok = _mm_and_ps(meets, finish4(s.t0, s.t1));
    return s;
}

}  // namespace whitted::packet_shapes
