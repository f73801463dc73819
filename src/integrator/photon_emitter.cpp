#include "integrator/photon_emitter.h"

#include <algorithm>
#include <cmath>

#include "sampler/warp.h"

namespace whitted {
namespace {

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

// The cone a spot's photons are drawn from: where its factor is not 0 (cos θ ≥ 0 unless exponent 0).
float spot_cone(const Light& light) {
    const float c = std::max(-1.0f, std::min(1.0f, light.cos_aperture));
    return light.exponent > 0.0f ? std::max(c, 0.0f) : c;
}

}  // namespace

float light_flux_scale(const Light& light, float radius) {
    switch (light.type) {
        case LightType::Point: return kPi * 4.0f * kPi;
        case LightType::Directional: return kPi * kPi * radius * radius;
        case LightType::Spot: {
            // ∫ cos^e θ dω over the cone: 2π (1 − c^(e+1)) / (e + 1) from c = cos of its edge.
            const float c = spot_cone(light), e = light.exponent;
            return kPi * 2.0f * kPi * (1.0f - (e > 0.0f ? std::pow(c, e + 1.0f) : c)) / (e + 1.0f);
        }
    }
    return 0.0f;
}

PhotonEmitter::PhotonEmitter(const SceneData& scene, const Bounds& bounds) : scene_(scene) {
    if (!bounds.empty()) {
        centre_ = bounds.centre();
        radius_ = std::max(1e-6f, 0.5f * glm::length(bounds.extent()));
    }
    double total = 0;
    power_.assign(scene.lights.size(), 0.0f);
    for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const float p = luminance(scene.lights[l].color) * light_flux_scale(scene.lights[l], radius_);
        if (!(p > 0.0f) || !std::isfinite(p)) continue;
        power_[l] = p;
        lights_.push_back(l);
        total += p;
    }
    double run = 0;
    for (std::size_t l : lights_) cdf_.push_back(float((run += power_[l]) / total));
    if (!cdf_.empty()) cdf_.back() = 1.0f;
}

float PhotonEmitter::power(std::size_t light) const { return power_[light]; }

EmittedPhoton PhotonEmitter::emit(float u, glm::vec2 u_point, glm::vec2 u_dir) const {
    EmittedPhoton out;
    if (lights_.empty()) return out;
    const std::size_t k =
        std::min<std::size_t>(std::size_t(std::upper_bound(cdf_.begin(), cdf_.end(), u) - cdf_.begin()), cdf_.size() - 1);
    const float prob = cdf_[k] - (k ? cdf_[k - 1] : 0.0f);
    const Light& light = scene_.lights[lights_[k]];
    glm::vec3 t, b;
    if (light.type == LightType::Directional) {
        // A disc of the bounding sphere facing the light, beyond the sphere on the light's side.
        const glm::vec3 dir = light.cos_half_angle < 1.0f ? uniform_cone(light.direction, light.cos_half_angle, u_dir)
                                                          : light.direction;
        orthonormal_basis(light.direction, t, b);
        const glm::vec2 d = radius_ * concentric_disc(u_point);
        const glm::vec3 on_disc = centre_ + d.x * t + d.y * b;
        // Rays of a tilted direction still start on the disc (§9.1's cone is a few degrees at most).
        out.ray = Ray{on_disc - 2.0f * radius_ * dir, dir};
        out.power = light.color * (light_flux_scale(light, radius_) / prob);
        return out;
    }
    glm::vec3 dir;
    float factor = 1.0f;  // intensity profile / its mean over the sampled directions
    if (light.type == LightType::Spot) {
        const float c = spot_cone(light);
        dir = uniform_cone(light.direction, c, u_dir);
        const float e = light.exponent;
        const float cos_theta = std::max(0.0f, glm::dot(dir, light.direction));
        const float mean = e > 0.0f ? (1.0f - std::pow(c, e + 1.0f)) / ((e + 1.0f) * (1.0f - c)) : 1.0f;
        factor = (e > 0.0f ? std::pow(cos_theta, e) : 1.0f) / mean;
    } else {
        dir = uniform_cone(glm::vec3(0, 0, 1), -1.0f, u_dir);
    }
    glm::vec3 origin = light.position;
    if (light.radius > 0.0f) {
        orthonormal_basis(dir, t, b);
        const glm::vec2 d = light.radius * concentric_disc(u_point);
        origin += d.x * t + d.y * b;
    }
    out.ray = Ray{origin, dir};
    out.power = light.color * (light_flux_scale(light, radius_) * factor / prob);
    out.falloff = light.falloff;
    out.attenuated = true;
    return out;
}

}  // namespace whitted
