#pragma once
// OpenEXR encoding (float RGB, ZIP compression) onto an open file, kept apart so that only this
// file sees OpenEXR's headers.
#include <cstdio>

#include <vector>

#include "film/image.h"
#include "film/image_layer.h"

namespace whitted {

// Writes `image` to `file` from its current position; false if OpenEXR or the file failed, with
// `error` the file's errno (0: OpenEXR's own failure).
// `layers`: more channels beside R, G, B (film/image_layer.h), of the image's size.
bool encode_exr(const LinearImage& image, std::FILE* file, int& error, const std::vector<ImageLayer>& layers = {});

}  // namespace whitted
