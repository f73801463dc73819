#include "integrator/light_sample.h"

#include <cmath>

namespace whitted {

LightSample sample_light(const Light& light, const glm::vec3& point) {
    LightSample s;
    if (light.type == LightType::Directional) {
        s.to_light = -light.direction;
        s.distance = std::numeric_limits<float>::infinity();
        s.intensity = light.color;
        return s;
    }
    glm::vec3 d = light.position - point;
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

}  // namespace whitted
