#pragma once
// The light arriving at a point from one light, before shadowing (scene-format.md §6), from one
// point of it when it has a size (§9.1: a disc of `radius` facing the point, a cone of directions
// `angle` wide).
#include <limits>

#include <glm/glm.hpp>

#include "data/scene_data.h"

namespace whitted {

struct LightSample {
    glm::vec3 to_light;  // unit direction from the point toward the light
    float distance;      // to the light; +inf for a directional light
    glm::vec3 intensity; // color · attenuation · spot factor
    glm::vec3 position;  // the point of the light the sample comes from (point and spot lights)
};

// att = 1 / (c + l·d + q·d²), not clamped; 1 where the denominator is <= 0.
inline float attenuation(const glm::vec3& falloff, float d) {
    float denom = falloff.x + falloff.y * d + falloff.z * d * d;
    return denom > 0.0f ? 1.0f / denom : 1.0f;
}

// Whether the light has a size to sample (a disc, or a cone of directions).
inline bool has_extent(const Light& light) {
    return light.type == LightType::Directional ? light.cos_half_angle < 1.0f : light.radius > 0.0f;
}

// From the light's centre (its position, or its direction).
LightSample sample_light(const Light& light, const glm::vec3& point);

// From the point of the light that u (in [0, 1)²) picks: uniform over the disc facing `point`, or
// over the cone of directions; the centre for a light without extent.
LightSample sample_light(const Light& light, const glm::vec3& point, glm::vec2 u);

}  // namespace whitted
