#pragma once
// A decoded texture, as the decoders produce it and the shading reads it.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace whitted {

// A texture image as 8-bit RGB, row 0 at the top: 3 bytes a texel (what the decoder gives; floats
// would take four times the memory for no more precision). A texel's value is byte / 255, linear.
struct TextureImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // width·height·3 bytes, row-major
    glm::vec3 texel(std::size_t i) const { return glm::vec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]) / 255.0f; }
    void push_back(glm::u8vec3 c) { rgb.insert(rgb.end(), {c.x, c.y, c.z}); }
};

}  // namespace whitted
