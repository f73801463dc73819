// whitted-view: the FLTK window a student or teacher keeps open while editing a scene.
// Exit codes: 0 success, 1 bad usage or no display; with --exit-when-done / --screenshot also
// 2 bad scene and 3 I/O failure (as the command-line renderer).
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>
#include <FL/Fl.H>
#include <FL/x.H>

#include "film/image_io.h"
#include "viewer_window.h"

namespace {

// Ctrl-C / SIGTERM: a thread of its own waits for them (they are blocked in every other thread),
// asks the window to quit cleanly, and ends the program itself if that has not happened 1.5 s
// later or on a second signal (e.g. when a native file chooser's own event loop is running).
void install_signal_thread() {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);  // before any other thread exists: all inherit it
    std::thread([set] {
        int sig = 0;
        if (sigwait(&set, &sig) != 0) return;
        whitted::viewer::request_quit_from_signal();
        const timespec grace{1, 500'000'000};
        sigtimedwait(&set, nullptr, &grace);
        std::_Exit(130);
    }).detach();
}

// FLTK exits from inside the library when it cannot open the display; check first, with a clear message.
Display* open_display_or_explain() {
    const char* name = std::getenv("DISPLAY");
    if (!name || !*name) {
        std::cerr << "whitted-view: error: no display: DISPLAY is not set.\n"
                     "whitted-view needs an X display; the command-line renderer `whitted` does not.\n";
        return nullptr;
    }
    Display* d = XOpenDisplay(nullptr);
    if (!d)
        std::cerr << "whitted-view: error: cannot open display '" << name << "'.\n"
                  << "whitted-view needs an X display; the command-line renderer `whitted` does not.\n";
    return d;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace whitted;
    using namespace whitted::viewer;
    CLI::App app{"whitted-view: view and re-render SceneView/Ray .sc scenes (FLTK)"};
    app.set_version_flag("--version", "whitted-view 0.1.0");
    app.option_defaults()->always_capture_default();
    ViewerOptions o;
    std::string mode_name = "whitted", missing = "ask";
    app.add_option("scene", o.scene, "Scene file (.sc) to open and render");
    app.add_option("--width", o.settings.width, "Image width in pixels")->check(CLI::Range(1, 32768));
    app.add_option("--height", o.settings.height, "Image height in pixels")->check(CLI::Range(1, 32768));
    app.add_flag("--fit", o.fit_window, "Render at the size of the image area");
    auto* depth_option = app.add_option("--max-depth", o.settings.integrator.max_depth,
                                        "Recursion limit for reflection/refraction (path mode: bounces, default 64)")
        ->check(CLI::Range(0, 1000));
    app.add_option("--aa", o.settings.sampling.aa, "Anti-aliasing: N x N rays per pixel, averaged")
        ->check(CLI::Range(1, Sampler::kMaxAa));
    auto* spp_option = app.add_option("--spp", o.settings.sampling.spp,
                   "Samples per pixel (per sub-pixel with --aa) for soft shadows, depth of field and gloss; they "
                   "arrive in passes")
        ->check(CLI::Range(1, Sampler::kMaxSpp));
    app.add_option("--aa-threshold", o.settings.sampling.aa_threshold,
                   "Adaptive anti-aliasing: only where a pixel differs from a neighbour by more (0-1); 0 = everywhere")
        ->check(CLI::Range(0.0f, 1.0f))
        ->check(CLI::Validator(
            [](std::string& s) { return std::isfinite(std::strtof(s.c_str(), nullptr)) ? "" : "not a finite number: " + s; },
            "FINITE"));
    app.add_option("--mode", mode_name, "Render mode (path: physically based path tracing)")
        ->check(CLI::IsMember({"whitted", "raycast", "normals", "depth", "path"}));
    app.add_option("--threads", o.settings.threads, "Worker threads (0 = all hardware threads)")
        ->check(CLI::Range(0, 1024));
    std::string stage = "illuminate";
    app.add_option("--cs1230-stage", stage,
                   "Brown CSCI 1230 JSON scenes: draw them as the course's Intersect or Illuminate project")
        ->check(CLI::IsMember({"illuminate", "intersect"}));
    app.add_flag("--watch", o.watch, "Reload and render again when the scene file changes on disk");
    // One directory per --texture-path (repeat it for more): a list would swallow the scene after it.
    app.add_option("--texture-path", o.texture_dirs, "Extra directory to look for textures in (repeat for more)")
        ->allow_extra_args(false)
        ->default_str("");
    app.add_option("--missing-textures", missing, "A texture that cannot be found: ask for the file, or draw a checkerboard")
        ->check(CLI::IsMember({"ask", "checker"}));
    app.add_flag("--lenient", o.lenient, "Skip unknown keywords and object types with a warning");
    app.add_option("--time", o.time, "Scene time t of 'velocity' and 'angularrate' (also Render ▸ Scene time; 0 = the still image)")
        ->check(CLI::Validator(
            [](std::string& s) { return std::isfinite(std::strtof(s.c_str(), nullptr)) ? "" : "not a finite number: " + s; },
            "FINITE"));
    auto* window_size = app.add_option("--window-size", [&o](const CLI::results_t& r) {
        return std::sscanf(r[0].c_str(), "%dx%d", &o.window_width, &o.window_height) == 2 && o.window_width > 0 &&
               o.window_height > 0;
    }, "Window size WxH (default 1000x760)")->type_name("WxH");
    auto* shot = app.add_option("--screenshot", o.screenshot,
                                "When the first render ends, save the image as shown on screen to FILE and exit");
    app.add_option("--ready-file", o.ready_file,
                   "When the first render ends and is on screen, write its job number, state and the window "
                   "and image geometry (root coordinates) to FILE; rewritten when a later render ends or the "
                   "layout changes");
    app.add_flag("--exit-when-done", o.exit_when_done, "Exit when the first render ends (for scripts)");
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : 1;
    }
    if (*shot && !is_supported_output(o.screenshot)) {
        std::cerr << "whitted-view: error: cannot write '" << o.screenshot << "': use .png, .bmp, .ppm, .jpg or .jpeg\n";
        return 1;
    }
    if (o.settings.sampling.aa_threshold > 0.0f && o.settings.sampling.spp > 1) {
        std::cerr << "whitted-view: error: --aa-threshold compares the colours of pixel centres, which --spp > 1 does "
                     "not take; use one or the other\n";
        return 1;
    }
    if (!o.screenshot.empty()) o.exit_when_done = true;
    // Nothing would ever be rendered, so "when done" would never come: say so instead of waiting.
    if (o.exit_when_done && o.scene.empty()) {
        std::cerr << "whitted-view: error: --screenshot and --exit-when-done need a scene file to render\n";
        return 1;
    }
    o.window_size_given = window_size->count() > 0;
    // Render settings on the command line replace the remembered ones (all of them).
    for (const char* name : {"--width", "--height", "--fit", "--max-depth", "--aa", "--spp", "--mode"})
        o.settings_given = o.settings_given || app.get_option(name)->count() > 0;
    // Scripts and tests get what they ask for, never what an earlier run left behind.
    if (o.exit_when_done || !o.ready_file.empty()) o.settings_given = true;
    o.settings.integrator.mode = *parse_render_mode(mode_name);
    o.settings.integrator.cs1230_stage = *cs1230::parse_stage(stage);
    if (o.settings.integrator.mode == RenderMode::Path) {  // §9.2: a path tracer's defaults
        if (spp_option->count() == 0) o.settings.sampling.spp = 64;
        if (depth_option->count() == 0) o.settings.integrator.max_depth = 64;
    }
    o.checker_textures = missing == "checker";

    install_signal_thread();
    Display* display = open_display_or_explain();
    if (!display) return 1;
    fl_open_display(display);

    Fl::visual(FL_RGB);  // true colour, so the image is shown exactly
    Fl::scheme("gtk+");
    int code = 0;
    {
        ViewerWindow window(o);
        window.show();
        // Not Fl::run(): a bounded wait, so a quit requested from inside a dialog's own event loop
        // (all windows hidden there) is seen here even when no further X event arrives.
        while (Fl::first_window() && !window.quitting()) Fl::wait(0.25);
        code = window.exit_code();
    }
    return code;
}
