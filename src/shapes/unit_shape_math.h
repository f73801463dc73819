#pragma once
// The ray/unit-shape intersection and normal math, templated on the scalar type: the renderer
// uses float (unit_shapes.cpp), tests may also run it in double to tell formula errors from
// float rounding. Header-only so both instances inline; no allocation, no virtual calls.
#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "shapes/unit_shapes.h"

namespace whitted::shape_math {

template <class T>
using Vec3 = glm::vec<3, T, glm::defaultp>;

template <class T>
struct Span {
    int count = 0;
    T t[2] = {0, 0};
    ShapePart part[2] = {kPartSide, kPartSide};
};

template <class T>
inline constexpr T kInf = std::numeric_limits<T>::infinity();

// Clips [tin, tout] to the slab -0.5 <= o + t·d <= 0.5 of one axis. d == ±0 gives inv = ±inf, so
// a parallel ray gets ±inf plane distances (inside: (-inf, inf); outside: an empty interval).
// If the origin lies exactly on a plane, 0·inf = NaN: NaN compares false, so that plane is
// ignored and a ray lying in a face counts as inside (the closed shape).
template <class T>
inline void clip_slab(T o, T d, ShapePart lo_part, ShapePart hi_part, T& tin, T& tout,
                      ShapePart& pin, ShapePart& pout) {
    const T inv = T(1) / d;
    // The far plane is at +0.5 for d >= +0, -0.5 for d <= -0: copysign instead of a select
    // (GCC turns float selects into branches that random rays mispredict).
    const T far_plane = std::copysign(T(0.5), inv);
    const T tn = (-far_plane - o) * inv;
    const T tf = (far_plane - o) * inv;
    const bool neg = std::signbit(inv);
    const int pn = neg ? hi_part : lo_part, pf = neg ? lo_part : hi_part;
    // Comparisons are false for NaN. The parts are blended with masks: a shared float
    // condition would make GCC branch.
    const int take_n = -int(tn > tin), take_f = -int(tf < tout);
    tin = std::max(tin, tn);   // (tin < tn) ? tn : tin keeps tin for NaN
    tout = std::min(tout, tf);
    pin = static_cast<ShapePart>(pin ^ ((pin ^ pn) & take_n));
    pout = static_cast<ShapePart>(pout ^ ((pout ^ pf) & take_f));
}

// Roots of a·t² + 2·hb·t + c with discriminant disc = hb² − a·c >= 0, a != 0, sorted.
// q = −(hb + sign(hb)·√disc) avoids the cancellation of −hb ± √disc.
template <class T>
inline void solve_quadratic(T a, T hb, T c, T disc, T& t0, T& t1) {
    const T q = -(hb + std::copysign(std::sqrt(disc), hb));
    const T r0 = q / a;
    const T r1 = q != T(0) ? c / q : T(0);  // q == 0 only for the double root t = 0
    t0 = std::min(r0, r1);
    t1 = std::max(r0, r1);
}

template <class T>
inline Span<T> finish(T tin, T tout, ShapePart pin, ShapePart pout) {
    Span<T> s;
    // Also rejects a zero direction (infinite interval) and NaN.
    if (tin <= tout && std::isfinite(tin) && std::isfinite(tout)) {
        s.count = 2;
        s.t[0] = tin; s.t[1] = tout;
        s.part[0] = pin; s.part[1] = pout;
    }
    return s;
}

template <class T>
inline Span<T> intersect_cube(const Vec3<T>& o, const Vec3<T>& d) {
    T tin = -kInf<T>, tout = kInf<T>;
    ShapePart pin = kPartNegX, pout = kPartPosX;
    clip_slab(o.x, d.x, kPartNegX, kPartPosX, tin, tout, pin, pout);
    clip_slab(o.y, d.y, kPartNegY, kPartPosY, tin, tout, pin, pout);
    clip_slab(o.z, d.z, kPartNegZ, kPartPosZ, tin, tout, pin, pout);
    return finish(tin, tout, pin, pout);
}

template <class T>
inline Span<T> intersect_sphere(const Vec3<T>& o, const Vec3<T>& d) {
    const T a = glm::dot(d, d);
    const T hb = glm::dot(o, d);
    // disc = hb² − a·c computed as a·(r² − |l|²), l = the line's closest point to the centre:
    // no cancellation between two large terms for grazing rays (Ray Tracing Gems, ch. 7).
    const Vec3<T> l = o - (hb / a) * d;
    const T disc = a * (T(0.25) - glm::dot(l, l));
    if (!(disc >= T(0))) return {};  // also a == 0 (NaN)
    const T c = glm::dot(o, o) - T(0.25);
    T t0, t1;
    solve_quadratic(a, hb, c, disc, t0, t1);
    return finish(t0, t1, kPartSide, kPartSide);
}

// Ellipsoid x² + 4y² + z² = 1: the map (x, y, z) → (x/2, y, z/2) takes it onto the sphere of
// radius 0.5 and keeps the ray parameter t, so the sphere's exact solution applies. Halving is
// exact in binary floating point, which keeps the packet version (sphere4 on halved lanes)
// bit-identical.
template <class T>
inline Vec3<T> ellipsoid_to_sphere(const Vec3<T>& v) {
    return {v.x * T(0.5), v.y, v.z * T(0.5)};
}

template <class T>
inline Span<T> intersect_ellipsoid(const Vec3<T>& o, const Vec3<T>& d) {
    return intersect_sphere(ellipsoid_to_sphere(o), ellipsoid_to_sphere(d));
}

template <class T>
inline Span<T> intersect_cylinder(const Vec3<T>& o, const Vec3<T>& d) {
    T tin = -kInf<T>, tout = kInf<T>;
    const T a = d.x * d.x + d.z * d.z;
    const T c = o.x * o.x + o.z * o.z - T(0.25);
    if (a > T(0)) {
        const T hb = o.x * d.x + o.z * d.z;
        const T s = hb / a;  // closest approach to the axis, as for the sphere
        const T lx = o.x - s * d.x, lz = o.z - s * d.z;
        const T disc = a * (T(0.25) - (lx * lx + lz * lz));
        if (!(disc >= T(0))) return {};
        solve_quadratic(a, hb, c, disc, tin, tout);
    } else if (c > T(0)) {
        return {};  // parallel to the axis, outside the tube
    }
    ShapePart pin = kPartSide, pout = kPartSide;
    clip_slab(o.y, d.y, kPartBottomCap, kPartTopCap, tin, tout, pin, pout);
    return finish(tin, tout, pin, pout);
}

// Cone: 4(x² + z²) = k², k = 0.5 − y, i.e. the double cone with apex (0, 0.5, 0). The y-slab
// [-0.5, 0.5] (k in [0, 1]) keeps the lower nappe only and adds the base cap; its top plane
// touches the solid only at the apex, so it is reported as the side.
template <class T>
inline Span<T> intersect_cone(const Vec3<T>& o_in, const Vec3<T>& d) {
    // From a far origin the quadratic's terms are huge and cancel (a ray from 1000 units away
    // "hits" well off the surface in float). Then the line is restarted from its point nearest
    // the centre, and that start's parameter is added back to the result.
    Vec3<T> o = o_in;
    T shift = T(0);
    if (glm::dot(o, o) > T(16)) {
        const T dd = glm::dot(d, d);
        if (dd > T(0)) {
            shift = -glm::dot(o, d) / dd;
            o = o + shift * d;
        }
    }
    const T ko = T(0.5) - o.y, kd = -d.y;
    const T a = T(4) * (d.x * d.x + d.z * d.z) - kd * kd;
    const T hb = T(4) * (o.x * d.x + o.z * d.z) - ko * kd;
    const T c = T(4) * (o.x * o.x + o.z * o.z) - ko * ko;
    T tin, tout;  // the part of the line inside the double cone that lies in the lower nappe
    if (a != T(0)) {
        T disc = hb * hb - a * c;
        if (disc < T(0)) {
            if (a > T(0)) return {};  // shallower than the cone's generators: missed
            disc = T(0);  // steep and "missing" both nappes: only through the apex, by rounding
        }
        T r0, r1;
        solve_quadratic(a, hb, c, disc, r0, r1);
        if (a > T(0)) {
            tin = r0; tout = r1;  // one nappe; the slab removes it if it is the upper one
        } else if (kd > T(0)) {   // steep, going down: k grows, the lower nappe is at t >= r1
            tin = r1; tout = kInf<T>;
        } else {
            tin = -kInf<T>; tout = r0;
        }
    } else if (hb != T(0)) {  // parallel to a generator: f(t) = 2·hb·t + c <= 0 is a half-line
        const T tr = -c / (T(2) * hb);
        tin = hb < T(0) ? tr : -kInf<T>;
        tout = hb < T(0) ? kInf<T> : tr;
    } else {
        if (c > T(0)) return {};
        tin = -kInf<T>; tout = kInf<T>;
    }
    ShapePart pin = kPartSide, pout = kPartSide;
    clip_slab(o.y, d.y, kPartBottomCap, kPartSide, tin, tout, pin, pout);
    return finish(tin + shift, tout + shift, pin, pout);
}

template <class T>
inline Span<T> intersect(ShapeKind kind, const Vec3<T>& o, const Vec3<T>& d) {
    switch (kind) {
        case ShapeKind::Cube: return intersect_cube(o, d);
        case ShapeKind::Sphere: return intersect_sphere(o, d);
        case ShapeKind::Cylinder: return intersect_cylinder(o, d);
        case ShapeKind::Cone: return intersect_cone(o, d);
        case ShapeKind::Ellipsoid: return intersect_ellipsoid(o, d);
        case ShapeKind::Mesh: break;  // not a unit shape: accel/ traverses its triangles
    }
    return {};
}

// intersect() with the direction first scaled by a power of two to a largest component in
// [0.5, 1), the distances found scaled back. Every intermediate of the shapes' arithmetic then
// scales by the same power of two, so the distances are bit for bit those of intersect() wherever
// its arithmetic stayed in float's normal range; beyond (an object scaled by 1e23: a unit ray's
// object-space direction 1e-23, its square 0) they are still found.
template <class T>
inline Span<T> intersect_rescaled(ShapeKind kind, const Vec3<T>& o, const Vec3<T>& d) {
    const T m = std::max(std::max(std::abs(d.x), std::abs(d.y)), std::abs(d.z));
    if (!(m > T(0)) || !std::isfinite(m)) return intersect(kind, o, d);
    int e = 0;
    std::frexp(m, &e);
    Span<T> s = intersect(kind, o, d * std::ldexp(T(1), -e));
    for (int i = 0; i < s.count; ++i) s.t[i] = std::ldexp(s.t[i], -e);
    return s;
}

template <class T>
inline Vec3<T> normal(ShapeKind kind, ShapePart part, const Vec3<T>& p) {
    switch (part) {
        case kPartTopCap: case kPartPosY: return {0, 1, 0};
        case kPartBottomCap: case kPartNegY: return {0, -1, 0};
        case kPartPosX: return {1, 0, 0};
        case kPartNegX: return {-1, 0, 0};
        case kPartPosZ: return {0, 0, 1};
        case kPartNegZ: return {0, 0, -1};
        case kPartSide: break;
    }
    if (kind == ShapeKind::Sphere) return glm::normalize(p);  // = p / 0.5 on the surface
    // The gradient of x² + 4y² + z² is 2·(x, 4y, z).
    if (kind == ShapeKind::Ellipsoid) return glm::normalize(Vec3<T>(p.x, T(4) * p.y, p.z));
    const T r = std::sqrt(p.x * p.x + p.z * p.z);
    // Radial forms stay exact for points slightly off the surface.
    if (kind == ShapeKind::Cylinder) {
        return r > T(0) ? Vec3<T>(p.x / r, 0, p.z / r) : Vec3<T>(1, 0, 0);
    }
    // Cone: the gradient of 4(x²+z²) − (0.5−y)² is ∝ (4x, 0.5−y, 4z); on the surface
    // 0.5 − y = 2r, so it is ∝ (2x/r, 1, 2z/r), of length √5. The apex gets +Y.
    if (!(r > T(0))) return {0, 1, 0};
    const T inv5 = T(1) / std::sqrt(T(5));
    return {T(2) * inv5 * p.x / r, inv5, T(2) * inv5 * p.z / r};
}

}  // namespace whitted::shape_math
