#include "viewer_window.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <ostream>

#include <FL/Fl.H>
#include <FL/Fl_Menu_Bar.H>

#include "camera_text.h"
#include "image_view.h"
#include "messages_panel.h"
#include "pixel_inspection.h"
#include "scripted_report.h"
#include "settings_bar.h"
#include "status_bar.h"
#include "status_text.h"
#include "viewer_util.h"
#include "watch_timer.h"

namespace whitted::viewer {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_quit_requested{false};

}  // namespace

void request_quit_from_signal() { g_quit_requested = true; }

// ---------------------------------------------------------------------------------------------

ViewerWindow::ViewerWindow(const ViewerOptions& options)
    : Fl_Double_Window(options.window_width, options.window_height, "whitted-view"), options_(options) {
    if (!options_.window_size_given)
        if (const auto size = preferences_.window_size()) this->size(size->first, size->second);
    // The widgets start from what was remembered, unless the command line said.
    RenderJob settings = options_.settings;
    bool fit = options_.fit_window;
    if (!options_.settings_given) preferences_.recall_settings(settings, fit);
    settings_chosen_ = !options_.settings_given;

    const int W = w();
    menu_ = new Fl_Menu_Bar(0, 0, W, kMenuH);
    settings_ = std::make_unique<SettingsBar>(settings, fit, options_.settings_given ? options_.render.given : std::set<std::string>{});
    settings_->on_render = [this] { render(); };
    settings_->on_stop = [this] { stop(); };
    settings_->on_view = [this] {
        controller_.set_display(settings_->view(), exposure_);
        set_message(std::string("view transform ") + view_transform_name(settings_->view()));
        if (report_) report_->changed();
    };
    settings_->on_change = [this] {
        settings_chosen_ = true;  // the user's choice: remembered
        if (!scene_.empty()) render();
    };
    build_menus();
    if (options_.render.is_given("view")) settings_->set_view(view_transform(options_.render));
    controller_.set_display(settings_->view(), exposure_);
    view_ = new ImageView(0, kMenuH + kToolH, W, 100);
    connect_view();
    messages_ = std::make_unique<MessagesPanel>([this](const std::string& line) { open_message_line(line); });
    status_ = std::make_unique<StatusBar>();
    end();
    inspection_ = std::make_unique<PixelInspection>(controller_, *view_);
    report_ = std::make_unique<ScriptedReport>(
        ScriptOptions{options_.screenshot, options_.ready_file, options_.exit_when_done}, *this, *view_, controller_,
        [this](std::ostream& out) { describe(out); }, [this] { quit(); });
    inspection_->on_drawn = [this] { report_->changed(); };
    resizable(this);  // our resize() lays the children out itself
    size_range(520, 300);
    callback([](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->quit(); }, this);
    layout();
    Fl::focus(view_);
    settings_->set_focus_home(view_);

    Fl::add_timeout(0.1, poll_cb, this);
    watch_ = std::make_unique<WatchTimer>(
        options_.watch, [this] { return scene_stamp(scene_, shown_.texture_files); }, [this] { render(true); },
        [this] { report_->changed(); });  // a test waits for ticks to know the file was (or would have been) checked
    if (!options.scene.empty()) open_scene(options.scene);
}

ViewerWindow::~ViewerWindow() {
    Fl::remove_timeout(poll_cb, this);
    Fl::remove_timeout(fit_cb, this);
    controller_.stop();
}

