#pragma once
// Watertight ray–triangle intersection (Woop, Benthin and Wald, "Watertight Ray/Triangle
// Intersection", JCGT 2013). The triangle is moved into a frame where the ray runs along +z from
// the origin (a translation and a shear, no rotation), so the hit test becomes three 2D edge
// functions of the projected corners. A shared edge is computed from the same two corners by the
// same operations in both of its triangles, so its edge function has the same value with opposite
// sign: no ray passes between two triangles that share the edge. Edge functions that come out
// exactly zero are recomputed in double, so the sign of a near-zero one is right too.
#include <cmath>
#include <cstdint>
#include <utility>

#include <glm/glm.hpp>

#include "base/ray.h"

namespace whitted {

// The per-ray part: the axis the ray runs most along (kz), the two others, the shear, and the
// origin's coordinates along kx, ky, kz.
struct WatertightRay {
    int kx, ky, kz;
    float sx, sy, sz;
    float ox, oy, oz;

    WatertightRay() = default;
    explicit WatertightRay(const Ray& r) {
        const glm::vec3 a = glm::abs(r.direction);
        kz = a.x > a.y ? (a.x > a.z ? 0 : 2) : (a.y > a.z ? 1 : 2);
        kx = kz == 2 ? 0 : kz + 1;
        ky = kx == 2 ? 0 : kx + 1;
        if (r.direction[kz] < 0.0f) std::swap(kx, ky);  // keep the winding of the projected triangle
        sx = r.direction[kx] / r.direction[kz];
        sy = r.direction[ky] / r.direction[kz];
        sz = 1.0f / r.direction[kz];
        ox = r.origin[kx];
        oy = r.origin[ky];
        oz = r.origin[kz];
    }
};

struct TriangleHit {
    float t;
    float u, v;  // barycentric weights of the second and third corners
};

// Whether the ray meets triangle (p0, p1, p2), from either side, at t in (t_min, t_max).
inline bool intersect_triangle(const WatertightRay& r, const glm::vec3& p0, const glm::vec3& p1,
                               const glm::vec3& p2, float t_min, float t_max, TriangleHit& hit) {
    // Only the coordinates used, read straight from the corners by axis (the same values as
    // subtracting whole vectors and picking components, without building them: the corners of a
    // glm::vec3 are three adjacent floats).
    const float* q0 = &p0.x;
    const float* q1 = &p1.x;
    const float* q2 = &p2.x;
    const float a_z = q0[r.kz] - r.oz, b_z = q1[r.kz] - r.oz, c_z = q2[r.kz] - r.oz;
    const float ax = (q0[r.kx] - r.ox) - r.sx * a_z, ay = (q0[r.ky] - r.oy) - r.sy * a_z;
    const float bx = (q1[r.kx] - r.ox) - r.sx * b_z, by = (q1[r.ky] - r.oy) - r.sy * b_z;
    const float cx = (q2[r.kx] - r.ox) - r.sx * c_z, cy = (q2[r.ky] - r.oy) - r.sy * c_z;
    // Edge functions: e0 of edge p1p2 (the weight of p0), e1 of p2p0, e2 of p0p1.
    float e0 = cx * by - cy * bx;
    float e1 = ax * cy - ay * cx;
    float e2 = bx * ay - by * ax;
    if (e0 == 0.0f || e1 == 0.0f || e2 == 0.0f) {
        e0 = float(double(cx) * double(by) - double(cy) * double(bx));
        e1 = float(double(ax) * double(cy) - double(ay) * double(cx));
        e2 = float(double(bx) * double(ay) - double(by) * double(ax));
    }
    if ((e0 < 0.0f || e1 < 0.0f || e2 < 0.0f) && (e0 > 0.0f || e1 > 0.0f || e2 > 0.0f)) return false;
    const float det = e0 + e1 + e2;
    if (det == 0.0f) return false;  // seen edge-on (or degenerate)
    const float az = r.sz * a_z, bz = r.sz * b_z, cz = r.sz * c_z;
    const float inv_det = 1.0f / det;
    const float t = (e0 * az + e1 * bz + e2 * cz) * inv_det;
    if (!(t > t_min && t < t_max)) return false;
    hit.t = t;
    hit.u = e1 * inv_det;
    hit.v = e2 * inv_det;
    return true;
}

}  // namespace whitted
