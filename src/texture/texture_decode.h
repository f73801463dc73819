#pragma once
// Image file bytes → TextureImage, refusing what would not fit: the dimensions are read from the
// header and checked before a pixel is decoded, a file shorter than its header says is refused
// (never decoded from memory past its end), and formats whitted does not document are refused.
#include <cstddef>
#include <string>
#include <string_view>

#include "data/texture_image.h"

namespace whitted {

struct TextureLimits {
    std::size_t max_file_bytes = std::size_t(256) << 20;  // read no more of a texture file than this
    int max_side = 16384;                                 // texels across or down
    std::size_t max_texels = std::size_t(1) << 26;        // 64 Mi texels: 192 MB as 8-bit RGB
    std::size_t max_total_bytes = std::size_t(1) << 30;   // all textures of a scene together, as stored
    // GIF (its first frame) is decoded only for the textures of CSCI 1230 files (scene-format.md
    // §9.5: their course's renderer reads it, and the course ships one); refused otherwise (§8).
    bool gif = false;
    // Each texture's mip-map pyramid (texture_filter.h, for --texture-filter trilinear or ewa)
    // is stored beside it, and counts in max_total_bytes too.
    bool mip_levels = false;
};

// What a decoded texture takes in memory under `limits`: its texels, and its pyramid if kept.
std::size_t stored_texture_bytes(int width, int height, const TextureLimits& limits);

// Decodes PNG, BMP, TGA, binary PNM (P5/P6) and, with limits.gif, GIF with stb_image, JPEG with libjpeg (jpeg_decode.h),
// plain PPM (P3) with ascii_ppm.h, into 8-bit RGB; alpha is dropped. Returns ""
// or why not (without the file's name), e.g. "16384x16384 texels, more than the limit of ...".
std::string decode_texture(std::string_view bytes, const TextureLimits& limits, TextureImage& out);

}  // namespace whitted
