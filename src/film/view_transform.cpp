#include "film/view_transform.h"

#include <cmath>


namespace whitted {

std::optional<ViewTransform> parse_view_transform(std::string_view name) {
    if (name == "linear") return ViewTransform::Linear;
    if (name == "srgb") return ViewTransform::Srgb;
    if (name == "filmic") return ViewTransform::Filmic;
    return std::nullopt;
}

const char* view_transform_name(ViewTransform view) {
    switch (view) {
        case ViewTransform::Linear: return "linear";
        case ViewTransform::Srgb: return "srgb";
        case ViewTransform::Filmic: return "filmic";
    }
    return "?";
}

float srgb_encode(float c) {
    c = clamp01(c);
    if (c == 1.0f) return 1.0f;  // 1.055 − 0.055 is not 1 in floats
    return c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
}

namespace {

// Narkowicz's fit of the ACES reference rendering and output transforms: 0 → 0, a mid grey of
// 0.18 → 0.27, and 1 only as c → ∞ (clamped: the fit overshoots 1 slightly beyond c ≈ 10).
float aces_fit(float c) {
    c = c > 0.0f ? c : 0.0f;  // NaN too
    return clamp01(c * (2.51f * c + 0.03f) / (c * (2.43f * c + 0.59f) + 0.14f));
}

}  // namespace

float view_encode(ViewTransform view, float c) {
    switch (view) {
        case ViewTransform::Linear: return clamp01(c);
        case ViewTransform::Srgb: return srgb_encode(c);
        case ViewTransform::Filmic: return srgb_encode(aces_fit(c));
    }
    return 0.0f;
}

std::uint8_t view_byte(ViewTransform view, float c) {
    return static_cast<std::uint8_t>(255.0f * view_encode(view, c) + 0.5f);
}

void encode_region(const LinearImage& from, Image& to, const PixelRegion& r, ViewTransform view, float scale) {
    to.srgb = view != ViewTransform::Linear;
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(from.width) + std::size_t(x);
            const glm::vec3 c = from.rgb[i] * scale;
            for (int k = 0; k < 3; ++k) to.rgb[3 * i + std::size_t(k)] = view_byte(view, c[k]);
        }
}

}  // namespace whitted
