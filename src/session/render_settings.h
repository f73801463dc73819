#pragma once
// The render settings every front end takes, declared once: their names, what they mean, their
// ranges and choices, their defaults in each mode, which change the pixels, and where a front end
// refuses one. whitted and whitted-mpi bind the table to their command lines, whitted-view to its
// command line, tool bar and Render menu; one validation turns the user's choices into a load and
// a render.
#include <cstddef>
#include <optional>
#include <utility>
#include <set>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "render/load_scene.h"
#include "film/view_transform.h"
#include "render/render_job.h"

namespace whitted {

// The values. `given` names the settings the user chose (on a command line, in a window); every
// other one takes its default for the mode (apply_defaults), so choosing `path` anywhere gives a
// path tracer's samples and depth unless the user set them.
struct RenderSettings {
    int width = 640, height = 480;
    std::string mode = "whitted";
    int max_depth = 5;
    int aa = 1, spp = 1;
    float aa_threshold = 0.0f;
    float noise_threshold = 0.0f;
    int min_spp = 16;
    int seed = 0;
    std::string view = "linear";  // the mode's default unless given: srgb in path mode
    float time = 0.0f;
    std::string frames;  // "A..B": numbered images NAME.000A.EXT … (session/frame_sequence.h); "" = one image
    float fps = 24.0f;   // frame n is at scene time n / fps
    std::string shutter;  // "T0,T1": motion blur over [time + T0, time + T1]; "" = the instant (accel/motion_set.h)
    int threads = 0;
    bool lenient = false;
    std::string missing_textures = "error";
    std::vector<std::string> texture_dirs;
    bool untrusted = false;
    std::string max_memory;  // "512M", "4G"; "" = the default
    double timeout = 0.0;     // seconds; 0 = none
    double time_limit = 0.0;  // seconds; 0 = none
    std::string checkpoint;         // "" = none
    double checkpoint_every = 5.0;  // seconds between flushes of the checkpoint
    std::string resume;             // "" = none
    std::string cs1230_stage = "illuminate";  // which course project draws a CSCI 1230 file (§9.5)
    int photons = 1 << 16;       // path mode's caustic photons per sample (0 = none)
    float photon_radius = 0.0f;  // their first gather radius (0 = from the scene's size)
    std::string aov;       // per-term images to write beside the image (render/aov.h); "" = none
    std::string aov_file;  // where: an .exr for one multi-layer file, else NAME.LAYER.png beside it
    std::string texture_filter = "bilinear";  // texture/texture_filter.h

    std::set<std::string> given;
    bool is_given(std::string_view name) const { return given.count(std::string(name)) != 0; }
};

enum class Frontend : unsigned { Cli = 1, Viewer = 2, Mpi = 4 };

// One setting: `name` is the command-line option without its dashes and the key it is remembered
// under; `label` the viewer's word for it.
struct Setting {
    using Field = std::variant<int RenderSettings::*, float RenderSettings::*, double RenderSettings::*,
                               bool RenderSettings::*, std::string RenderSettings::*,
                               std::vector<std::string> RenderSettings::*>;
    const char* name;
    const char* label;
    const char* help;
    Field field;
    double min = 0, max = 0;            // numbers: the range (inclusive)
    std::vector<const char*> choices;   // text: the values it may take ({} = any)
    bool changes_pixels = false;        // part of what a checkpoint's pixels depend on
    // Front ends that refuse it, and why (a sentence for their error message).
    unsigned refused_by = 0;
    const char* refusal = "";         // whitted-mpi's reason
    const char* viewer_refusal = "";  // whitted-view's, where it differs
    bool refused(Frontend f) const { return (refused_by & unsigned(f)) != 0; }
    const char* why_refused(Frontend f) const {
        return f == Frontend::Viewer && *viewer_refusal ? viewer_refusal : refusal;
    }
};

const std::vector<Setting>& render_settings_table();
const Setting* find_setting(std::string_view name);

// The names of the render modes (the choices of `mode`).
const std::vector<const char*>& render_mode_names();

// Sets every setting the user did not give to its default for s.mode (path: 64 samples per pixel
// and 64 bounces, shown through the sRGB curve; every other mode: the lab model's 1 and 5, linear).
// A CSCI 1230 JSON scene (§9.5) is
// drawn at the course's 1024 x 768 and depth 4 (the path tracer's 64 bounces still win in path mode).
void apply_mode_defaults(RenderSettings& s, bool course_scene = false);

// Checks what a range cannot and fills what depends on other settings: returns "" or the message
// of a usage error. --aa-threshold with --spp > 1 becomes the noise threshold of adaptive sampling
// (pixel centres carry no penumbra or blur to compare; the error estimate does), unless
// --noise-threshold is given too.
std::string validate(RenderSettings& s);

// The setting's value as text, as a command line would give it ("" for an empty list).
std::string setting_text(const RenderSettings& s, const Setting& setting);

// "name=value" of every setting that changes the pixels, in table order: with the input files'
// bytes, what a checkpoint of the render is valid for.
std::string pixel_key(const RenderSettings& s);

// --shutter's "T0,T1" (two finite numbers, T0 <= T1), or nothing if it is not that.
std::optional<std::pair<float, float>> parse_shutter(const std::string& text);

// The render and the load the settings describe (the job without callbacks or cancel flag).
RenderJob make_render_job(const RenderSettings& s);
// The view transform of the 8-bit images (film/view_transform.h).
ViewTransform view_transform(const RenderSettings& s);
// The load's settings: limits of --untrusted, the memory left for the scene besides `image_bytes`.
LoadOptions make_load_options(const RenderSettings& s, std::size_t image_bytes = 0);
// The memory limit: --max-memory, else 1 GiB under --untrusted, else three quarters of the RAM.
std::size_t memory_limit(const RenderSettings& s);
// The time limit of a run: --timeout, else 60 s under --untrusted, else none (0).
double timeout_seconds(const RenderSettings& s);

}  // namespace whitted
