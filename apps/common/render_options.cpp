#include "render_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "cs1230/detect.h"
#include "film/image_io.h"
#include "base/read_file.h"
#include "session/run_limits.h"
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
        return std::isfinite(std::strtod(s.c_str(), nullptr)) ? std::string() : "not a finite number: " + s;
    },
    "FINITE");

const CLI::Validator memory_size(
    [](std::string& s) { return parse_memory_size(s) ? std::string() : "not a size such as 512M or 4G: " + s; },
    "SIZE");

}  // namespace

CLI::Option* add_setting_option(CLI::App& app, RenderSettings& settings, const Setting& setting) {
    const std::string flag = "--" + std::string(setting.name);
    return std::visit(
        [&](auto member) -> CLI::Option* {
            using T = std::remove_cvref_t<decltype(settings.*member)>;
            auto& value = settings.*member;
            if constexpr (std::is_same_v<T, bool>) {
                return app.add_flag(flag, value, setting.help);
            } else if constexpr (std::is_same_v<T, std::vector<std::string>>) {
                // One directory per option (repeat it for more): a list would swallow the scene after it.
                return app.add_option(flag, value, setting.help)->allow_extra_args(false)->default_str("");
            } else if constexpr (std::is_same_v<T, std::string>) {
                CLI::Option* o = app.add_option(flag, value, setting.help);
                if (!setting.choices.empty()) o->check(CLI::IsMember(std::vector<std::string>(setting.choices.begin(), setting.choices.end())));
                if (std::string(setting.name) == "max-memory") o->check(memory_size);
                return o;
            } else {
                CLI::Option* o = app.add_option(flag, value, setting.help)->check(CLI::Range(T(setting.min), T(setting.max)));
                if constexpr (std::is_floating_point_v<T>) o->check(finite_number);
                return o;
            }
        },
        setting.field);
}

void add_render_options(CLI::App& app, RenderOptions& o, Frontend) {
    app.option_defaults()->always_capture_default();
    app.add_option("scene", o.scene_path,
                   "Scene file (.sc); without one, renders the bundled showcase");
    app.add_option("-o,--output", o.output,
                   "Output image: .png (default), .bmp, .ppm, .jpg; .exr or .pfm keep linear, unclamped values");
    for (const Setting& setting : render_settings_table()) add_setting_option(app, o.settings, setting);
    app.add_flag("-q,--quiet", o.quiet, "No progress line");
    app.add_flag("--stats", o.stats, "Print timings and ray counts");
}

std::string collect_given(CLI::App& app, RenderSettings& settings, Frontend frontend, const char* program) {
    (void)program;
    for (const Setting& setting : render_settings_table()) {
        const CLI::Option* option = app.get_option_no_throw("--" + std::string(setting.name));
        if (!option || option->count() == 0) continue;
        if (setting.refused(frontend))
            return "--" + std::string(setting.name) + " is not for this program: " + setting.why_refused(frontend);
        settings.given.insert(setting.name);
    }
    return "";
}

std::string finish_render_options(CLI::App& app, RenderOptions& o, Frontend frontend) {
    if (std::string refused = collect_given(app, o.settings, frontend, ""); !refused.empty()) return refused;
    apply_mode_defaults(o.settings, !o.scene_path.empty() && cs1230::is_json_scene_file(o.scene_path));
    if (std::string problem = validate(o.settings); !problem.empty()) return problem;
    o.is_showcase = o.scene_path.empty();
    if (o.is_showcase) o.scene_path = bundled_showcase();
    if (o.output.empty()) o.output = default_output(o.scene_path, o.is_showcase);
    const RenderSettings& s = o.settings;
    // An unknown format or a size it cannot hold, before the render.
    if (std::string problem = output_problem(s.width, s.height, o.output); !problem.empty()) return problem;
    // (An image given as the scene, `whitted out.png`, is let through: its load says what it is.)
    if (same_file(o.output, o.scene_path) &&
        !binary_file_kind(read_regular_file(o.scene_path, ParseOptions{}.max_file_bytes).bytes))
        return "the output '" + o.output + "' is the scene file itself; name another with -o";
    const std::size_t limit = memory_limit(s);
    o.for_image = image_memory(s.width, s.height, o.output, make_render_job(s).sampling);
    if (o.for_image > limit)
        return "a " + std::to_string(s.width) + "x" + std::to_string(s.height) + " image needs about " +
               describe_bytes(o.for_image) + " of memory to render and write, more than the limit of " +
               describe_bytes(limit) + " (--max-memory)";
    return "";
}

int parse_render_options(CLI::App& app, RenderOptions& o, int argc, char** argv, const char* program,
                         Frontend frontend) {
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? -1 : kExitUsage;
    }
    if (std::string problem = finish_render_options(app, o, frontend); !problem.empty()) {
        std::cerr << program << ": error: " << problem << "\n";
        return kExitUsage;
    }
    return kExitOk;
}

LoadOptions load_options(const RenderOptions& o, const std::atomic<bool>* cancel) {
    LoadOptions lo = make_load_options(o.settings, o.for_image);
    lo.cancel = cancel;
    return lo;
}

RenderJob render_job(const RenderOptions& o, const std::atomic<bool>* cancel) {
    RenderJob job = make_render_job(o.settings);
    job.cancel = cancel;
    job.time_rays = o.stats;
    return job;
}

}  // namespace whitted::cli
