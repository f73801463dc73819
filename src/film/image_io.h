#pragma once
// Image files: written atomically in the format the extension names; read for tests and textures.
#include <cstdint>
#include <string>

#include <vector>

#include "film/image.h"
#include "film/image_layer.h"

namespace whitted {

// Writes PNG (default; zlib, film/png_encode.h), BMP, PPM (binary P6) or JPEG (stb) by the file's
// extension (case-insensitive); .exr and .pfm get the 8-bit values as linear floats (value / 255).
// The image goes to a temporary file beside the target (hidden: .NAME.tmpNNNNNN.EXT), which is
// renamed over it only when complete, so a failure never leaves a half-written image. Returns "" or an error message.
std::string write_image(const Image& image, const std::string& path);

// The temporary file a write_image call is writing right now, or nullptr. For a signal handler
// that exits at once: it may read this (a fixed buffer behind an atomic flag, async-signal-safe)
// and unlink the file, so that not even an exit in mid-write leaves a partial file behind.
const char* image_file_being_written();

// Why write_image would refuse a width × height image at `path` (an unknown extension, a size
// the format cannot hold), or "": a frontend asks before spending a render on it.
std::string output_problem(int width, int height, const std::string& path);

// Why the file `path` cannot be created, found before a render is spent on it (a missing folder,
// no permission, a directory of that name), or "". Creates and removes a file beside it to know.
std::string output_unwritable(const std::string& path);

// Where an interrupted render's image goes instead of `path`, so that a good image there is never
// replaced by a partial one: NAME.partial.EXT beside it (NAME shortened if it would not fit).
std::string partial_image_path(const std::string& path);

// True for the extensions write_image understands (.png .bmp .ppm .jpg .jpeg .exr .pfm).
bool is_supported_output(const std::string& path);

// True for the formats that keep linear floating-point values (.exr .pfm).
bool is_linear_output(const std::string& path);

// Writes OpenEXR (float RGB) or PFM by the extension, atomically as write_image does. The 8-bit
// formats get the image clamped and converted as §7 says. Returns "" or an error message.
// `layers`: more channels an .exr keeps beside R, G, B (film/image_layer.h; other formats refuse them).
std::string write_linear_image(const LinearImage& image, const std::string& path,
                               const std::vector<ImageLayer>& layers = {});

// Reads any format stb_image reads into 8-bit RGB. Returns "" or an error message.
std::string read_image(const std::string& path, Image& out);

}  // namespace whitted
