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

// What else --inspect gives: the pixel's ray tree written to a file (.obj polylines or .json), and
// printed as JSON instead of the text report.
struct InspectOutputs {
    std::string ray_tree_file;
    bool json = false;
};

// "" or what is wrong with these outputs (a file name that is neither .obj nor .json, a folder that
// cannot be written to).
std::string inspect_outputs_problem(const InspectOutputs& outputs);

// Prints the report of pixel `p` of `job`'s image of the loaded scene to stdout (or its ray tree
// as JSON), paths shown relative to the scene's folder, and writes the ray tree file if asked.
// Returns the exit code.
int print_inspection(const Scene& scene, const RenderJob& job, const PixelArg& p, const std::string& scene_path,
                     const InspectOutputs& outputs = {});

}  // namespace whitted::cli
