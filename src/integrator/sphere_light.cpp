#include "integrator/sphere_light.h"

#include <algorithm>
#include <cmath>

#include "accel/instance_geometry.h"
#include "sampler/warp.h"

namespace whitted {
namespace {

// Below this sin² of the cone's half-angle (that of 1.5°), 1 − cos θ is computed from sin² θ:
// 1 − sqrt(1 − s) loses every digit in float when s is tiny.
constexpr float kSmallCone = 0.00068523f;

}  // namespace

std::optional<SphereLight> SphereLight::of(const Instance& inst) {
    const glm::mat4 m = object_to_world(inst);
    const glm::vec3 c[3] = {glm::vec3(m[0]), glm::vec3(m[1]), glm::vec3(m[2])};
    const float l[3] = {glm::length(c[0]), glm::length(c[1]), glm::length(c[2])};
    if (!(l[0] > 0.0f) || !std::isfinite(l[0])) return std::nullopt;
    constexpr float kTolerance = 1e-4f;  // relative: what float matrices of a rotation and a scale keep
    for (int i = 0; i < 3; ++i) {
        if (std::abs(l[i] - l[0]) > kTolerance * l[0]) return std::nullopt;
        if (std::abs(glm::dot(c[i], c[(i + 1) % 3])) > kTolerance * l[0] * l[0]) return std::nullopt;
    }
    return SphereLight(glm::vec3(m[3]), 0.5f * (l[0] + l[1] + l[2]) / 3.0f);
}

bool SphereLight::inside(const glm::vec3& x) const {
    const glm::vec3 d = x - centre_;
    return glm::dot(d, d) <= radius_ * radius_ * (1.0f + 1e-4f);
}

float SphereLight::one_minus_cos_max(const glm::vec3& x) const {
    const glm::vec3 d = x - centre_;
    const float sin2_max = radius_ * radius_ / glm::dot(d, d);
    return sin2_max < kSmallCone ? 0.5f * sin2_max : 1.0f - std::sqrt(std::max(0.0f, 1.0f - sin2_max));
}

SphereLight::Sample SphereLight::sample(const glm::vec3& x, glm::vec2 u) const {
    if (inside(x)) {  // by area: z uniform in [−1, 1], the azimuth uniform (Archimedes)
        const float z = 1.0f - 2.0f * u.x, r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * u.y;
        const glm::vec3 n(r * std::cos(phi), r * std::sin(phi), z);
        return {centre_ + radius_ * n, n, 1.0f / (4.0f * kPi * radius_ * radius_)};
    }
    const glm::vec3 to_centre = centre_ - x;
    const float dc = glm::length(to_centre);
    const float sin_max = radius_ / dc, sin2_max = sin_max * sin_max;
    // The direction's angle θ to the centre, uniform in the cone's solid angle.
    float one_minus_cos = one_minus_cos_max(x) * u.x;
    float sin2 = one_minus_cos * (2.0f - one_minus_cos);
    if (sin2_max < kSmallCone) sin2 = sin2_max * u.x;
    const float cos_theta = std::sqrt(std::max(0.0f, 1.0f - sin2));
    // The angle α at the centre between −to_centre and the point where that direction first meets
    // the sphere (the law of sines, the nearer of the two intersections).
    const float cos_alpha = sin2 / sin_max + cos_theta * std::sqrt(std::max(0.0f, 1.0f - sin2 / sin2_max));
    const glm::vec3 n = around_axis(-to_centre / dc, std::clamp(cos_alpha, -1.0f, 1.0f), u.y);
    Sample s{centre_ + radius_ * n, n, 0.0f};
    s.pdf_area = pdf_area(x, n);
    return s;
}

float SphereLight::pdf_area(const glm::vec3& x, const glm::vec3& n) const {
    if (inside(x)) return 1.0f / (4.0f * kPi * radius_ * radius_);
    const glm::vec3 p = centre_ + radius_ * n;
    const glm::vec3 w = x - p;
    const float d2 = glm::dot(w, w);
    // |cos|: a point drawn on the silhouette may round to just behind it; a BSDF ray from outside
    // meets the near side first, so the far side is never asked for.
    const float cos_light = std::abs(glm::dot(n, w)) / std::sqrt(d2);
    return cos_light / (d2 * 2.0f * kPi * one_minus_cos_max(x));
}

}  // namespace whitted
