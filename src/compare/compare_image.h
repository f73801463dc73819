#pragma once
// Reading an image to compare, in any format whitted reads or writes, as float RGB: the 8-bit
// formats (PNG, JPEG, BMP, TGA, binary and plain PPM) as byte / 255, .exr and .pfm as the linear
// values they keep. Read through base/read_file.h's door and the decoders' size checks.
#include <cstddef>
#include <string>

#include "film/image.h"
#include "film/linear_decode.h"

namespace whitted {

struct CompareImage {
    LinearImage pixels;
    std::string format;   // "PNG", "JPEG", "BMP", "TGA", "PPM", "OpenEXR", "PFM"
    bool linear = false;  // OpenEXR or PFM: values may lie outside [0, 1]
};

struct CompareLimits {
    std::size_t max_file_bytes = std::size_t(256) << 20;
    ImageLimits image;  // 16384 pixels across, 64 Mi pixels
};

// "" and the image in `out`, or a message naming the file and what is wrong with it.
std::string read_compare_image(const std::string& path, CompareImage& out, const CompareLimits& limits = {});

}  // namespace whitted
