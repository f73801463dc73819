// libFuzzer target: any bytes as a texture file, through the header checks and stb_image's
// decoders, then sampled. Must never crash, read uninitialised memory or take more than the limits.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "texture/texture_decode.h"
#include "texture/texture_sample.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace whitted;
    TextureLimits limits;
    limits.max_texels = std::size_t(1) << 22;  // 4 Mi texels: within libFuzzer's memory limit
    TextureImage image;
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    limits.gif = true;  // GIF too: the textures of CSCI 1230 files may be GIF (scene-format.md §9.5)
    if (!decode_texture(bytes, limits, image).empty()) return 0;
    // Every texel is read (a texel stb did not write would show under valgrind or MSan).
    unsigned sum = 0;
    for (std::uint8_t b : image.rgb) sum += b;
    sum += unsigned(sample_texture(image, {0.37f, 0.71f}, 2.0f, 3.0f).x);
    __asm__ volatile("" : : "r"(sum));  // keep the reads
    return 0;
}
