// whitted: the command-line renderer. Scene file in, image file out.
// Exit codes: 0 success, 1 bad usage, 2 bad scene, 3 I/O failure (the scene cannot be read, the
// image cannot be written, out of memory), 130 interrupted.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "film/image_io.h"
#include "interrupt.h"
#include "progress.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace {

constexpr int kExitUsage = 1, kExitScene = 2, kExitIo = 3, kExitInterrupted = 130;

std::string bundled_showcase() {
    // The source tree's scenes/ (known at build time) — the build is run from a checkout.
    return std::string(WHITTED_SCENES_DIR) + "/showcase.sc";
}

std::string default_output(const std::string& scene, bool is_showcase) {
    if (is_showcase) return "showcase.png";
    return std::filesystem::path(scene).replace_extension(".png").string();
}

}  // namespace

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

// Warnings printed before the rest are only counted: a file with 100,000 stray brackets
// should not bury its one real message.
constexpr int kMaxWarningsShown = 50;

int run(int argc, char** argv) {
    using namespace whitted;
    CLI::App app{"whitted: a Whitted-style ray tracer for SceneView/Ray .sc scene files"};
    app.set_version_flag("--version", "whitted 0.1.0");
    app.option_defaults()->always_capture_default();
    app.footer("Exit codes: 0 done, 1 bad usage, 2 bad scene (FILE:LINE:COL: error: ...), 3 I/O failure, "
               "130 interrupted (the part rendered so far is written).");
    std::string scene_path, output, mode_name = "whitted", missing = "error";
    int width = 640, height = 480, max_depth = 5, aa = 1, spp = 1, threads = 0;
    float aa_threshold = 0.0f;
    bool lenient = false, quiet = false, stats = false;
    std::vector<std::string> texture_dirs;
    app.add_option("scene", scene_path, "Scene file (.sc); without one, renders the bundled showcase");
    app.add_option("-o,--output", output,
                   "Output image: .png (default), .bmp, .ppm, .jpg; .exr or .pfm keep linear, unclamped values");
    app.add_option("--width", width, "Image width in pixels")->check(CLI::Range(1, 32768));
    app.add_option("--height", height, "Image height in pixels")->check(CLI::Range(1, 32768));
    auto* depth_option = app.add_option("--max-depth", max_depth,
                                        "Recursion limit for reflection/refraction (camera ray = 0); in path mode the "
                                        "bounces of a path (default 64 there)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--aa", aa, "Anti-aliasing: N x N rays per pixel, averaged (1 = one ray through the centre)")
        ->check(CLI::Range(1, Sampler::kMaxAa));
    auto* spp_option = app.add_option("--spp", spp,
                   "Samples per pixel (per sub-pixel with --aa N: N x N x spp in all) for soft shadows, depth of "
                   "field and gloss; 1 = the pixel, lens and light centres (default 64 in path mode)")
        ->check(CLI::Range(1, Sampler::kMaxSpp));
    app.add_option("--aa-threshold", aa_threshold,
                   "Adaptive anti-aliasing: supersample only pixels whose colour differs from a neighbour's by more "
                   "than this (0-1, per channel); 0 = every pixel")
        ->check(CLI::Range(0.0f, 1.0f))
        ->check(finite_number);
    app.add_option("--mode", mode_name,
                   "Render mode: whitted (the lab's model), path (physically based path tracing), raycast, normals, "
                   "depth")
        ->check(CLI::IsMember({"whitted", "path", "raycast", "normals", "depth"}));
    app.add_option("--threads", threads, "Worker threads (0 = all hardware threads)")->check(CLI::Range(0, 1024));
    app.add_option("--texture-path", texture_dirs, "Extra directory to look for textures in (repeatable)")
        ->default_str("");
    app.add_option("--missing-textures", missing, "What to do with a texture that cannot be loaded")
        ->check(CLI::IsMember({"error", "checker"}));
    app.add_flag("--lenient", lenient, "Skip unknown keywords and object types with a warning instead of failing");
    app.add_flag("-q,--quiet", quiet, "No progress line");
    app.add_flag("--stats", stats, "Print timings and ray counts");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : kExitUsage;
    }

    const RenderMode mode = *parse_render_mode(mode_name);
    if (mode == RenderMode::Path) {  // §9.2: a path tracer's defaults
        if (spp_option->count() == 0) spp = 64;
        if (depth_option->count() == 0) max_depth = 64;
    }
    if (aa_threshold > 0.0f && spp > 1) {
        std::cerr << "whitted: error: --aa-threshold compares the colours of pixel centres, which --spp > 1 does not "
                     "take; use --aa-threshold with --spp 1, or --spp alone\n";
        return kExitUsage;
    }
    const bool is_showcase = scene_path.empty();
    if (is_showcase) scene_path = bundled_showcase();
    if (output.empty()) output = default_output(scene_path, is_showcase);
    if (std::string problem = output_problem(width, height, output); !problem.empty()) {
        std::cerr << "whitted: error: " << problem << "\n";  // an unknown format or a size it cannot hold, before the render
        return kExitUsage;
    }
    if (same_file(output, scene_path)) {
        std::cerr << "whitted: error: the output '" << output << "' is the scene file itself; name another with -o\n";
        return kExitUsage;
    }

    cli::install_interrupt_handler();  // from here on Ctrl-C stops the load or the render
    LoadOptions load_options;
    load_options.cancel = &cli::interrupt_flag();
    load_options.lenient = lenient;
    load_options.threads = threads;  // --threads 1 means one thread for the build too
    load_options.textures.search_dirs = texture_dirs;
    load_options.textures.missing = missing == "checker" ? MissingTexturePolicy::Checker : MissingTexturePolicy::Error;
    LoadResult loaded = load_scene(scene_path, load_options);
    int warnings = 0;
    if (mode == RenderMode::Path)
        loaded.diagnostics.insert(loaded.diagnostics.end(), loaded.path_warnings.begin(), loaded.path_warnings.end());
    for (const Diagnostic& d : loaded.diagnostics)
        if (d.severity == Severity::Error || ++warnings <= kMaxWarningsShown) std::cerr << d.str() << "\n";
    if (warnings > kMaxWarningsShown)
        std::cerr << "whitted: " << warnings - kMaxWarningsShown << " more warnings not shown\n";
    if (loaded.cancelled) {
        std::cerr << "whitted: interrupted while loading the scene: nothing written\n";
        return kExitInterrupted;
    }
    if (!loaded.ok()) {
        if (!loaded.missing_textures.empty() && missing == "error")
            std::cerr << "whitted: use --texture-path DIR to add a place to look, or --missing-textures=checker to "
                         "render without them\n";
        return loaded.unreadable ? kExitIo : kExitScene;
    }

    RenderJob job;
    job.width = width;
    job.height = height;
    job.integrator = {mode, max_depth};
    job.sampling = {aa, spp, aa_threshold};
    job.threads = threads;
    job.cancel = &cli::interrupt_flag();
    cli::ProgressLine progress(job.tile_count(), !quiet && isatty(STDERR_FILENO));
    job.on_tile = [&](const Tile&) { progress.tile_done(); };

    const auto integrator = make_integrator(*loaded.scene, job.camera_for(*loaded.scene), job.integrator);
    Film film(width, height);
    RenderStats rs = render(*integrator, job, film);
    progress.finish();

    const std::string err = is_linear_output(output) ? write_linear_image(film.to_linear(), output)
                                                     : write_image(film.to_image(), output);
    if (!err.empty()) {
        std::cerr << "whitted: error: " << err << "\n";
        return kExitIo;
    }
    if (stats) {
        const auto& ls = loaded.stats;
        std::fprintf(stderr,
                     "objects %zu, lights %zu, textures %zu; %d samples per pixel\n"
                     "parse %.3fs, flatten %.3fs, textures %.3fs, build %.3fs, render %.3fs (%d threads)\n"
                     "rays: camera %llu, reflected %llu, refracted %llu, shadow %llu; %.2f Mrays/s\n"
                     "samples rejected (not finite, counted as black): %llu\n",
                     ls.objects, ls.lights, ls.textures, job.sampling.samples_per_pixel(), ls.parse_seconds,
                     ls.flatten_seconds, ls.texture_seconds, ls.build_seconds, rs.seconds, rs.threads,
                     (unsigned long long)rs.rays.camera, (unsigned long long)rs.rays.reflected,
                     (unsigned long long)rs.rays.refracted, (unsigned long long)rs.rays.shadow,
                     rs.seconds > 0 ? double(rs.rays.total()) / rs.seconds * 1e-6 : 0.0,
                     (unsigned long long)rs.rays.rejected);
    }
    if (rs.cancelled) {
        std::cerr << "whitted: interrupted: wrote the " << rs.tiles_done << " of " << rs.tiles_total
                  << " tiles rendered so far to " << output << "\n";
        return kExitInterrupted;
    }
    if (!quiet) std::cerr << "wrote " << output << "\n";
    return 0;
}

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << "whitted: error: out of memory (a smaller image or scene may fit)\n";
    } catch (const std::exception& e) {
        std::cerr << "whitted: error: " << e.what() << "\n";
    }
    return kExitIo;
}
