#include "render_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "film/image_io.h"
#include "integrator/render_mode.h"
#include "run_limits.h"
#include "base/read_file.h"
#include "parse/binary_sniff.h"
#include "parse/parser.h"

namespace whitted::cli {
namespace {

std::string bundled_showcase() {
    // The source tree's scenes/ (known at build time) — the build is run from a checkout.
    return std::string(WHITTED_SCENES_DIR) + "/showcase.sc";
}

std::string default_output(const std::string& scene, bool is_showcase) {
    if (is_showcase) return "showcase.png";
    return std::filesystem::path(scene).replace_extension(".png").string();
}

// True when writing `output` would replace the scene file itself (`whitted scene.png`).
bool same_file(const std::string& a, const std::string& b) {
    std::error_code ec;
    return std::filesystem::equivalent(a, b, ec) && !ec;
}

// CLI::Range lets NaN through (every comparison with it is false).
const CLI::Validator finite_number(
    [](std::string& s) {
        return std::isfinite(std::strtof(s.c_str(), nullptr)) ? std::string() : "not a finite number: " + s;
    },
    "FINITE");

const CLI::Validator memory_size(
    [](std::string& s) { return parse_memory_size(s) ? std::string() : "not a size such as 512M or 4G: " + s; },
    "SIZE");

}  // namespace

void add_render_options(CLI::App& app, RenderOptions& o) {
    app.option_defaults()->always_capture_default();
    app.add_option("scene", o.scene_path, "Scene file (.sc); without one, renders the bundled showcase");
    app.add_option("-o,--output", o.output,
                   "Output image: .png (default), .bmp, .ppm, .jpg; .exr or .pfm keep linear, unclamped values");
    app.add_option("--width", o.width, "Image width in pixels")->check(CLI::Range(1, 32768));
    app.add_option("--height", o.height, "Image height in pixels")->check(CLI::Range(1, 32768));
    app.add_option("--max-depth", o.max_depth,
                   "Recursion limit for reflection/refraction (camera ray = 0); in path mode the bounces of a path "
                   "(default 64 there)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--aa", o.aa, "Anti-aliasing: N x N rays per pixel, averaged (1 = one ray through the centre)")
        ->check(CLI::Range(1, Sampler::kMaxAa));
    app.add_option("--spp", o.spp,
                   "Samples per pixel (per sub-pixel with --aa N: N x N x spp in all) for soft shadows, depth of "
                   "field and gloss; 1 = the pixel, lens and light centres (default 64 in path mode)")
        ->check(CLI::Range(1, Sampler::kMaxSpp));
    app.add_option("--aa-threshold", o.aa_threshold,
                   "Adaptive anti-aliasing: supersample only pixels whose colour differs from a neighbour's by more "
                   "than this (0-1, per channel); 0 = every pixel")
        ->check(CLI::Range(0.0f, 1.0f))
        ->check(finite_number);
    app.add_option("--mode", o.mode_name,
                   "Render mode: whitted (the lab's model), path (physically based path tracing), raycast, normals, "
                   "depth")
        ->check(CLI::IsMember({"whitted", "path", "raycast", "normals", "depth"}));
    app.add_option("--time", o.time,
                   "Scene time t: 'velocity x y z' moves by t·(x, y, z), 'angularrate ax ay az r' turns by r·t "
                   "degrees (0 = the still image)")
        ->check(finite_number);
    app.add_option("--threads", o.threads, "Worker threads (0 = all hardware threads)")->check(CLI::Range(0, 1024));
    // One directory per --texture-path (repeat it for more): a list would swallow the scene after it.
    app.add_option("--texture-path", o.texture_dirs, "Extra directory to look for textures in (repeat for more)")
        ->allow_extra_args(false)
        ->default_str("");
    app.add_option("--missing-textures", o.missing, "What to do with a texture that cannot be loaded")
        ->check(CLI::IsMember({"error", "checker"}));
    app.add_option("--max-memory", o.max_memory_text,
                   "Memory the image and scene may need, estimated before anything is built: a size such as 512M "
                   "or 4G (default: three quarters of this machine's RAM)")
        ->check(memory_size);
    app.add_flag("--untrusted", o.untrusted,
                 "For scene files you did not write: textures only from the scene's folder and --texture-path, and "
                 "lower limits on file sizes, objects, textures, memory (1G) and time (60 s) (see the README)");
    app.add_flag("--lenient", o.lenient, "Skip unknown keywords and object types with a warning instead of failing");
    app.add_flag("-q,--quiet", o.quiet, "No progress line");
    app.add_flag("--stats", o.stats, "Print timings and ray counts");
}

void add_timeout_option(CLI::App& app, RenderOptions& o) {
    app.add_option("--timeout", o.timeout,
                   "Stop after this many seconds (load and render), keeping the part rendered as NAME.partial.EXT; "
                   "0 = never")
        ->check(CLI::Range(0.0, 1e7))
        ->check(finite_number);
}

std::string finish_render_options(RenderOptions& o, bool timeout_given) {
    if (o.aa_threshold > 0.0f && o.spp > 1)
        return "--aa-threshold compares the colours of pixel centres, which --spp > 1 does not take; use "
               "--aa-threshold with --spp 1, or --spp alone";
    o.is_showcase = o.scene_path.empty();
    if (o.is_showcase) o.scene_path = bundled_showcase();
    if (o.output.empty()) o.output = default_output(o.scene_path, o.is_showcase);
    // An unknown format or a size it cannot hold, before the render.
    if (std::string problem = output_problem(o.width, o.height, o.output); !problem.empty()) return problem;
    // (An image given as the scene, `whitted out.png`, is let through: its load says what it is.)
    if (same_file(o.output, o.scene_path) &&
        !binary_file_kind(read_regular_file(o.scene_path, ParseOptions{}.max_file_bytes).bytes))
        return "the output '" + o.output + "' is the scene file itself; name another with -o";
    using Untrusted = UntrustedLimits;
    if (o.untrusted && (o.width > Untrusted::kImageSide || o.height > Untrusted::kImageSide))
        return "--untrusted renders images of at most " + std::to_string(Untrusted::kImageSide) + "x" +
               std::to_string(Untrusted::kImageSide) + " pixels (" + std::to_string(o.width) + "x" +
               std::to_string(o.height) + " asked for)";
    if (o.untrusted && !timeout_given) o.timeout = Untrusted::kSeconds;
    o.max_memory = !o.max_memory_text.empty() ? *parse_memory_size(o.max_memory_text)
                   : o.untrusted              ? Untrusted::kMemory
                                              : default_max_memory();
    o.for_image = image_memory(o.width, o.height, o.output);
    if (o.for_image > o.max_memory)
        return "a " + std::to_string(o.width) + "x" + std::to_string(o.height) + " image needs about " +
               describe_bytes(o.for_image) + " of memory to render and write, more than the limit of " +
               describe_bytes(o.max_memory) + " (--max-memory)";
    return "";
}

int parse_render_options(CLI::App& app, RenderOptions& o, int argc, char** argv, const char* program) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? -1 : kExitUsage;
    }
    if (o.mode_name == "path") {  // §9.2: a path tracer's defaults, where the user gave none
        if (app.get_option("--spp")->count() == 0) o.spp = 64;
        if (app.get_option("--max-depth")->count() == 0) o.max_depth = 64;
    }
    const CLI::Option* timeout = app.get_option_no_throw("--timeout");
    if (std::string problem = finish_render_options(o, timeout && timeout->count() > 0); !problem.empty()) {
        std::cerr << program << ": error: " << problem << "\n";
        return kExitUsage;
    }
    return kExitOk;
}

LoadOptions load_options(const RenderOptions& o, const std::atomic<bool>* cancel) {
    LoadOptions lo;
    lo.cancel = cancel;
    lo.lenient = o.lenient;
    lo.threads = o.threads;  // --threads 1 means one thread for the build too
    lo.time = o.time;
    lo.textures.search_dirs = o.texture_dirs;
    lo.textures.missing = o.missing == "checker" ? MissingTexturePolicy::Checker : MissingTexturePolicy::Error;
    if (o.max_memory > 0) lo.max_memory = o.max_memory - std::min(o.max_memory, o.for_image);
    if (o.untrusted) apply_untrusted(lo);
    return lo;
}

RenderJob render_job(const RenderOptions& o, const std::atomic<bool>* cancel) {
    RenderJob job;
    job.width = o.width;
    job.height = o.height;
    job.integrator = {*parse_render_mode(o.mode_name), o.max_depth};
    job.sampling = {o.aa, o.spp, o.aa_threshold};
    job.threads = o.threads;
    job.cancel = cancel;
    return job;
}

}  // namespace whitted::cli
