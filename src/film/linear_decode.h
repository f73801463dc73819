#pragma once
// Reading back the linear formats whitted writes (.exr, .pfm) from a file's bytes, for tools that
// compare images. The size is read from the header and checked against the limits before a
// pixel is decoded; a file shorter than its header says is refused, never read past its end.
#include <cstddef>
#include <string>
#include <string_view>

#include "film/image.h"

namespace whitted {

struct ImageLimits {
    int max_side = 16384;                           // pixels across or down
    std::size_t max_pixels = std::size_t(1) << 26;  // 64 Mi pixels: 768 MB as float RGB
};

// True if `bytes` start as an OpenEXR file (its magic number) or a PFM ("PF" or "Pf" and a newline).
bool is_linear_image_data(std::string_view bytes);

// Decodes OpenEXR (exr_decode.h) or PFM: colour "PF" or grey "Pf", either byte order (the sign
// of the scale; its size is ignored), rows bottom to top. A grey image gets R = G = B. Returns ""
// or why not (without the file's name).
std::string decode_linear_image(std::string_view bytes, const ImageLimits& limits, LinearImage& out);

// Why a width × height image is over `limits` (or not an image), or "".
std::string image_size_problem(long long width, long long height, const ImageLimits& limits);

}  // namespace whitted
