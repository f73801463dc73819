#pragma once
// The light arriving at a point from one light, before shadowing (scene-format.md §6).
#include <limits>

#include <glm/glm.hpp>

#include "flatten/flat_scene.h"

namespace whitted {

struct LightSample {
    glm::vec3 to_light;  // unit direction from the point toward the light
    float distance;      // to the light; +inf for a directional light
    glm::vec3 intensity; // color · attenuation · spot factor
};

// att = 1 / (c + l·d + q·d²), not clamped; 1 where the denominator is <= 0.
inline float attenuation(const glm::vec3& falloff, float d) {
    float denom = falloff.x + falloff.y * d + falloff.z * d * d;
    return denom > 0.0f ? 1.0f / denom : 1.0f;
}

LightSample sample_light(const Light& light, const glm::vec3& point);

}  // namespace whitted
