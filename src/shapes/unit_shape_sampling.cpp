#include "shapes/unit_shape_sampling.h"

#include <algorithm>
#include <cmath>

#include "sampler/warp.h"

namespace whitted {
namespace {

const float kConeSide = kPi * 0.5f * std::sqrt(1.25f);  // π·r·slant, r = 0.5, height 1
const float kDisc = kPi * 0.25f;                         // a cap of radius 0.5

// Picks part k of n with the given shares of the area; rescales x to [0, 1) within it.
int pick(float& x, const float* shares, int n) {
    float below = 0.0f;
    for (int k = 0; k < n - 1; ++k) {
        if (x < below + shares[k]) {
            x = std::min((x - below) / shares[k], 0x1.fffffep-1f);
            return k;
        }
        below += shares[k];
    }
    x = std::clamp((x - below) / shares[n - 1], 0.0f, 0x1.fffffep-1f);
    return n - 1;
}

glm::vec3 disc_at(float y, glm::vec2 u) {
    const glm::vec2 d = 0.5f * concentric_disc(u);
    return {d.x, y, d.y};
}

}  // namespace

float unit_shape_area(ShapeKind kind) {
    switch (kind) {
        case ShapeKind::Cube: return 6.0f;
        case ShapeKind::Sphere: return kPi;
        case ShapeKind::Cylinder: return kPi + 2.0f * kDisc;
        case ShapeKind::Cone: return kConeSide + kDisc;
        case ShapeKind::Ellipsoid: return 4.0f * kPi;  // the unit sphere it is mapped from
        default: return 0.0f;
    }
}

ShapeSample sample_unit_shape(ShapeKind kind, glm::vec2 u) {
    switch (kind) {
        case ShapeKind::Cube: {
            const float sixth[6] = {1 / 6.0f, 1 / 6.0f, 1 / 6.0f, 1 / 6.0f, 1 / 6.0f, 1 / 6.0f};
            const int face = pick(u.x, sixth, 6);
            const float a = u.x - 0.5f, b = u.y - 0.5f;
            switch (face) {
                case 0: return {{0.5f, a, b}, kPartPosX};
                case 1: return {{-0.5f, a, b}, kPartNegX};
                case 2: return {{a, 0.5f, b}, kPartPosY};
                case 3: return {{a, -0.5f, b}, kPartNegY};
                case 4: return {{a, b, 0.5f}, kPartPosZ};
                default: return {{a, b, -0.5f}, kPartNegZ};
            }
        }
        case ShapeKind::Sphere: {
            const float y = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - y * y)), phi = 2.0f * kPi * u.y;
            return {0.5f * glm::vec3(r * std::cos(phi), y, r * std::sin(phi)), kPartSide};
        }
        case ShapeKind::Cylinder: {
            const float total = unit_shape_area(kind), shares[3] = {kPi / total, kDisc / total, kDisc / total};
            const int part = pick(u.x, shares, 3);
            if (part == 1) return {disc_at(0.5f, u), kPartTopCap};
            if (part == 2) return {disc_at(-0.5f, u), kPartBottomCap};
            const float phi = 2.0f * kPi * u.y;
            return {{0.5f * std::cos(phi), u.x - 0.5f, 0.5f * std::sin(phi)}, kPartSide};
        }
        case ShapeKind::Cone: {
            const float total = unit_shape_area(kind), shares[2] = {kConeSide / total, kDisc / total};
            if (pick(u.x, shares, 2) == 1) return {disc_at(-0.5f, u), kPartBottomCap};
            // The side's area grows linearly with the distance t from the apex: t = √x.
            const float t = std::sqrt(u.x), phi = 2.0f * kPi * u.y;
            return {{0.5f * t * std::cos(phi), 0.5f - t, 0.5f * t * std::sin(phi)}, kPartSide};
        }
        case ShapeKind::Ellipsoid: {
            const float y = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - y * y)), phi = 2.0f * kPi * u.y;
            return {{r * std::cos(phi), 0.5f * y, r * std::sin(phi)}, kPartSide};
        }
        default: return {glm::vec3(0.0f), kPartSide};
    }
}

glm::vec3 unit_shape_area_normal(ShapeKind kind, const glm::vec3& n) {
    if (kind != ShapeKind::Ellipsoid) return n;
    // n ∝ (p.x, 4p.y, p.z) = (q.x, 2q.y, q.z), so q ∝ (n.x, n.y/2, n.z), on the unit sphere.
    const glm::vec3 q = glm::normalize(glm::vec3(n.x, 0.5f * n.y, n.z));
    return 0.5f * glm::vec3(q.x, 2.0f * q.y, q.z);
}

}  // namespace whitted
