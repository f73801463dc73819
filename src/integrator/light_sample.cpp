#include "integrator/light_sample.h"

#include <cmath>

#include "sampler/warp.h"

namespace whitted {
namespace {

// A point or spot light sitting at `at`.
LightSample from_position(const Light& light, const glm::vec3& at, const glm::vec3& point) {
    LightSample s;
    s.position = at;
    glm::vec3 d = at - point;
    s.distance = glm::length(d);
    s.to_light = s.distance > 0.0f ? d / s.distance : glm::vec3(0, 1, 0);
    float factor = attenuation(light.falloff, s.distance);
    if (light.type == LightType::Spot) {
        // θ is the angle between the spot's axis and the ray from the light to the point.
        float cos_theta = glm::dot(light.direction, -s.to_light);
        if (cos_theta < light.cos_aperture) factor = 0.0f;
        else factor *= std::pow(std::max(cos_theta, 0.0f), light.exponent);  // pow(0, 0) = 1
    }
    s.intensity = light.color * factor;
    return s;
}

LightSample from_direction(const Light& light, const glm::vec3& travel) {
    LightSample s;
    s.position = glm::vec3(0.0f);
    s.to_light = -travel;
    s.distance = std::numeric_limits<float>::infinity();
    s.intensity = light.color;
    return s;
}

}  // namespace

LightSample sample_light(const Light& light, const glm::vec3& point) {
    if (light.type == LightType::Directional) return from_direction(light, light.direction);
    return from_position(light, light.position, point);
}

LightSample sample_light(const Light& light, const glm::vec3& point, glm::vec2 u) {
    if (!has_extent(light)) return sample_light(light, point);
    if (light.type == LightType::Directional)
        return from_direction(light, uniform_cone(light.direction, light.cos_half_angle, u));
    // The disc faces the point: it lies in the plane through the light's centre perpendicular to
    // the line from the point. (A point at the centre itself sees the disc in any orientation.)
    const glm::vec3 axis = point - light.position;
    const float len = glm::length(axis);
    const glm::vec3 w = len > 0.0f ? axis / len : glm::vec3(0, 0, 1);
    glm::vec3 t, b;
    orthonormal_basis(w, t, b);
    const glm::vec2 d = light.radius * concentric_disc(u);
    return from_position(light, light.position + d.x * t + d.y * b, point);
}

}  // namespace whitted
