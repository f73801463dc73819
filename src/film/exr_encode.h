#pragma once
// OpenEXR encoding (float RGB, ZIP compression) onto an open file, kept apart so that only this
// file sees OpenEXR's headers.
#include <cstdio>

#include "film/image.h"

namespace whitted {

// Writes `image` to `file` from its current position; false if OpenEXR or the file failed, with
// `error` the file's errno (0: OpenEXR's own failure).
bool encode_exr(const LinearImage& image, std::FILE* file, int& error);

}  // namespace whitted