// The image's gestures: the camera (camera_session.h), the pixel readout, the inspector.
void ViewerWindow::connect_view() {
    view_->on_camera_drag = [this](ImageView::Drag kind, int dx, int dy, bool end) {
        // Orbit in screen pixels; pan in image pixels, so that the scene follows the mouse.
        const double s = view_->scale();
        const bool moved = kind == ImageView::Drag::Orbit
                               ? camera_.orbit_drag(float(dx), float(dy), end)
                               : camera_.pan_drag(float(dx / s), float(dy / s), view_->image.height, end);
        if (moved) render_view();
    };
    view_->on_wheel = [this](int steps, bool fov) {
        if (camera_.wheel(steps, fov)) render_view();
    };
    view_->on_hover = [this](int x, int y) {
        // Path mode's radiance goes above 1 where the bytes clip: its linear values too.
        const bool path = controller_.status().settings.integrator.mode == RenderMode::Path;
        status_->set_pixel(pixel_readout(view_->image, x, y, path ? controller_.linear_at(x, y) : std::nullopt));
    };
    view_->on_inspect = [this](int x, int y) { inspection_->inspect(x, y); };
}

void ViewerWindow::resize(int X, int Y, int W, int H) {
    Fl_Double_Window::resize(X, Y, W, H);
    if (!view_) return;  // the remembered size, set before the widgets are made
    layout();  // places the children exactly (Fl_Group only scales them)
    report_->changed();
}

void ViewerWindow::layout() {
    const int W = w(), H = h();
    menu_->resize(0, 0, W, kMenuH);
    settings_->layout(W);
    const int msg_h = messages_->has_lines() ? kMessagesH : 0;
    const int top = kMenuH + kToolH, bottom = H - kStatusH - msg_h;
    view_->resize(0, top, W, std::max(10, bottom - top));
    // With Fit window on, the image follows its area: render again once resizing has settled
    // (a drag comes as many resizes; each one postpones it).
    if (view_->w() != area_w_ || view_->h() != area_h_) {
        area_w_ = view_->w();
        area_h_ = view_->h();
        Fl::remove_timeout(fit_cb, this);
        if (settings_->fit() && !scene_.empty()) Fl::add_timeout(0.3, fit_cb, this);
    }
    if (msg_h) messages_->place(0, bottom, W, msg_h);
    else messages_->hide();
    status_->layout(H - kStatusH, W);
    redraw();
}

// ---------------------------------------------------------------------------------------------

LoadOptions ViewerWindow::load_options() const {
    LoadOptions o = make_load_options(options_.render);  // --untrusted's confinement and limits, --max-memory
    o.lenient = options_.lenient;
    o.time = options_.time;
    o.threads = settings_->threads();  // the BVH build uses the same threads as the render
    o.textures.search_dirs = options_.texture_dirs;
    textures_.apply(scene_, o.textures);  // the answers the user gave for this scene's missing textures
    o.textures.missing = options_.checker_textures ? MissingTexturePolicy::Checker : MissingTexturePolicy::Error;
    o.cs1230_stage = options_.settings.integrator.cs1230_stage;  // the Intersect stage reads no texture (§9.5)
    return o;
}

void ViewerWindow::open_scene(const std::string& path) {
    scene_ = path;
    std::string title = "whitted-view: " + base_name(path);
    copy_label(title.c_str());
    camera_.reset();  // another scene: its own camera
    std::error_code ec;
    if (fs::is_regular_file(path, ec)) {  // a name that is no file is not worth opening again
        preferences_.add_recent(path);
        preferences_.fill_recent_menu(*menu_, "&File/Open &recent", [this](const std::string& p) { open_scene(p); });
    }
    remember();
    render(true);
}

void ViewerWindow::render(bool force_reload) {
    if (scene_.empty()) {
        set_message("open a scene first (File > Open)");
        return;
    }
    RenderJob s = settings_->job(view_->w(), view_->h());
    extra_message_.clear();
    watch_->rearm();
    camera_.apply(s);  // the view the user moved to stays
    if (!controller_.start(scene_, load_options(), s, force_reload)) {
        set_message("the image is up to date: nothing changed (File > Reload reads the scene again)");
        report_->changed();
        return;
    }
    report_->job_started(controller_.status().job);
}

// Renders with the camera on screen: coarse frames at once, the previous frame cancelled.
void ViewerWindow::render_view() {
    if (scene_.empty()) return;
    RenderJob s = settings_->job(view_->w(), view_->h());
    camera_.apply(s);
    controller_.start(scene_, load_options(), s, false, /*coarse_first=*/true);
    report_->job_started(controller_.status().job);
}

