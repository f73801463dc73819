#pragma once
#include <glm/glm.hpp>

#include "data/texture_image.h"

namespace whitted {

// The texel at (u, v) ∈ [0,1)² repeated (repeat_u × repeat_v) times (scene-format.md §8):
// s = frac(u·U), t = frac(v·V), bilinear between the four nearest texel centres, wrapping
// around the edges; row 0 is the top of the image.
glm::vec3 sample_texture(const TextureImage& image, glm::vec2 uv, float repeat_u, float repeat_v);

}  // namespace whitted
