#pragma once
// False colours for error maps: magma (black through purple and orange to pale yellow), the map
// FLIP's own tool draws its error images with, so that whitted's look like the paper's.
#include <vector>

#include <glm/glm.hpp>

#include "film/image.h"

namespace whitted {

// The magma colour of t in [0, 1] (clamped; NaN is 0) as 8-bit sRGB: entry round(255·t) of the
// 256-entry map.
glm::u8vec3 magma(float t);

// A width × height image of `values` (row-major, each in [0, 1]) in magma colours.
Image magma_image(const std::vector<float>& values, int width, int height);

}  // namespace whitted