void ViewerWindow::stop() { controller_.stop(); }

void ViewerWindow::quit() {
    if (!quitting_) remember();
    quitting_ = true;
    controller_.stop();
    Fl::remove_timeout(poll_cb, this);
    watch_->stop();
    Fl::remove_timeout(fit_cb, this);
    // Every window, dialogs included: a dialog's own event loop ends when its window is hidden.
    while (Fl_Window* w = Fl::first_window()) w->hide();
    // Fl::wait() runs timers before it sleeps: with none left it would sleep until the next X
    // event, keeping a dialog's loop (and so the program) alive. A last one wakes it up.
    Fl::add_timeout(0.02, [](void*) {}, nullptr);
}

int ViewerWindow::exit_code() const { return report_->exit_code(); }

void ViewerWindow::remember() {
    const RenderJob shown = settings_->shown();
    preferences_.save(w(), h(), settings_chosen_ ? &shown : nullptr, settings_->fit());
}

// Shown in the status bar (and, if an error or warning, in the messages panel) at the next poll.
void ViewerWindow::set_message(const std::string& text) { extra_message_ = text; }

// The scene's folder, absolute (file choosers need that), or the current one without a scene.
std::string ViewerWindow::scene_dir() const {
    std::error_code ec;
    fs::path dir = scene_.empty() ? fs::current_path(ec) : fs::absolute(scene_, ec).parent_path();
    return dir.string();
}

// Paths in messages are shown relative to the scene's folder (as the scene names its textures).
std::string ViewerWindow::relative_to_scene(std::string text) const {
    const std::string dir = fs::path(scene_).parent_path().string();
    if (dir.empty()) return text;
    const std::string prefix = dir + "/";
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
    return text;
}

// ---------------------------------------------------------------------------------------------

void ViewerWindow::poll_cb(void* self) { static_cast<ViewerWindow*>(self)->poll(); }
void ViewerWindow::fit_cb(void* self) { static_cast<ViewerWindow*>(self)->fit_to_area(); }

void ViewerWindow::poll() {
    if (g_quit_requested) {
        quit();
        return;
    }
    controller_.reap();
    const RenderStatus st = controller_.status();

    if (controller_.copy_image_if_changed(view_->image, image_version_)) {
        view_->redraw();
        inspection_->image_of_job(st.job);  // a ray tree drawn over another render's image goes
    }
    // The file's camera, once a load got that far (Home and the first move start from it).
    if (st.state == RenderState::Rendering || st.state == RenderState::Finished) camera_.file_loaded(st.file_camera);
    show_failure(st);
    settings_->set_busy(is_busy(st.state));

    std::string message = extra_message_.empty() ? relative_to_scene(st.message) : extra_message_;
    if (message.empty()) message = render_hint(st);
    status_->update(scene_, st, message);
    switch (messages_->update(st, extra_message_, [this](const std::string& t) { return relative_to_scene(t); })) {
        case MessagesPanel::Change::Shown: layout(); [[fallthrough]];
        case MessagesPanel::Change::Text: report_->changed(); break;
        case MessagesPanel::Change::Same: break;
    }
    shown_ = st;

    // (Automated runs never open dialogs: a missing texture ends them like a scene error.)
    const bool will_ask =
        st.state == RenderState::MissingTextures && !report_->automated() && st.job != asked_textures_job_;
    report_->polled(st, will_ask);

    // While frames come (a moving camera), look often; otherwise ten times a second.
    Fl::repeat_timeout(is_busy(st.state) ? 0.015 : 0.1, poll_cb, this);

    // Last, as it opens modal dialogs (which run their own event loop).
    if (will_ask) {
        asked_textures_job_ = st.job;
        ask_for_textures(st);
    }
}

