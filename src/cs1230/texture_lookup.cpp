#include "cs1230/texture_lookup.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace whitted::cs1230 {
namespace {

// Around the axis: θ = atan2(z, x), u = −θ/2π for θ < 0, else 1 − θ/2π (in float, then double,
// as the course's renderer computes it).
float around_u(const glm::vec3& p) {
    const float theta = std::atan2(p.z, p.x);
    const double turn = double(theta) / (2.0 * std::numbers::pi);
    return float(theta < 0.0f ? -turn : 1.0 - turn);
}

// The texel index along one axis for t in [0, 1] (clamped) and `repeat` copies of `size` texels.
int texel_index(float t, float repeat, int size) {
    t = std::clamp(t, 0.0f, 1.0f);
    const float x = t * repeat * float(size);
    double c = t >= 1.0f ? std::ceil(double(repeat) * double(size)) - 1.0 : std::floor(double(x));
    if (!std::isfinite(c) || c < 0.0) return 0;  // an absurd repeat: the first texel
    c = std::fmod(c, double(size));
    return int(c);
}

}  // namespace

glm::vec2 shape_uv(ShapeKind kind, ShapePart part, const glm::vec3& p) {
    switch (part) {
        case kPartSide:
            if (kind == ShapeKind::Sphere || kind == ShapeKind::Ellipsoid) {
                const float y = std::clamp(p.y, -0.5f, 0.5f);
                const float v = float(0.5 + std::asin(double(y) / 0.5) / std::numbers::pi);
                return {v <= 0.0f || v >= 1.0f ? 0.5f : around_u(p), v};
            }
            if (kind == ShapeKind::Cone && p.y >= 0.5f) return {0.5f, p.y + 0.5f};  // the apex
            return {around_u(p), p.y + 0.5f};
        case kPartTopCap: return {p.x + 0.5f, 0.5f - p.z};
        case kPartBottomCap: return {p.x + 0.5f, p.z + 0.5f};
        case kPartPosX: return {0.5f - p.z, p.y + 0.5f};
        case kPartNegX: return {p.z + 0.5f, p.y + 0.5f};
        case kPartPosY: return {p.x + 0.5f, 0.5f - p.z};
        case kPartNegY: return {p.x + 0.5f, p.z + 0.5f};
        case kPartPosZ: return {p.x + 0.5f, p.y + 0.5f};
        case kPartNegZ: return {0.5f - p.x, p.y + 0.5f};
    }
    return {0.0f, 0.0f};
}

glm::vec3 nearest_texel(const TextureImage& image, glm::vec2 uv, float repeat_u, float repeat_v) {
    if (image.width <= 0 || image.height <= 0) return glm::vec3(0.0f);
    const int c = texel_index(uv.x, repeat_u, image.width);
    const int r = texel_index(1.0f - uv.y, repeat_v, image.height);
    return image.texel(std::size_t(r) * std::size_t(image.width) + std::size_t(c));
}

}  // namespace whitted::cs1230
