#include "session/run_limits.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "film/film.h"
#include "film/image_io.h"
#include "session/session.h"

namespace whitted {

std::optional<std::size_t> parse_memory_size(const std::string& text) {
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (errno || end == text.c_str() || !std::isfinite(value) || value <= 0) return std::nullopt;
    const std::string suffix(end);
    double scale = 1;
    if (suffix == "K" || suffix == "k") scale = 0x1p10;
    else if (suffix == "M" || suffix == "m") scale = 0x1p20;
    else if (suffix == "G" || suffix == "g") scale = 0x1p30;
    else if (suffix == "T" || suffix == "t") scale = 0x1p40;
    else if (!suffix.empty()) return std::nullopt;
    if (value * scale >= 0x1p63 || value * scale < 1) return std::nullopt;
    return std::size_t(value * scale);
}

std::size_t image_memory(int width, int height, const std::string& output, const SamplingSettings& sampling) {
    // The films (FilmPixel: a sum of 3 floats and a weight; two while a pass continues the last),
    // then the copy the writer encodes: 3 floats a pixel for .exr/.pfm, 3 bytes for the 8-bit formats.
    const std::size_t films = sample_passes(sampling).size() > 1 ? 2 : 1;
    const std::size_t per_pixel = films * sizeof(FilmPixel) + (is_linear_output(output) ? 3 * sizeof(float) : 3);
    return std::size_t(width) * std::size_t(height) * per_pixel;
}

std::string why_no_partial_image(int tiles_done, int width, int height) {
    if (tiles_done <= 0) return "no tile was rendered";
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    if (pixels > kMaxPartialImagePixels)
        return "a partial image of " + std::to_string(pixels / 1'000'000) + " megapixels is not written (more than " +
               std::to_string(kMaxPartialImagePixels / 1'000'000) + " megapixels take long to write)";
    return "";
}

void apply_untrusted(LoadOptions& options) {
    using L = UntrustedLimits;
    options.max_file_bytes = std::min(options.max_file_bytes, L::kSceneFileBytes);
    options.limits.max_instances = std::min(options.limits.max_instances, L::kObjects);
    options.limits.max_steps = std::min(options.limits.max_steps, L::kSteps);
    TextureLimits& t = options.textures.limits;
    t.max_file_bytes = std::min(t.max_file_bytes, L::kTextureFileBytes);
    t.max_side = std::min(t.max_side, L::kTextureSide);
    t.max_texels = std::min(t.max_texels, L::kTextureTexels);
    options.textures.confined = true;  // textures, meshes and the scene file itself
    options.max_mesh_file_bytes = std::min(options.max_mesh_file_bytes, L::kMeshFileBytes);
}

}  // namespace whitted
