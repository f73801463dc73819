#pragma once
// Plain (ASCII, "P3") PPM, which stb_image does not read: the Brown/Tufts course's textures
// are in it (scene-format.md §9.4).
#include <string>
#include <string_view>

#include "data/texture_image.h"
#include "texture/texture_decode.h"

namespace whitted {

bool is_ascii_ppm(std::string_view bytes);

// Decodes a P3 file: texel = value / maxval (linear, as every texture), stored as the nearest of
// the 8-bit values (TextureImage). False with `reason` for a malformed or truncated file, a value
// above maxval, or a size past the limits (checked on the header, before anything is allocated).
bool decode_ascii_ppm(std::string_view bytes, TextureImage& out, std::string& reason,
                      const TextureLimits& limits = {});

}  // namespace whitted
