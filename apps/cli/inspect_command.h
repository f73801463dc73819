#pragma once
// `whitted SCENE --inspect X,Y`: print what made one pixel (src/inspect) instead of rendering.
#include <optional>
#include <string>

#include "render/load_scene.h"
#include "render/render_job.h"

namespace whitted::cli {

struct PixelArg {
    int x = 0, y = 0;
};

// "X,Y" (column, row; row 0 at the top) inside a width × height image, or a message saying what
// is wrong with it in `error`.
std::optional<PixelArg> parse_pixel_arg(const std::string& text, int width, int height, std::string& error);

// Prints the report of pixel `p` of `job`'s image of the loaded scene to stdout, paths shown
// relative to the scene's folder. Returns the exit code.
int print_inspection(const Scene& scene, const RenderJob& job, const PixelArg& p, const std::string& scene_path);

}  // namespace whitted::cli
