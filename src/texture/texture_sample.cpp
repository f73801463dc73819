#include "texture/texture_sample.h"

#include <cmath>

namespace whitted {

glm::vec3 sample_texture(const TextureImage& image, glm::vec2 uv, float repeat_u, float repeat_v) {
    if (image.width <= 0 || image.height <= 0) return glm::vec3(1.0f);
    const float s = uv.x * repeat_u - std::floor(uv.x * repeat_u);
    const float t = uv.y * repeat_v - std::floor(uv.y * repeat_v);
    // Texel centres sit at half-integers: column c covers [c, c+1) and its centre is c + 0.5.
    const float x = s * float(image.width) - 0.5f;
    const float y = t * float(image.height) - 0.5f;
    if (!std::isfinite(x) || !std::isfinite(y)) return image.texel(0);  // never index with NaN
    const float fx = std::floor(x), fy = std::floor(y);
    const float ax = x - fx, ay = y - fy;
    auto wrap = [](long i, int n) { return static_cast<int>(((i % n) + n) % n); };
    const int x0 = wrap(long(fx), image.width), x1 = wrap(long(fx) + 1, image.width);
    const int y0 = wrap(long(fy), image.height), y1 = wrap(long(fy) + 1, image.height);
    auto at = [&](int col, int row) { return image.texel(std::size_t(row) * image.width + col); };
    return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x1, y0)) + ay * ((1 - ax) * at(x0, y1) + ax * at(x1, y1));
}

}  // namespace whitted
