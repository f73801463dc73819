// libFuzzer target: any bytes as an OpenEXR or PFM image to compare (the 8-bit formats are
// texture_fuzzer's), then every metric of `whitted compare` against the image with one value
// changed. Must never crash, read past the bytes or allocate past the limits, whatever the
// header says and whatever values (NaN, infinities) the pixels hold.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "compare/compare.h"
#include "film/linear_decode.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace whitted;
    ImageLimits limits;
    limits.max_pixels = std::size_t(1) << 22;  // 4 Mi pixels: within libFuzzer's memory limit
    LinearImage image;
    if (!decode_linear_image(std::string_view(reinterpret_cast<const char*>(data), size), limits, image).empty())
        return 0;
    if (image.rgb.size() > 4096) return 0;  // the metrics' cost grows with the pixels, not their risk
    LinearImage other = image;
    other.rgb[other.rgb.size() / 2].y += 0.5f;
    const CompareReport r = compare_images(image, other);
    __asm__ volatile("" : : "r"(r.flip.mean), "r"(r.ssim.mean), "r"(r.errors.psnr));
    return 0;
}