// A failure keeps the last good image on screen, dimmed, under a banner with the errors.
void ViewerWindow::show_failure(const RenderStatus& st) {
    const bool failed = st.state == RenderState::Failed || st.state == RenderState::MissingTextures;
    std::vector<std::string> overlay;
    if (failed) {
        const bool kept = view_->image.width > 0;  // the first load has no good image to keep
        overlay.push_back(st.state == RenderState::MissingTextures ? "Textures were not found:"
                          : kept ? "The scene could not be loaded (the last good image is kept):"
                                 : "The scene could not be loaded:");
        for (const auto& d : st.diagnostics)
            if (d.severity == Severity::Error)
                for (const std::string& line : split_lines(relative_to_scene(d.str())))
                    if (overlay.size() < 16) overlay.push_back(line);
    }
    const bool dimmed = failed && view_->image.width > 0;
    if (overlay != view_->overlay || dimmed != view_->dimmed) {
        view_->overlay = overlay;
        view_->dimmed = dimmed;
        view_->redraw();
    }
}

// The image area has a new size and Fit window is on: render at that size (the controller reuses
// the loaded scene). A load in progress is waited for, not restarted. Not after a stop (the user
// wanted it stopped), a failure or missing textures (it would fail, or ask, again), nor in
// automated runs (they end with the first render).
void ViewerWindow::fit_to_area() {
    if (!settings_->fit() || scene_.empty() || options_.exit_when_done) return;
    const RenderStatus st = controller_.status();
    if (st.state == RenderState::Loading) {
        Fl::repeat_timeout(0.3, fit_cb, this);
        return;
    }
    const bool shown = st.state == RenderState::Rendering || st.state == RenderState::Finished;
    if (shown && (st.settings.width != view_->w() || st.settings.height != view_->h())) render();
}

// For tests and scripts (--ready-file). Geometry in root-window coordinates (where a screen grab
// finds things); the area is where the image is shown (Fit window renders at its size). The status
// of the last poll, whose image, status bar and messages are what the window shows; the controller
// may have moved on since (a small render can end in between).
void ViewerWindow::describe(std::ostream& out) const {
    const RenderStatus& st = shown_;
    const ScreenRect vis = view_->visible();
    out << "job " << st.job << " " << (st.scene_reused ? "reused" : "loaded") << "\n"
        << "state " << state_name(st.state) << "\n"
        << "window " << x() << " " << y() << " " << w() << " " << h() << "\n"
        << "area " << x() + view_->x() << " " << y() + view_->y() << " " << view_->w() << " " << view_->h() << "\n"
        << "image " << x() + vis.x << " " << y() + vis.y << " " << vis.w << " " << vis.h << "\n"
        << "watch_ticks " << watch_->ticks() << "\n"
        << "zoom " << view_->scale() << (view_->fitting() ? " fit" : "") << "\n"
        << "dimmed " << (view_->dimmed ? 1 : 0) << "\n"
        << "exposure " << exposure_ << "\n"
        << "view " << view_transform_name(settings_->view()) << "\n";
    if (const std::optional<CameraDesc> cam = camera_.current())
        out << "camera " << (camera_.moved() ? "moved " : "file ") << camera_block(*cam) << "\n";
    for (const std::string& r : preferences_.recent()) out << "recent " << r << "\n";
    for (const std::string& line : view_->overlay) out << "banner " << line << "\n";
    // The ray tree drawn over the image, in root coordinates (ends of lines, places of marks).
    const auto root = [&](const glm::vec2& p) {
        const glm::vec2 w = view_->to_window(p);
        return std::to_string(x() + w.x) + " " + std::to_string(y() + w.y);
    };
    for (const OverlayLine& l : view_->rays.lines)
        out << "ray " << ray_kind_name(l.kind) << " " << l.depth << " " << root(l.a) << " " << root(l.b) << "\n";
    for (const OverlayMark& m : view_->rays.marks) out << "mark " << mark_shape_name(m.shape) << " " << root(m.at) << "\n";
    settings_->describe(out, x(), y());
    status_->describe(out, x(), y());
    messages_->describe(out);
}

}  // namespace whitted::viewer
