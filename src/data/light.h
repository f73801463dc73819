#pragma once
// A light as the integrators read it (scene-format.md §6, §9.1).
#include <glm/glm.hpp>

#include "data/light_type.h"

namespace whitted {

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0, -1, 0};  // unit, the way the light travels
    glm::vec3 color{0.5f};
    glm::vec3 falloff{1, 0, 0};
    float cos_aperture = -1.0f;  // spot: cos of the half-angle
    float exponent = 1.0f;
    float radius = 0.0f;   // point/spot: a disc facing the shaded point (§9.1)
    float cos_half_angle = 1.0f;  // directional: its directions fill this cone (§9.1)
    // CSCI 1230 spot (§9.5): full intensity within the inner half-angle, none beyond the outer one.
    float spot_inner_deg = 0.0f, spot_outer_deg = 0.0f;
};

}  // namespace whitted
