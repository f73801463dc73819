#pragma once
// JPEG textures through libjpeg-turbo, not stb_image: Debian builds stb with its assertions on,
// and a corrupt Huffman table aborts the process inside stbi__jpeg_huff_decode (found by
// fuzz/texture_fuzzer). libjpeg reports every error, and is fuzzed by OSS-Fuzz.
#include <string>
#include <string_view>

#include "texture/texture_decode.h"

namespace whitted {

// "" and the image in `out`, or why not. Refuses the image's size by `limits` from the header,
// before decoding; a warning (a truncated or corrupt file) is an error.
std::string decode_jpeg(std::string_view bytes, const TextureLimits& limits, TextureImage& out);

}  // namespace whitted
