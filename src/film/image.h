#pragma once
// An 8-bit RGB image, row 0 at the top: what the renderer produces and every frontend shows.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace whitted {

// Words about an image that go into its file: PNG tEXt chunks, EXR string attributes (the other
// formats have no place for them). Keys as PNG keywords: 1 to 79 printable Latin-1 characters.
using ImageText = std::vector<std::pair<std::string, std::string>>;

struct Image {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // width·height·3 bytes, row-major
    ImageText text;
    // The bytes are sRGB-encoded (a view transform other than linear): a PNG says so (sRGB and
    // gAMA chunks), so colour-managed programs show it as meant. Linear bytes carry no chunk: the
    // lab's images, like the course's, are shown as their bytes are.
    bool srgb = false;

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgb(std::size_t(w) * h * 3, 0) {}
    glm::u8vec3 at(int x, int y) const {
        const std::uint8_t* p = &rgb[(std::size_t(y) * width + x) * 3];
        return {p[0], p[1], p[2]};
    }
};

// A linear floating-point RGB image (radiance as rendered, unclamped), row 0 at the top: what
// .exr and .pfm files keep.
struct LinearImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> rgb;  // width·height pixels, row-major
    ImageText text;
};

// c clamped to [0, 1], NaN mapped to 0: what an 8-bit image can show.
inline float clamp01(float c) { return c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f; }

// ⌊255·clamp(c, 0, 1) + 0.5⌋ (scene-format.md §7): linear, no gamma curve.
inline std::uint8_t to_byte(float c) { return static_cast<std::uint8_t>(255.0f * clamp01(c) + 0.5f); }

}  // namespace whitted
