#include "explain_command.h"

#include <filesystem>
#include <iostream>
#include <new>
#include <string>

#include <CLI/CLI.hpp>

#include "compare/colour_map.h"
#include "compare/compare_image.h"
#include "compare/explain.h"
#include "compare/explain_report.h"
#include "film/image_io.h"
#include "interrupt.h"
#include "load_report.h"
#include "render_options.h"

namespace whitted::cli {
namespace {

constexpr const char* kProgram = "whitted explain";

// IMAGE's error image beside it: shot.png → shot.explain.png.
std::string default_diff_path(const std::string& image) {
    std::filesystem::path p(image);
    return (p.parent_path() / (p.stem().string() + ".explain.png")).string();
}

int run(int argc, char** argv) {
    CLI::App app{"whitted explain: why IMAGE differs from whitted's render of SCENE. Renders the reference at the "
                 "image's size (with the render settings given, as whitted takes them), compares them as `whitted "
                 "compare` does, then renders the lab's classic mistakes (field of view, pixel corners, normals, "
                 "Blinn-Phong, shadows, depth, refraction, texture v, acne, gamma) and names those the image matches, "
                 "fits the difference as a sum of the reference's terms (specular, diffuse, ambient, reflection, "
                 "transmission, each light's shadows) and shows the worst regions with the inspector's account of "
                 "their centre pixels. docs/compare.md has a worked example.",
                 "whitted explain"};
    app.footer("Exit codes (as whitted compare): 0 no difference, 1 WARNING, 2 FAILURE (the image differs), 3 the "
               "image is not the --width/--height given, 4 the image cannot be read or the error image written, 5 bad "
               "usage, 6 bad scene; 130 interrupted.");
    RenderOptions o;
    std::string image_path, diff_path;
    ExplainOptions eo;
    bool json = false, quiet = false, no_diff = false;
    app.option_defaults()->always_capture_default();
    app.add_option("scene", o.scene_path, "The scene file the image was rendered from")->required();
    app.add_option("image", image_path, "The image to explain (PNG, JPEG, BMP, TGA, PPM, OpenEXR or PFM)")->required();
    for (const Setting& setting : render_settings_table()) add_setting_option(app, o.settings, setting);
    auto non_negative = CLI::NonNegativeNumber;
    app.add_option("--fail", eo.compare.thresholds.fail, "A pixel fails if a channel differs by more than this")
        ->check(non_negative);
    app.add_option("--failpercent", eo.compare.thresholds.fail_percent,
                   "FAILURE if more than this percentage of the pixels fail")
        ->check(non_negative);
    app.add_option("--warn", eo.compare.thresholds.warn, "A pixel warns if a channel differs by more than this")
        ->check(non_negative);
    app.add_option("--warnpercent", eo.compare.thresholds.warn_percent,
                   "WARNING if more than this percentage of the pixels warn")
        ->check(non_negative);
    app.add_option("--diff", diff_path,
                   "Write the FLIP error image (magma colours) to FILE (default: IMAGE's name with .explain.png)")
        ->type_name("FILE");
    app.add_flag("--no-diff", no_diff, "Write no error image");
    app.add_flag("--json", json, "Print one JSON object instead of the words");
    app.add_flag("-q,--quiet", quiet, "Print nothing but errors: the exit code says it");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? kExplainSame : kExplainUsage;
    }
    if (no_diff && !diff_path.empty()) {
        std::cerr << kProgram << ": error: --diff and --no-diff together\n";
        return kExplainUsage;
    }

    CompareImage image;
    if (std::string problem = read_compare_image(image_path, image); !problem.empty()) {
        std::cerr << kProgram << ": error: " << problem << "\n";
        return kExplainFile;
    }
    // The reference is rendered at the image's size unless a size is given, which it must then have.
    const bool sized = app.get_option("--width")->count() > 0 || app.get_option("--height")->count() > 0;
    if (sized && (o.settings.width != image.pixels.width || o.settings.height != image.pixels.height)) {
        std::cerr << kProgram << ": error: " << image_path << " is " << image.pixels.width << "x"
                  << image.pixels.height << ", not the " << o.settings.width << "x" << o.settings.height
                  << " asked for\n";
        return kExplainSize;
    }
    o.settings.width = image.pixels.width;
    o.settings.height = image.pixels.height;
    o.settings.given.insert("width");  // as if given: the mode's default size must not replace it
    o.settings.given.insert("height");
    if (!no_diff && diff_path.empty()) diff_path = default_diff_path(image_path);
    o.output = no_diff ? default_diff_path(image_path) : diff_path;  // checked as the renderer checks -o
    if (std::string problem = finish_render_options(app, o, Frontend::Cli); !problem.empty()) {
        std::cerr << kProgram << ": error: " << problem << "\n";
        return kExplainUsage;
    }
    if (!no_diff) {
        std::error_code ec;
        if (std::filesystem::equivalent(diff_path, image_path, ec) && !ec) {
            std::cerr << kProgram << ": error: --diff " << diff_path << " would replace the image being explained\n";
            return kExplainUsage;
        }
        if (std::string problem = output_unwritable(diff_path); !problem.empty()) {
            std::cerr << kProgram << ": error: " << problem << "\n";
            return kExplainFile;
        }
    }

    install_interrupt_handler();
    LoadResult loaded = load_scene(o.scene_path, load_options(o, &interrupt_flag()));
    if (int code = report_load(loaded, o, kProgram); code != kExitOk)
        return code == kExitScene ? kExplainScene : code == kExitIo ? kExplainFile : code;
    RenderJob job = render_job(o, nullptr);
    eo.quantize = !image.linear;  // an 8-bit file against the reference's 8-bit values
    eo.cancel = &interrupt_flag();
    const Explanation e = explain_image(*loaded.scene, job, image.pixels, eo);
    if (interrupt_flag().load()) {
        std::cerr << kProgram << ": interrupted\n";
        return kExitInterrupted;
    }
    if (!no_diff && e.differs()) {
        if (std::string problem =
                write_image(magma_image(e.compare.flip.error, e.compare.width, e.compare.height), diff_path);
            !problem.empty()) {
            std::cerr << kProgram << ": error: " << problem << "\n";
            return kExplainFile;
        }
    }
    const ExplainInputs inputs{o.scene_path, image_path, image.format, e.differs() && !no_diff ? diff_path : "",
                               std::filesystem::path(o.scene_path).parent_path().string()};
    if (!quiet) std::cout << (json ? explain_json(inputs, eo, e) : explain_text(inputs, eo, e)) << std::flush;
    return int(e.compare.verdict);
}

}  // namespace

int explain_main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::bad_alloc&) {
        std::cerr << kProgram << ": error: out of memory\n";
    } catch (const std::exception& e) {
        std::cerr << kProgram << ": error: " << e.what() << "\n";
    }
    return kExplainFile;
}

}  // namespace whitted::cli
