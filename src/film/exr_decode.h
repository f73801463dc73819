#pragma once
// OpenEXR decoding from memory, kept apart so that only this file sees OpenEXR's headers (as
// exr_encode.h for writing).
#include <string>
#include <string_view>

#include "film/image.h"
#include "film/linear_decode.h"

namespace whitted {

// The data window of the first part of an OpenEXR file as linear RGB (half, float and uint
// channels converted to float). R, G and B are read (a missing one is 0), or Y alone for a
// luminance image (R = G = B = Y); other channels (A, Z, …) are ignored. Subsampled, deep and
// empty images are refused. Returns "" or why not.
std::string decode_exr(std::string_view bytes, const ImageLimits& limits, LinearImage& out);

}  // namespace whitted
