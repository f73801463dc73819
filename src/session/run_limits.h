#pragma once
// What a run may take: memory sizes on the command line, the memory an image needs, the limits
// of --untrusted (for scene files from others: a class's submissions, a grading script).
#include <cstddef>
#include <optional>
#include <string>

#include "render/load_scene.h"
#include "render/render_job.h"

namespace whitted {

// "4G", "512M", "100000K", "2000000000": a number of bytes with an optional binary suffix.
std::optional<std::size_t> parse_memory_size(const std::string& text);

// What rendering and writing a width × height image to `output` takes besides the scene: the
// film (two while a pass continues the last, session/session.h) and the copy the writer encodes (the encoders stream it; PNG keeps a few 4 MB bands in flight).
std::size_t image_memory(int width, int height, const std::string& output, const SamplingSettings& sampling = {});

// --untrusted: limits for files one did not write (README, "Rendering files from others").
struct UntrustedLimits {
    static constexpr std::size_t kSceneFileBytes = std::size_t(16) << 20;
    static constexpr std::size_t kObjects = 1'000'000;
    static constexpr std::size_t kSteps = 10'000'000;
    static constexpr std::size_t kTextureFileBytes = std::size_t(32) << 20;
    static constexpr std::size_t kMeshFileBytes = std::size_t(32) << 20;
    static constexpr int kTextureSide = 4096;
    static constexpr std::size_t kTextureTexels = std::size_t(1) << 24;
    static constexpr std::size_t kMemory = std::size_t(1) << 30;  // unless --max-memory says otherwise
    static constexpr double kSeconds = 60;                        // unless --timeout says otherwise
    static constexpr int kImageSide = 8192;
};

// An interrupted render's part is written beside the output (NAME.partial.EXT) only if a tile of
// it was rendered and it is at most this many pixels: a bigger one could take longer to convert
// and encode than an interrupt should wait (a 715-megapixel PNG: tens of seconds).
constexpr std::size_t kMaxPartialImagePixels = 64'000'000;  // 8000 × 8000

// Why the part of an interrupted width × height render with `tiles_done` tiles is not written
// ("no tile was rendered", "…megapixels…"), or "" when it is.
std::string why_no_partial_image(int tiles_done, int width, int height);

// Applies UntrustedLimits to a load (textures confined to the scene's folder and --texture-path).
void apply_untrusted(LoadOptions& options);

}  // namespace whitted
