#pragma once
// The command line of the renderers that turn a scene file into an image file (whitted,
// whitted-mpi): the render settings of the one table (session/render_settings.h), bound to CLI11,
// and what only these front ends take (the scene, the output, --quiet, --stats).
#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/load_scene.h"
#include "render/render_job.h"
#include "session/render_settings.h"

namespace whitted::cli {

// Exit codes shared by the command-line renderers.
constexpr int kExitOk = 0, kExitUsage = 1, kExitScene = 2, kExitIo = 3, kExitInterrupted = 130;
constexpr int kExitTimeout = 4;  // --timeout ran out (whitted-mpi: also two ranks disagreeing on a tile)

struct RenderOptions {
    RenderSettings settings;
    std::string scene_path, output;
    bool quiet = false, stats = false;
    bool is_showcase = false;  // no scene given: the bundled showcase
    std::size_t for_image = 0;  // set by finish_render_options: the memory the image needs
};

// Declares every setting of the table on `app` for the front end `frontend` (those it refuses are
// accepted by the parser and refused after it, with the table's reason), and the positional scene,
// -o, -q and --stats.
void add_render_options(CLI::App& app, RenderOptions& o, Frontend frontend);

// Marks the settings given on the command line; refuses those the front end does not take; applies
// the mode's defaults; validates; fills the output name and checks the image's memory. Returns ""
// or the message of a usage error (print it, exit 1).
std::string finish_render_options(CLI::App& app, RenderOptions& o, Frontend frontend);

// The load's settings, with the memory left besides the image and the limits of --untrusted.
LoadOptions load_options(const RenderOptions& o, const std::atomic<bool>* cancel);

// The job for the whole image (threads, mode, sampling), without callbacks.
RenderJob render_job(const RenderOptions& o, const std::atomic<bool>* cancel);

// Parses argv into `o`: kExitOk to go on, or the code to exit with (--help and --version give
// -1 after printing: exit 0).
int parse_render_options(CLI::App& app, RenderOptions& o, int argc, char** argv, const char* program,
                         Frontend frontend);

// Binds one setting of the table to `app`, writing into `settings` (also the viewer's command line).
CLI::Option* add_setting_option(CLI::App& app, RenderSettings& settings, const Setting& setting);

// After app.parse: the names of the table's settings given on the command line into settings.given,
// and "" or why the front end refuses one of them.
std::string collect_given(CLI::App& app, RenderSettings& settings, Frontend frontend, const char* program);

}  // namespace whitted::cli
