#pragma once
// Maps from the unit square [0, 1)² to the shapes the effects sample: discs (lens, disc lights),
// cones of directions (a directional light's angular size) and cos^e lobes (gloss). Each keeps
// the square's stratification (the concentric map is continuous and area-preserving), so
// well-spread samples stay well spread. The square's centre (0.5, 0.5) maps to the disc's centre.
#include <algorithm>
#include <cmath>

#include <glm/glm.hpp>

#include "base/math.h"

namespace whitted {

// Uniform over the unit disc (Shirley and Chiu 1997, concentric mapping).
inline glm::vec2 concentric_disc(glm::vec2 u) {
    const glm::vec2 o = 2.0f * u - 1.0f;
    if (o.x == 0.0f && o.y == 0.0f) return {0.0f, 0.0f};
    float r, theta;
    if (std::abs(o.x) > std::abs(o.y)) {
        r = o.x;
        theta = (kPi / 4.0f) * (o.y / o.x);
    } else {
        r = o.y;
        theta = kPi / 2.0f - (kPi / 4.0f) * (o.x / o.y);
    }
    return r * glm::vec2(std::cos(theta), std::sin(theta));
}

// Two unit vectors that make (t, b, n) orthonormal, for unit n (Duff et al. 2017, branchless).
inline void orthonormal_basis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float c = n.x * n.y * a;
    t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = glm::vec3(c, sign + n.y * n.y * a, -n.y);
}

// The direction at polar angle acos(cos_theta) and azimuth 2π·v around unit `axis`.
inline glm::vec3 around_axis(const glm::vec3& axis, float cos_theta, float v) {
    glm::vec3 t, b;
    orthonormal_basis(axis, t, b);
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * kPi * v;
    return sin_theta * std::cos(phi) * t + sin_theta * std::sin(phi) * b + cos_theta * axis;
}

// Uniform over the solid angle of the cone of half-angle acos(cos_max) around unit `axis`.
inline glm::vec3 uniform_cone(const glm::vec3& axis, float cos_max, glm::vec2 u) {
    return around_axis(axis, 1.0f - u.x * (1.0f - cos_max), u.y);
}

// Distributed as cos^e(α) around unit `axis` (α the angle to it), over the hemisphere about it:
// pdf = (e + 1)/(2π) · cos^e α, so cos α = u^(1/(e+1)).
inline glm::vec3 cosine_power_lobe(const glm::vec3& axis, float e, glm::vec2 u) {
    return around_axis(axis, std::pow(1.0f - u.x, 1.0f / (e + 1.0f)), u.y);
}

// Cosine-weighted over the hemisphere about unit n (pdf cos θ / π): the disc lifted (Malley's method).
inline glm::vec3 cosine_hemisphere(const glm::vec3& n, glm::vec2 u) {
    const glm::vec2 d = concentric_disc(u);
    glm::vec3 t, b;
    orthonormal_basis(n, t, b);
    return d.x * t + d.y * b + std::sqrt(std::max(0.0f, 1.0f - glm::dot(d, d))) * n;
}

}  // namespace whitted
