#include "session/render_settings.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cs1230/stage.h"
#include "integrator/render_mode.h"
#include "render/aov.h"
#include "session/frame_sequence.h"
#include "session/run_limits.h"

namespace whitted {
namespace {

using S = RenderSettings;
constexpr unsigned kMpi = unsigned(Frontend::Mpi), kViewer = unsigned(Frontend::Viewer);
// The viewer renders passes until the user stops it, over every pixel: no adaptive sampling or
// time budget yet (those run in whitted's session).
constexpr const char* kViewerRendersUntilStopped =
    "whitted-view renders passes over every pixel until you stop it (Esc); adaptive sampling and time limits "
    "are whitted's";

// A sequence of files is a batch job; the viewer shows one image at a scene time of its own.
constexpr const char* kViewerShowsOneFrame =
    "whitted-view shows one image (set its scene time with Ctrl+T); write a sequence with whitted --frames A..B";

// Motion blur is for images written; the viewer shows the scene at one instant.
constexpr const char* kViewerShowsOneInstant =
    "whitted-view shows the scene at one instant (Ctrl+T sets it); render motion blur with whitted --shutter T0,T1";

constexpr const char* kViewerKeepsNoCheckpoint =
    "whitted-view renders passes until you stop it and keeps no checkpoint; a long render to a file is "
    "whitted's (whitted SCENE -o OUT --checkpoint FILE, then --resume FILE)";

// --frames and what does not go with it: each frame's time comes from its number, and a frame is
// one whole render to its own file (continued by skipping the files written, not by a checkpoint).
std::string frames_problem(const RenderSettings& s) {
    if (s.frames.empty()) {
        if (s.is_given("fps")) return "--fps is the frame rate of --frames A..B: give --frames too";
        return "";
    }
    if (!parse_frame_range(s.frames))
        return "--frames " + s.frames + " is not a range of frame numbers A..B (0 <= A <= B <= " +
               std::to_string(kMaxFrame) + ")";
    if (s.is_given("time")) return "--time and --frames: each frame's time is its number / --fps";
    if (!s.checkpoint.empty() || !s.resume.empty())
        return "--frames keeps no checkpoint: an interrupted sequence goes on by skipping the frames already "
               "written (run the same command again)";
    if (!s.aov.empty()) return "--aov with --frames is not supported yet: render the layers of one frame with --time";
    if (s.time_limit > 0) return "--time-limit is a budget for one image, not for --frames: use --timeout";
    return "";
}

}  // namespace

const std::vector<const char*>& render_mode_names() {
    static const std::vector<const char*> names{"whitted", "path", "raycast", "normals", "depth"};
    return names;
}

const std::vector<Setting>& render_settings_table() {
    static const std::vector<Setting> table{
        {"width", "Width", "Image width in pixels", &S::width, 1, 32768, {}, true},
        {"height", "Height", "Image height in pixels", &S::height, 1, 32768, {}, true},
        {"mode", "Mode",
         "Render mode: whitted (the lab's model), path (physically based path tracing), raycast, normals, depth",
         &S::mode, 0, 0, render_mode_names(), true},
        {"max-depth", "Depth",
         "Recursion limit for reflection/refraction (camera ray = 0); in path mode the bounces of a path (default 64 "
         "there)",
         &S::max_depth, 0, 1000, {}, true},
        {"aa", "AA", "Anti-aliasing: N x N rays per pixel, averaged (1 = one ray through the centre)", &S::aa, 1,
         Sampler::kMaxAa, {}, true},
        {"spp", "SPP",
         "Samples per pixel (per sub-pixel with --aa N: N x N x spp in all) for soft shadows, depth of field, gloss "
         "and path tracing; they arrive in passes (1 = the pixel, lens and light centres; default 64 in path mode)",
         &S::spp, 1, Sampler::kMaxSpp, {}, true},
        {"aa-threshold", "AA threshold",
         "Adaptive anti-aliasing: supersample only pixels whose colour differs from a neighbour's by more than this "
         "(0-1, per channel; 0 = every pixel); with --spp > 1 it is the noise threshold",
         &S::aa_threshold, 0, 1, {}, true},
        {"noise-threshold", "Noise threshold",
         "Adaptive sampling: a pixel takes no more samples once its error estimate is below this (e.g. 0.01; 0 = "
         "off); needs --spp > 1",
         &S::noise_threshold, 0, 1, {}, true, kViewer, "", kViewerRendersUntilStopped},
        {"min-spp", "Min SPP", "Adaptive sampling: the samples every pixel takes before it may stop", &S::min_spp, 1,
         Sampler::kMaxSpp, {}, true, kViewer, "", kViewerRendersUntilStopped},
        {"seed", "Seed",
         "Another seed gives other, equally good sample values: an independent render of the same scene (a "
         "reference to measure noise against, or renders to average); 0 = the default",
         &S::seed, 0, 2147483647, {}, true},
        {"view", "View transform",
         "How linear values become 8-bit pixels (PNG, JPEG, BMP, PPM and the viewer; .exr and .pfm keep the "
         "linear values): linear (clamped, as the lab's model and the course's images; the default except in "
         "path mode), srgb (the sRGB curve: how pbrt, Mitsuba and Cycles show radiance; the default in path "
         "mode), filmic (the ACES filmic fit, then sRGB: highlights roll off instead of clipping)",
         &S::view, 0, 0, {"linear", "srgb", "filmic"}, false},
        {"time", "Scene time",
         "Scene time t: 'velocity x y z' moves by t·(x, y, z), 'angularrate ax ay az r' turns by r·t degrees (0 = "
         "the still image)",
         &S::time, -1e30, 1e30, {}, true},
        // Each frame's pixels depend on its time, which the checkpoint does not keep: a sequence
        // takes no checkpoint (validate), and frames already written are skipped instead.
        {"frames", "Frames",
         "Render the frames A..B of the animation (velocity, angularrate) as numbered images NAME.000A.EXT … "
         "NAME.000B.EXT beside the output, frame n at scene time n / --fps; the scene is read once; a frame whose "
         "file exists is skipped (so an interrupted sequence goes on where it stopped)",
         &S::frames, 0, 0, {}, false, kViewer, "", kViewerShowsOneFrame},
        {"fps", "Frames per second", "With --frames: frames per unit of scene time (frame n is at time n / fps)",
         &S::fps, 1e-6, 1e6, {}, false, kViewer, "", kViewerShowsOneFrame},
        {"shutter", "Shutter",
         "Motion blur: T0,T1 is the interval the shutter is open, relative to the image's scene time (--time, or "
         "each frame's with --frames); each sample takes its own time in it and moving objects (velocity, "
         "angularrate) are met where they are then. Default: the instant itself. Give --spp or "
         "--aa for samples (one sample per pixel is taken mid-shutter)",
         &S::shutter, 0, 0, {}, true, kViewer, "", kViewerShowsOneInstant},
        {"threads", "Threads", "Worker threads (0 = all hardware threads)", &S::threads, 0, 1024, {}, false},
        {"lenient", "Lenient", "Skip unknown keywords and object types with a warning instead of failing",
         &S::lenient, 0, 0, {}, true},
        {"missing-textures", "Missing textures",
         "A texture that cannot be loaded: error (the viewer asks for the file), checker (a checkerboard), ask (the "
         "same as error)",
         &S::missing_textures, 0, 0, {"error", "checker", "ask"}, true},
        {"texture-path", "Texture folders", "Extra directory to look for textures in (repeat for more)",
         &S::texture_dirs, 0, 0, {}, true},
        {"untrusted", "Untrusted",
         "For scene files you did not write: textures only from the scene's folder and --texture-path, and lower "
         "limits on file sizes, objects, textures, memory (1G) and time (60 s) (see the README)",
         &S::untrusted, 0, 0, {}, false},
        {"max-memory", "Memory limit",
         "Memory the image and scene may need, estimated before anything is built: a size such as 512M or 4G "
         "(default: three quarters of this machine's RAM)",
         &S::max_memory, 0, 0, {}, false},
        {"timeout", "Timeout",
         "Stop after this many seconds (load and render), keeping the last whole pass (or the tiles of the first) as "
         "NAME.partial.EXT, exit 4; 0 = never",
         &S::timeout, 0, 1e7, {}, false, kViewer, "", kViewerRendersUntilStopped},
        {"time-limit", "Time limit",
         "Render whole passes while they fit in this many seconds (load and write included), then write the complete "
         "image at the samples reached, exit 0; 0 = none",
         &S::time_limit, 0, 1e7, {}, false, kViewer, "", kViewerRendersUntilStopped},
        {"photons", "Photons",
         "Path mode: photons per sample for caustics, the light of point, spot and directional lights through "
         "glass and off mirrors (0 = none; used only in scenes with such lights and an ideal mirror or glass)",
         &S::photons, 0, 1 << 24, {}, true},
        {"photon-radius", "Photon radius",
         "Path mode: the caustic photons' gather radius at the first sample, in scene units, shrinking as samples "
         "add up (0 = the scene's bounding diagonal / 500)",
         &S::photon_radius, 0, 1e30, {}, true},
        // whitted-view renders passes until it is stopped and is started again in a moment: it
        // keeps no checkpoint.
        {"checkpoint", "Checkpoint",
         "Keep the render so far in FILE (each tile as it is finished, each whole pass; flushed every "
         "--checkpoint-every seconds) so that --resume FILE goes on after a crash, a reboot or a batch limit",
         &S::checkpoint, 0, 0, {}, false, kViewer, "", kViewerKeepsNoCheckpoint},
        {"checkpoint-every", "Checkpoint every", "Seconds between flushes of the --checkpoint file to the disk",
         &S::checkpoint_every, 0, 86400, {}, false, kViewer, "", kViewerKeepsNoCheckpoint},
        {"resume", "Resume",
         "Go on from a --checkpoint FILE of the same job (scene, input files and every setting that changes "
         "pixels): the image is the one an uninterrupted render writes",
         &S::resume, 0, 0, {}, false, kViewer, "", kViewerKeepsNoCheckpoint},
        {"cs1230-stage", "CS1230 stage",
         "For Brown CSCI 1230 JSON scenes: draw them as the course's Intersect project (directional lights, no "
         "shadows, reflections or textures) or Illuminate (everything)",
         &S::cs1230_stage, 0, 0, {"illuminate", "intersect"}, true},
        {"aov", "Per-term images",
         "Also write these layers of the render (comma-separated): whitted mode ambient, diffuse, specular, reflect, "
         "transmit, emit, background (they add up to the image before clamping), diffuse.Lk, specular.Lk, shadow.Lk "
         "(light k), normal, depth, albedo, object, samples; path mode direct, indirect, albedo, normal, depth, "
         "object, samples; 'all' for every one. Into the .exr output, else NAME.LAYER.png (see --aov-file)",
         &S::aov, 0, 0, {}, false, kMpi | kViewer,
         "whitted-mpi does not gather per-term images from its ranks yet; render them with whitted",
         "whitted-view shows the image only; write per-term images with whitted --aov"},
        {"aov-file", "Per-term image file",
         "Where --aov's layers go: FILE.exr for one multi-layer OpenEXR file (the image and its layers), any other "
         "name for one PNG per layer beside it (FILE.LAYER.png); default: the output",
         &S::aov_file, 0, 0, {}, false, kMpi | kViewer,
         "whitted-mpi does not gather per-term images from its ranks yet; render them with whitted",
         "whitted-view shows the image only; write per-term images with whitted --aov"},
        {"texture-filter", "Texture filter",
         "How textures are read: bilinear (the lab's rule, the default), nearest (the texel under the point: the "
         "Brown/Tufts renderer's blocky look), trilinear or ewa (over what a pixel covers, from mip-maps and ray "
         "differentials: no shimmer on floors receding to the horizon at one sample per pixel; see docs/textures.md)",
         &S::texture_filter, 0, 0, {"nearest", "bilinear", "trilinear", "ewa"}, true},
    };
    return table;
}

const Setting* find_setting(std::string_view name) {
    for (const Setting& s : render_settings_table())
        if (name == s.name) return &s;
    return nullptr;
}

void apply_mode_defaults(RenderSettings& s, bool course_scene) {
    const bool path = s.mode == "path";  // §9.2: a path tracer's defaults
    if (!s.is_given("spp")) s.spp = path ? 64 : 1;
    if (!s.is_given("max-depth")) s.max_depth = path ? 64 : course_scene ? 4 : 5;
    if (!s.is_given("width")) s.width = course_scene ? 1024 : 640;
    if (!s.is_given("height")) s.height = course_scene ? 768 : 480;
    if (!s.is_given("view")) s.view = path ? "srgb" : "linear";
}

std::string validate(RenderSettings& s) {
    if (!parse_render_mode(s.mode)) return "unknown render mode '" + s.mode + "'";
    for (const Setting& setting : render_settings_table()) {
        const bool ok = std::visit(
            [&](auto member) {
                using T = std::remove_cvref_t<decltype(s.*member)>;
                if constexpr (std::is_same_v<T, int> || std::is_same_v<T, float> || std::is_same_v<T, double>)
                    return std::isfinite(double(s.*member)) && double(s.*member) >= setting.min &&
                           double(s.*member) <= setting.max;
                else if constexpr (std::is_same_v<T, std::string>)
                    return setting.choices.empty() ||
                           std::any_of(setting.choices.begin(), setting.choices.end(),
                                       [&](const char* c) { return s.*member == c; });
                else
                    return true;
            },
            setting.field);
        if (!ok) return "--" + std::string(setting.name) + " " + setting_text(s, setting) + " is out of its range";
    }
    if (!s.max_memory.empty() && !parse_memory_size(s.max_memory))
        return "--max-memory " + s.max_memory + " is not a size such as 512M or 4G";
    if (s.aa_threshold > 0.0f && s.spp > 1) {
        // Pixel centres carry no penumbra or blur: with samples, the threshold is the noise threshold.
        if (s.noise_threshold == 0.0f) s.noise_threshold = s.aa_threshold;
        s.aa_threshold = 0.0f;
    }
    if (s.noise_threshold > 0.0f && s.spp * s.aa * s.aa < 2)
        return "--noise-threshold stops pixels between passes of samples: give --spp 2 or more (--spp 64, say)";
    if (s.noise_threshold > 0.0f && !(s.checkpoint.empty() && s.resume.empty()))
        return "--checkpoint and --resume do not keep adaptive sampling's state (which pixels have stopped, and "
               "when): render without " +
               std::string(s.is_given("noise-threshold") ? "--noise-threshold" : "--aa-threshold (with --spp > 1, the "
                                                                                  "noise threshold)") +
               ", or without a checkpoint";
    if (s.texture_filter != "bilinear" && s.mode != "whitted")
        return "--texture-filter " + s.texture_filter +
               " is for whitted mode: path mode's many samples per pixel already average a texture over each "
               "pixel (a filter on top would only blur it), and the debug views show the texture as it is";
    if (std::string problem = frames_problem(s); !problem.empty()) return problem;
    if (!s.shutter.empty()) {
        if (!parse_shutter(s.shutter))
            return "--shutter " + s.shutter + " is not an interval T0,T1 of scene time (two numbers, T0 <= T1)";
    }
    if (!s.aov_file.empty() && s.aov.empty()) return "--aov-file names where --aov's layers go: give --aov too";
    if (!s.aov.empty()) {
        const std::vector<std::string> names = split_aov_list(s.aov);
        if (names.empty()) return "--aov needs the names of layers (diffuse,specular,depth,... or all)";
        if (std::string problem = check_aov_names(names, *parse_render_mode(s.mode)); !problem.empty())
            return "--aov: " + problem;
        if (s.aa_threshold > 0.0f && s.aa > 1 && s.spp == 1)
            return "--aov with adaptive anti-aliasing (--aa-threshold) is not supported yet: use --aa N alone, or "
                   "--spp with --noise-threshold";
    }
    if (!s.aov.empty() && !s.resume.empty())
        return "--resume does not keep --aov's layers (the checkpoint holds the image's samples only): render "
               "the layers without a checkpoint";
    if (s.untrusted && (s.width > UntrustedLimits::kImageSide || s.height > UntrustedLimits::kImageSide))
        return "--untrusted renders images of at most " + std::to_string(UntrustedLimits::kImageSide) + "x" +
               std::to_string(UntrustedLimits::kImageSide) + " pixels (" + std::to_string(s.width) + "x" +
               std::to_string(s.height) + " asked for)";
    return "";
}

std::string setting_text(const RenderSettings& s, const Setting& setting) {
    return std::visit(
        [&](auto member) {
            std::ostringstream out;
            using T = std::remove_cvref_t<decltype(s.*member)>;
            if constexpr (std::is_same_v<T, std::vector<std::string>>) {
                for (std::size_t i = 0; i < (s.*member).size(); ++i) out << (i ? "," : "") << (s.*member)[i];
            } else if constexpr (std::is_same_v<T, float> || std::is_same_v<T, double>) {
                out.precision(std::is_same_v<T, float> ? 9 : 17);  // every value reads back as itself
                out << s.*member;
            } else {
                out << s.*member;
            }
            return out.str();
        },
        setting.field);
}

std::string pixel_key(const RenderSettings& s) {
    std::string key;
    for (const Setting& setting : render_settings_table())
        if (setting.changes_pixels) key += std::string(setting.name) + "=" + setting_text(s, setting) + ";";
    return key;
}

std::optional<std::pair<float, float>> parse_shutter(const std::string& text) {
    const std::size_t comma = text.find(',');
    if (comma == std::string::npos) return std::nullopt;
    auto number = [](const std::string& t) -> std::optional<float> {
        std::istringstream in(t);
        float v;
        if (!(in >> v) || !std::isfinite(v)) return std::nullopt;
        in >> std::ws;
        if (!in.eof()) return std::nullopt;
        return v;
    };
    const auto t0 = number(text.substr(0, comma)), t1 = number(text.substr(comma + 1));
    if (!t0 || !t1 || !(*t0 <= *t1)) return std::nullopt;
    return std::pair{*t0, *t1};
}

RenderJob make_render_job(const RenderSettings& s) {
    RenderJob job;
    job.width = s.width;
    job.height = s.height;
    job.integrator.mode = *parse_render_mode(s.mode);
    job.integrator.max_depth = s.max_depth;
    job.integrator.cs1230_stage = cs1230::parse_stage(s.cs1230_stage).value_or(cs1230::Stage::Illuminate);
    job.integrator.photons = s.photons;
    job.integrator.photon_radius = s.photon_radius;
    job.sampling.aa = s.aa;
    job.sampling.spp = s.spp;
    job.sampling.aa_threshold = s.aa_threshold;
    job.sampling.noise_threshold = s.noise_threshold;
    job.sampling.min_spp = s.min_spp;
    job.sampling.seed = std::uint32_t(s.seed);
    job.threads = s.threads;
    job.aovs = split_aov_list(s.aov);
    job.integrator.texture_filter = parse_texture_filter(s.texture_filter).value_or(TextureFilter::Bilinear);
    // Samples closer than a pixel see a smaller footprint (as pbrt-v4 scales its differentials).
    job.integrator.texture_sample_rows =
        float(s.height) * std::min(8.0f, float(s.aa) * std::sqrt(float(s.spp)));
    return job;
}

ViewTransform view_transform(const RenderSettings& s) {
    return parse_view_transform(s.view).value_or(ViewTransform::Linear);
}

std::size_t memory_limit(const RenderSettings& s) {
    if (!s.max_memory.empty())
        if (const auto bytes = parse_memory_size(s.max_memory)) return *bytes;
    return s.untrusted ? UntrustedLimits::kMemory : default_max_memory();
}

double timeout_seconds(const RenderSettings& s) {
    if (s.is_given("timeout") || !s.untrusted) return s.timeout;
    return UntrustedLimits::kSeconds;
}

LoadOptions make_load_options(const RenderSettings& s, std::size_t image_bytes) {
    LoadOptions lo;
    lo.lenient = s.lenient;
    lo.threads = s.threads;  // --threads 1 means one thread for the build too
    lo.time = s.time;
    if (const auto shutter = parse_shutter(s.shutter)) {
        lo.shutter = true;
        lo.shutter_open = shutter->first;
        lo.shutter_close = shutter->second;
    }
    lo.cs1230_stage = cs1230::parse_stage(s.cs1230_stage).value_or(cs1230::Stage::Illuminate);
    lo.textures.search_dirs = s.texture_dirs;
    lo.textures.missing = s.missing_textures == "checker" ? MissingTexturePolicy::Checker : MissingTexturePolicy::Error;
    const std::size_t limit = memory_limit(s);
    lo.max_memory = limit - std::min(limit, image_bytes);
    lo.textures.limits.mip_levels = uses_footprint(parse_texture_filter(s.texture_filter).value_or(TextureFilter::Bilinear));
    if (s.untrusted) apply_untrusted(lo);
    return lo;
}

}  // namespace whitted
