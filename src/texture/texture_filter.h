#pragma once
// Filtered texture look-ups (--texture-filter): the texel nearest the point, bilinear (the lab's
// rule, sample_texture), or over the pixel's footprint on the texture through a mip-map pyramid
// (trilinear, or EWA: an elliptical Gaussian, as pbrt-v4's util/mipmap.h).
#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "data/texture_image.h"

namespace whitted {

enum class TextureFilter : unsigned char { Nearest, Bilinear, Trilinear, Ewa };

std::optional<TextureFilter> parse_texture_filter(std::string_view name);
// Whether the filter reads a footprint and the mip-map pyramid.
inline bool uses_footprint(TextureFilter f) { return f == TextureFilter::Trilinear || f == TextureFilter::Ewa; }

// How (u, v) changes from a pixel to the next one to the right (dx) and down (dy), before the
// texture's repeats.
struct TextureFootprint {
    glm::vec2 dx, dy;
};

// The levels below the image of its mip-map pyramid: each half the one above in each direction
// (odd sizes rounded up; the last 1 × 1), a texel the mean of the 2 × 2 above it (wrapping around
// the edges, as the texture repeats).
std::vector<TextureImage> build_mip_levels(const TextureImage& image);
// Their bytes, known before they are made.
std::size_t mip_levels_bytes(int width, int height);

// The texel whose square holds (u, v) (repeated as sample_texture): no blending, the blocky look.
glm::vec3 sample_texture_nearest(const TextureImage& image, glm::vec2 uv, float repeat_u, float repeat_v);

// The pyramid level a trilinear look-up reads: log2 of the footprint's longer side in texels of
// the image (0 = the image; clamped to [0, levels]).
float trilinear_level(const TextureImage& image, int levels, const TextureFootprint& footprint, float repeat_u,
                      float repeat_v);

// The look-up over `footprint` (trilinear or EWA; `levels` from build_mip_levels, or empty: the
// image alone). A footprint that is not finite reads the image bilinearly.
glm::vec3 sample_texture_filtered(const TextureImage& image, const std::vector<TextureImage>& levels,
                                  TextureFilter filter, glm::vec2 uv, float repeat_u, float repeat_v,
                                  const TextureFootprint& footprint);

}  // namespace whitted
