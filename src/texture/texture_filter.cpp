#include "texture/texture_filter.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "texture/texture_sample.h"

namespace whitted {
namespace {

int wrap(long i, int n) { return static_cast<int>(((i % n) + n) % n); }

glm::vec3 texel_at(const TextureImage& image, long col, long row) {
    return image.texel(std::size_t(wrap(row, image.height)) * std::size_t(image.width) +
                       std::size_t(wrap(col, image.width)));
}

const TextureImage& level_image(const TextureImage& image, const std::vector<TextureImage>& levels, int k) {
    return k <= 0 ? image : levels[std::size_t(k - 1)];
}

// The footprint in texels of the image: the repeats scale (u, v) before the image's size does.
void in_texels(const TextureImage& image, const TextureFootprint& f, float ru, float rv, glm::vec2& dx, glm::vec2& dy) {
    const glm::vec2 scale(ru * float(image.width), rv * float(image.height));
    dx = f.dx * scale;
    dy = f.dy * scale;
}

// pbrt-v4's Gaussian of EWA, exp(-2 r²) - exp(-2) over r² ∈ [0, 1], tabulated once.
constexpr int kWeights = 128;
const std::array<float, kWeights>& ewa_weights() {
    static const std::array<float, kWeights> table = [] {
        std::array<float, kWeights> t{};
        for (int i = 0; i < kWeights; ++i) {
            const float r2 = float(i) / float(kWeights - 1);
            t[std::size_t(i)] = std::exp(-2.0f * r2) - std::exp(-2.0f);
        }
        return t;
    }();
    return table;
}

// The Gaussian-weighted mean of the texels of level `k` inside the ellipse with axes dx, dy (in
// the level's texels) around texture position (s, t) ∈ [0, 1)² (Heckbert's EWA, as pbrt-v4).
glm::vec3 ewa(const TextureImage& level, float s, float t, glm::vec2 dx, glm::vec2 dy) {
    const float x = s * float(level.width) - 0.5f, y = t * float(level.height) - 0.5f;
    // The ellipse's implicit form A s² + B s t + C t² < 1, widened by a texel so it always holds one.
    float a = dx.y * dx.y + dy.y * dy.y + 1.0f;
    float b = -2.0f * (dx.x * dx.y + dy.x * dy.y);
    float c = dx.x * dx.x + dy.x * dy.x + 1.0f;
    const float inv_f = 1.0f / (a * c - b * b * 0.25f);
    a *= inv_f;
    b *= inv_f;
    c *= inv_f;
    const float det = 4.0f * a * c - b * b, inv_det = 1.0f / det;
    const float half_w = 2.0f * inv_det * std::sqrt(std::max(0.0f, det * c));
    const float half_h = 2.0f * inv_det * std::sqrt(std::max(0.0f, det * a));
    const long x0 = long(std::ceil(x - half_w)), x1 = long(std::floor(x + half_w));
    const long y0 = long(std::ceil(y - half_h)), y1 = long(std::floor(y + half_h));
    const auto& weights = ewa_weights();
    glm::vec3 sum(0.0f);
    float total = 0.0f;
    for (long row = y0; row <= y1; ++row) {
        const float ty = float(row) - y;
        for (long col = x0; col <= x1; ++col) {
            const float sx = float(col) - x;
            const float r2 = a * sx * sx + b * sx * ty + c * ty * ty;
            if (!(r2 < 1.0f)) continue;
            const float w = weights[std::size_t(std::min(int(r2 * kWeights), kWeights - 1))];
            sum += w * texel_at(level, col, row);
            total += w;
        }
    }
    return total > 0.0f ? sum / total : texel_at(level, long(std::floor(x + 0.5f)), long(std::floor(y + 0.5f)));
}

constexpr float kMaxAnisotropy = 8.0f;  // pbrt-v4's: a longer ellipse is widened (blurred), not followed

}  // namespace

std::optional<TextureFilter> parse_texture_filter(std::string_view name) {
    if (name == "nearest") return TextureFilter::Nearest;
    if (name == "bilinear") return TextureFilter::Bilinear;
    if (name == "trilinear") return TextureFilter::Trilinear;
    if (name == "ewa") return TextureFilter::Ewa;
    return std::nullopt;
}

std::size_t mip_levels_bytes(int width, int height) {
    std::size_t bytes = 0;
    while (width > 1 || height > 1) {
        width = (width + 1) / 2;
        height = (height + 1) / 2;
        bytes += std::size_t(width) * std::size_t(height) * 3;
    }
    return bytes;
}

std::vector<TextureImage> build_mip_levels(const TextureImage& image) {
    std::vector<TextureImage> levels;
    if (image.width <= 0 || image.height <= 0) return levels;
    const TextureImage* above = &image;
    while (above->width > 1 || above->height > 1) {
        TextureImage next;
        next.width = (above->width + 1) / 2;
        next.height = (above->height + 1) / 2;
        next.rgb.reserve(std::size_t(next.width) * std::size_t(next.height) * 3);
        for (int row = 0; row < next.height; ++row)
            for (int col = 0; col < next.width; ++col) {
                const glm::vec3 mean = 0.25f * (texel_at(*above, 2 * col, 2 * row) + texel_at(*above, 2 * col + 1, 2 * row) +
                                                texel_at(*above, 2 * col, 2 * row + 1) +
                                                texel_at(*above, 2 * col + 1, 2 * row + 1));
                next.push_back(glm::u8vec3(glm::clamp(glm::round(mean * 255.0f), 0.0f, 255.0f)));
            }
        levels.push_back(std::move(next));
        above = &levels.back();
    }
    return levels;
}

glm::vec3 sample_texture_nearest(const TextureImage& image, glm::vec2 uv, float repeat_u, float repeat_v) {
    if (image.width <= 0 || image.height <= 0) return glm::vec3(1.0f);
    const float s = uv.x * repeat_u - std::floor(uv.x * repeat_u);
    const float t = uv.y * repeat_v - std::floor(uv.y * repeat_v);
    if (!std::isfinite(s) || !std::isfinite(t)) return image.texel(0);
    // Column c holds s·W ∈ [c, c + 1); min() for an s that rounds up to 1.
    const int col = std::min(int(s * float(image.width)), image.width - 1);
    const int row = std::min(int(t * float(image.height)), image.height - 1);
    return image.texel(std::size_t(row) * std::size_t(image.width) + std::size_t(col));
}

float trilinear_level(const TextureImage& image, int levels, const TextureFootprint& footprint, float repeat_u,
                      float repeat_v) {
    glm::vec2 dx, dy;
    in_texels(image, footprint, repeat_u, repeat_v, dx, dy);
    const float width = std::max(glm::length(dx), glm::length(dy));
    if (!(width > 1.0f)) return 0.0f;  // (NaN too)
    return std::min(std::log2(width), float(levels));
}

glm::vec3 sample_texture_filtered(const TextureImage& image, const std::vector<TextureImage>& levels,
                                  TextureFilter filter, glm::vec2 uv, float repeat_u, float repeat_v,
                                  const TextureFootprint& footprint) {
    if (image.width <= 0 || image.height <= 0) return glm::vec3(1.0f);
    const int top = int(levels.size());
    if (filter == TextureFilter::Trilinear) {
        const float level = trilinear_level(image, top, footprint, repeat_u, repeat_v);
        const int k = int(level);
        const float f = level - float(k);
        const glm::vec3 fine = sample_texture(level_image(image, levels, k), uv, repeat_u, repeat_v);
        if (f == 0.0f || k >= top) return fine;
        return (1.0f - f) * fine + f * sample_texture(level_image(image, levels, k + 1), uv, repeat_u, repeat_v);
    }
    glm::vec2 dx, dy;
    in_texels(image, footprint, repeat_u, repeat_v, dx, dy);
    if (glm::dot(dx, dx) < glm::dot(dy, dy)) std::swap(dx, dy);  // dx the longer axis
    const float longer = glm::length(dx);
    float shorter = glm::length(dy);
    if (!std::isfinite(longer) || !std::isfinite(shorter) || !(shorter > 0.0f))
        return sample_texture(image, uv, repeat_u, repeat_v);
    if (shorter * kMaxAnisotropy < longer) {
        const float widen = longer / (shorter * kMaxAnisotropy);
        dy *= widen;
        shorter *= widen;
    }
    // The level where the shorter axis is about a texel: the longer spans at most kMaxAnisotropy.
    const float level = shorter > 1.0f ? std::min(std::log2(shorter), float(top)) : 0.0f;
    const int k = int(level);
    const float f = level - float(k);
    const float s = uv.x * repeat_u - std::floor(uv.x * repeat_u);
    const float t = uv.y * repeat_v - std::floor(uv.y * repeat_v);
    if (!std::isfinite(s) || !std::isfinite(t)) return image.texel(0);
    auto at_level = [&](int j) {
        const TextureImage& l = level_image(image, levels, j);
        const glm::vec2 scale(float(l.width) / float(image.width), float(l.height) / float(image.height));
        glm::vec2 ax = dx * scale, ay = dy * scale;
        // Past the pyramid's top (or without one) the ellipse is shrunk to a few texels: the
        // texels it sums stay bounded.
        if (const float minor = glm::length(ay); minor > 2.0f) ax *= 2.0f / minor, ay *= 2.0f / minor;
        return ewa(l, s, t, ax, ay);
    };
    const glm::vec3 fine = at_level(k);
    if (f == 0.0f || k >= top) return fine;
    return (1.0f - f) * fine + f * at_level(k + 1);
}

}  // namespace whitted
