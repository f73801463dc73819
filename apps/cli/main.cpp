// whitted: the command-line renderer. Scene file in, image file out.
// Exit codes: 0 success, 1 bad usage, 2 bad scene, 3 I/O failure (the scene cannot be read, the
// image cannot be written, out of memory), 4 --timeout ran out, 130 interrupted.
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <optional>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "film/image_io.h"
#include "interrupt.h"
#include "limits.h"
#include "parse/read_file.h"
#include "progress.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace {

constexpr int kExitUsage = 1, kExitScene = 2, kExitIo = 3, kExitTimeout = 4, kExitInterrupted = 130;

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

const CLI::Validator memory_size(
    [](std::string& s) { return whitted::cli::parse_memory_size(s) ? std::string() : "not a size such as 512M or 4G: " + s; },
    "SIZE");

// Warnings printed before the rest are only counted: a file with 100,000 stray brackets
// should not bury its one real message.
constexpr int kMaxWarningsShown = 50;

int run(int argc, char** argv) {
    using namespace whitted;
    CLI::App app{"whitted: a Whitted-style ray tracer for SceneView/Ray .sc scene files"};
    app.set_version_flag("--version", "whitted 0.1.0");
    app.option_defaults()->always_capture_default();
    app.footer("Exit codes: 0 done, 1 bad usage, 2 bad scene (FILE:LINE:COL: error: ...), 3 I/O failure, "
               "4 --timeout ran out, 130 interrupted (the part rendered so far is written to NAME.partial.EXT).");
    std::string scene_path, output, mode_name = "whitted", missing = "error";
    int width = 640, height = 480, max_depth = 5, aa = 1, threads = 0;
    float aa_threshold = 0.0f;
    bool lenient = false, quiet = false, stats = false;
    std::vector<std::string> texture_dirs;
    app.add_option("scene", scene_path, "Scene file (.sc); without one, renders the bundled showcase");
    app.add_option("-o,--output", output, "Output image: .png (default), .bmp, .ppm, .jpg");
    app.add_option("--width", width, "Image width in pixels")->check(CLI::Range(1, 32768));
    app.add_option("--height", height, "Image height in pixels")->check(CLI::Range(1, 32768));
    app.add_option("--max-depth", max_depth, "Recursion limit for reflection/refraction (camera ray = 0)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--aa", aa, "Anti-aliasing: N x N rays per pixel, averaged (1 = one ray through the centre)")
        ->check(CLI::Range(1, kMaxAa));
    app.add_option("--aa-threshold", aa_threshold,
                   "Adaptive anti-aliasing: supersample only pixels whose colour differs from a neighbour's by more "
                   "than this (0-1, per channel); 0 = every pixel")
        ->check(CLI::Range(0.0f, 1.0f))
        ->check(finite_number);
    app.add_option("--mode", mode_name, "Render mode")->check(CLI::IsMember({"whitted", "raycast", "normals", "depth"}));
    app.add_option("--threads", threads, "Worker threads (0 = all hardware threads)")->check(CLI::Range(0, 1024));
    // One directory per --texture-path (repeat it for more): a list would swallow the scene after it.
    app.add_option("--texture-path", texture_dirs, "Extra directory to look for textures in (repeat for more)")
        ->allow_extra_args(false)
        ->default_str("");
    app.add_option("--missing-textures", missing, "What to do with a texture that cannot be loaded")
        ->check(CLI::IsMember({"error", "checker"}));
    std::string max_memory_text;
    app.add_option("--max-memory", max_memory_text,
                   "Memory the image and scene may need, estimated before anything is built: a size such as 512M "
                   "or 4G (default: three quarters of this machine's RAM)")
        ->check(memory_size);
    double timeout = 0;
    app.add_option("--timeout", timeout,
                   "Stop after this many seconds (load and render), keeping the part rendered as NAME.partial.EXT; "
                   "0 = never")
        ->check(CLI::Range(0.0, 1e7))
        ->check(finite_number);
    bool untrusted = false;
    app.add_flag("--untrusted", untrusted,
                 "For scene files you did not write: textures only from the scene's folder and --texture-path, and "
                 "lower limits on file sizes, objects, textures, memory (1G) and time (60 s) (see the README)");
    app.add_flag("--lenient", lenient, "Skip unknown keywords and object types with a warning instead of failing");
    app.add_flag("-q,--quiet", quiet, "No progress line");
    app.add_flag("--stats", stats, "Print timings and ray counts");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : kExitUsage;
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
    // A missing folder or a read-only one is found now, not after a long render (as POV-Ray does).
    if (std::string problem = output_unwritable(output); !problem.empty()) {
        std::cerr << "whitted: error: " << problem << "\n";
        return kExitIo;
    }

    using Untrusted = cli::UntrustedLimits;
    if (untrusted && (width > Untrusted::kImageSide || height > Untrusted::kImageSide)) {
        std::cerr << "whitted: error: --untrusted renders images of at most " << Untrusted::kImageSide << "x"
                  << Untrusted::kImageSide << " pixels (" << width << "x" << height << " asked for)\n";
        return kExitUsage;
    }
    if (untrusted && app.count("--timeout") == 0) timeout = Untrusted::kSeconds;
    const std::size_t max_memory = !max_memory_text.empty() ? *cli::parse_memory_size(max_memory_text)
                                   : untrusted                ? Untrusted::kMemory
                                                              : default_max_memory();
    const std::size_t for_image = cli::image_memory(width, height, output);
    if (for_image > max_memory) {
        std::cerr << "whitted: error: a " << width << "x" << height << " image needs about " << describe_bytes(for_image)
                  << " of memory to render and write, more than the limit of " << describe_bytes(max_memory)
                  << " (--max-memory)\n";
        return kExitUsage;
    }

    cli::install_interrupt_handler();  // from here on Ctrl-C stops the load or the render
    const cli::Deadline deadline(timeout);
    LoadOptions load_options;
    load_options.cancel = &cli::interrupt_flag();
    load_options.lenient = lenient;
    load_options.max_memory = max_memory - for_image;
    load_options.threads = threads;  // --threads 1 means one thread for the build too
    load_options.textures.search_dirs = texture_dirs;
    load_options.textures.missing = missing == "checker" ? MissingTexturePolicy::Checker : MissingTexturePolicy::Error;
    if (untrusted) cli::apply_untrusted(load_options);
    LoadResult loaded = load_scene(scene_path, load_options);
    int warnings = 0;
    for (const Diagnostic& d : loaded.diagnostics)
        if (d.severity == Severity::Error || ++warnings <= kMaxWarningsShown) std::cerr << d.str() << "\n";
    if (warnings > kMaxWarningsShown)
        std::cerr << "whitted: " << warnings - kMaxWarningsShown << " more warnings not shown\n";
    if (loaded.cancelled) {
        if (deadline.timed_out()) {
            std::cerr << "whitted: error: the time limit of " << timeout << " s (--timeout) ran out while loading the "
                      << "scene: nothing written\n";
            return kExitTimeout;
        }
        std::cerr << "whitted: interrupted while loading the scene: nothing written\n";
        return kExitInterrupted;
    }
    if (!loaded.ok()) {
        if (!loaded.missing_textures.empty() && missing == "error")
            std::cerr << "whitted: use --texture-path DIR to add a place to look, or --missing-textures=checker to "
                         "render without them\n";
        return loaded.unreadable ? kExitIo : kExitScene;
    }

    RenderOptions options;
    options.width = width;
    options.height = height;
    options.max_depth = max_depth;
    options.aa = aa;
    options.aa_threshold = aa_threshold;
    options.mode = *parse_render_mode(mode_name);
    options.threads = threads;
    options.cancel = &cli::interrupt_flag();
    const int ts = options.tile_size;
    cli::ProgressLine progress(((width + ts - 1) / ts) * ((height + ts - 1) / ts), !quiet && isatty(STDERR_FILENO));
    options.on_tile = [&](const Tile&) { progress.tile_done(); };

    Image image(width, height);
    RenderStats rs = render(*loaded.scene, options, image);
    progress.finish();

    // An interrupted render never replaces the output: a good image from an earlier run may be
    // there (a batch timeout's SIGTERM must not destroy it). Its part goes beside it.
    const std::string written = rs.cancelled ? partial_image_path(output) : output;
    if (std::string err = write_image(image, written); !err.empty()) {
        std::cerr << "whitted: error: " << err << "\n";
        return kExitIo;
    }
    if (stats) {
        const auto& ls = loaded.stats;
        std::fprintf(stderr,
                     "objects %zu, lights %zu, textures %zu\n"
                     "parse %.3fs, flatten %.3fs, textures %.3fs, build %.3fs, render %.3fs (%d threads)\n"
                     "rays: camera %llu, reflected %llu, refracted %llu, shadow %llu; %.2f Mrays/s\n",
                     ls.objects, ls.lights, ls.textures, ls.parse_seconds, ls.flatten_seconds, ls.texture_seconds,
                     ls.build_seconds, rs.seconds, rs.threads,
                     (unsigned long long)rs.rays.camera, (unsigned long long)rs.rays.reflected,
                     (unsigned long long)rs.rays.refracted, (unsigned long long)rs.rays.shadow,
                     rs.seconds > 0 ? double(rs.rays.total()) / rs.seconds * 1e-6 : 0.0);
    }
    if (rs.cancelled && deadline.timed_out()) {
        std::cerr << "whitted: error: the time limit of " << timeout << " s (--timeout) ran out: wrote the "
                  << rs.tiles_done << " of " << rs.tiles_total << " tiles rendered so far to " << written << " ("
                  << output << " was not written)\n";
        return kExitTimeout;
    }
    if (rs.cancelled) {
        std::cerr << "whitted: interrupted: wrote the " << rs.tiles_done << " of " << rs.tiles_total
                  << " tiles rendered so far to " << written << " (" << output << " was not written)\n";
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
