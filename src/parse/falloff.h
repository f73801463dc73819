#pragma once
// Light attenuation sanity (scene-format.md §6).
#include <glm/glm.hpp>

namespace whitted {

// True when c + l·d + q·d² <= 0 for some distance d > 0 (`function c l q`), i.e. the light
// deserves a load-time warning: `function 0 0 0`, negative coefficients. `function 0 0.2 0` and
// `function 0 0 0.1` are fine (positive for every d > 0).
bool falloff_can_be_nonpositive(const glm::vec3& clq);

}  // namespace whitted
