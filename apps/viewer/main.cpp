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

#include "cs1230/detect.h"
#include "film/image_io.h"
#include "render_options.h"
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
    // The render settings of every front end (session/render_settings.h), as whitted takes them;
    // those the viewer cannot honour are refused after parsing, with the table's reason.
    RenderSettings rs;
    rs.missing_textures = "ask";
    app.add_option("scene", o.scene, "Scene file (.sc or CSCI 1230 .json) to open and render");
    for (const Setting& setting : render_settings_table()) cli::add_setting_option(app, rs, setting);
    app.add_flag("--fit", o.fit_window, "Render at the size of the image area");
    app.add_flag("--watch", o.watch, "Reload and render again when the scene file changes on disk");
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
    if (std::string problem = cli::collect_given(app, rs, Frontend::Viewer, "whitted-view"); !problem.empty()) {
        std::cerr << "whitted-view: error: " << problem << "\n";
        return 1;
    }
    apply_mode_defaults(rs, !o.scene.empty() && cs1230::is_json_scene_file(o.scene));
    if (std::string problem = validate(rs); !problem.empty()) {
        std::cerr << "whitted-view: error: " << problem << "\n";
        return 1;
    }
    if (rs.noise_threshold > 0.0f) {  // --aa-threshold with --spp > 1 means adaptive sampling (validate)
        std::cerr << "whitted-view: error: --aa-threshold with --spp > 1 is adaptive sampling: "
                  << find_setting("noise-threshold")->why_refused(Frontend::Viewer) << "\n";
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
    for (const char* name : {"width", "height", "max-depth", "aa", "spp", "mode"})
        o.settings_given = o.settings_given || rs.is_given(name);
    o.settings_given = o.settings_given || o.fit_window;
    // Scripts and tests get what they ask for, never what an earlier run left behind.
    if (o.exit_when_done || !o.ready_file.empty()) o.settings_given = true;
    o.settings = make_render_job(rs);
    o.render = rs;
    o.lenient = rs.lenient;
    o.time = rs.time;
    o.texture_dirs = rs.texture_dirs;
    o.checker_textures = rs.missing_textures == "checker";

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
