#pragma once
// The options every renderer frontend that turns a scene file into an image file takes (whitted,
// whitted-mpi): declared once on a CLI11 app, checked once, turned into the load and render settings.
#include <atomic>
#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "render/load_scene.h"
#include "render/render_job.h"

namespace whitted::cli {

// Exit codes shared by the command-line renderers.
constexpr int kExitOk = 0, kExitUsage = 1, kExitScene = 2, kExitIo = 3, kExitInterrupted = 130;
constexpr int kExitTimeout = 4;  // whitted's --timeout ran out (whitted-mpi has no --timeout; its 4 is another)

struct RenderOptions {
    std::string scene_path, output, mode_name = "whitted", missing = "error";
    int width = 640, height = 480, max_depth = 5, aa = 1, spp = 1, threads = 0;
    float aa_threshold = 0.0f, time = 0.0f;
    std::string cs1230_stage = "illuminate";  // which of the course's projects draws a CSCI 1230 file (§9.5)
    bool lenient = false, quiet = false, stats = false;
    std::vector<std::string> texture_dirs;
    bool is_showcase = false;  // no scene given: the bundled showcase
    // Limits (README, "Rendering files from others"): --untrusted, --max-memory SIZE, --timeout S.
    bool untrusted = false;
    std::string max_memory_text;
    double timeout = 0;  // seconds; 0 = none (--untrusted: 60 unless given)
    std::size_t max_memory = 0, for_image = 0;  // set by finish_render_options: the limit, the image's share
};

// Declares the options (and the positional scene) on `app`, writing into `o`.
void add_render_options(CLI::App& app, RenderOptions& o);
// --timeout S (whitted only: an MPI job's time limit is the batch system's, whose SIGTERM keeps
// the part rendered as any interrupt does).
void add_timeout_option(CLI::App& app, RenderOptions& o);

// After parsing: fills the defaults that depend on other options (showcase, output name, the
// limits of --untrusted and --max-memory) and checks what CLI11 cannot, including the memory the
// image needs. Returns "" or the message of a usage error (print it, exit 1).
std::string finish_render_options(RenderOptions& o, bool timeout_given = false);

// The load's settings, with the memory left besides the image and the limits of --untrusted.
LoadOptions load_options(const RenderOptions& o, const std::atomic<bool>* cancel);

// The job for the whole image (threads, mode, sampling), without callbacks.
RenderJob render_job(const RenderOptions& o, const std::atomic<bool>* cancel);

// Parses argv into `o`: kExitOk to go on, or the code to exit with (--help and --version give
// -1 after printing: exit 0).
int parse_render_options(CLI::App& app, RenderOptions& o, int argc, char** argv, const char* program);

}  // namespace whitted::cli
