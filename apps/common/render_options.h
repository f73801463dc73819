#pragma once
// The options every renderer frontend that turns a scene file into an image file takes (whitted,
// whitted-mpi): declared once on a CLI11 app, checked once, turned into the load and render settings.
#include <atomic>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/load_scene.h"
#include "render/render_job.h"

namespace whitted::cli {

// Exit codes shared by the command-line renderers.
constexpr int kExitOk = 0, kExitUsage = 1, kExitScene = 2, kExitIo = 3, kExitInterrupted = 130;

struct RenderOptions {
    std::string scene_path, output, mode_name = "whitted", missing = "error";
    int width = 640, height = 480, max_depth = 5, aa = 1, spp = 1, threads = 0;
    float aa_threshold = 0.0f, time = 0.0f;
    bool lenient = false, quiet = false, stats = false;
    std::vector<std::string> texture_dirs;
    bool is_showcase = false;  // no scene given: the bundled showcase
};

// Declares the options (and the positional scene) on `app`, writing into `o`.
void add_render_options(CLI::App& app, RenderOptions& o);

// After parsing: fills the defaults that depend on other options (showcase, output name) and
// checks what CLI11 cannot. Returns "" or the message of a usage error (print it, exit 1).
std::string finish_render_options(RenderOptions& o);

LoadOptions load_options(const RenderOptions& o, const std::atomic<bool>* cancel);

// The job for the whole image (threads, mode, sampling), without callbacks.
RenderJob render_job(const RenderOptions& o, const std::atomic<bool>* cancel);

// Parses argv into `o`: kExitOk to go on, or the code to exit with (--help and --version give
// -1 after printing: exit 0).
int parse_render_options(CLI::App& app, RenderOptions& o, int argc, char** argv, const char* program);

}  // namespace whitted::cli
