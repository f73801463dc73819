#include "viewer_window.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <thread>

#include <FL/fl_ask.H>
#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/Fl_Text_Buffer.H>
#include <FL/Fl_Text_Display.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_Check_Button.H>
#include <FL/Fl_Choice.H>
#include <FL/Fl_Menu_Bar.H>
#include <FL/Fl_Return_Button.H>
#include <FL/Fl_Spinner.H>
#include <FL/fl_draw.H>
#include <FL/x.H>

#include "film/image_io.h"
#include "flatten/flatten.h"
#include "viewer_util.h"
#include "inspector_window.h"  // [inspector]

namespace whitted::viewer {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_quit_requested{false};

}  // namespace

void request_quit_from_signal() { g_quit_requested = true; }

// ---------------------------------------------------------------------------------------------

ViewerWindow::ViewerWindow(const ViewerOptions& options)
    : Fl_Double_Window(options.window_width, options.window_height, "whitted-view"), options_(options) {
    const int W = w();
    load_preferences();
    build_menus();
    build_toolbar();

    view_ = new ImageView(0, kMenuH + kToolH, W, 100);
    connect_view();
    view_->on_inspect = [this](int px, int py) { inspect(px, py); };  // [inspector]

    messages_ = new MessagesView(0, 0, W, kMessagesH);
    messages_->on_open_line = [this](const std::string& line) { open_message_line(line); };
    message_text_ = new Fl_Text_Buffer();
    message_styles_ = new Fl_Text_Buffer();
    messages_->buffer(message_text_);
    messages_->textfont(FL_COURIER);
    messages_->textsize(13);
    messages_->wrap_mode(Fl_Text_Display::WRAP_AT_BOUNDS, 0);
    static const Fl_Text_Display::Style_Table_Entry styles[] = {
        {FL_FOREGROUND_COLOR, FL_COURIER, 13, 0}, {FL_RED, FL_COURIER, 13, 0}, {FL_DARK_YELLOW, FL_COURIER, 13, 0}};
    messages_->highlight_data(message_styles_, styles, 3, 'A', nullptr, nullptr);

    scene_box_ = new Fl_Box(0, 0, 10, kStatusH);
    progress_box_ = new Fl_Box(0, 0, 10, kStatusH);
    message_box_ = new Fl_Box(0, 0, 10, kStatusH);
    pixel_box_ = new Fl_Box(0, 0, 10, kStatusH);
    for (Fl_Box* b : {scene_box_, progress_box_, message_box_, pixel_box_}) {
        b->box(FL_THIN_DOWN_BOX);
        b->align(FL_ALIGN_LEFT | FL_ALIGN_INSIDE | FL_ALIGN_CLIP);
        b->labelsize(13);
    }
    end();
    resizable(this);  // our resize() lays the children out itself
    size_range(520, 300);
    callback([](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->quit(); }, this);
    scene_box_->copy_label(" no scene: File > Open");
    layout();
    view_->take_focus();

    Fl::add_timeout(0.1, poll_cb, this);
    Fl::add_timeout(1.0, watch_cb, this);
    if (!options.scene.empty()) open_scene(options.scene);
}

ViewerWindow::~ViewerWindow() {
    Fl::remove_timeout(poll_cb, this);
    Fl::remove_timeout(watch_cb, this);
    Fl::remove_timeout(done_cb, this);
    Fl::remove_timeout(ready_cb, this);
    Fl::remove_timeout(fit_cb, this);
    controller_.stop();
}

void ViewerWindow::resize(int X, int Y, int W, int H) {
    Fl_Double_Window::resize(X, Y, W, H);
    if (!view_) return;  // the remembered size, set before the widgets are made
    layout();  // places the children exactly (Fl_Group only scales them)
    rewrite_ready_file_soon();
}

void ViewerWindow::layout() {
    const int W = w(), H = h();
    menu_->resize(0, 0, W, kMenuH);
    layout_toolbar();
    const int msg_h = show_messages_ ? kMessagesH : 0;
    const int top = kMenuH + kToolH, bottom = H - kStatusH - msg_h;
    view_->resize(0, top, W, std::max(10, bottom - top));
    // With Fit window on, the image follows its area: render again once resizing has settled
    // (a drag comes as many resizes; each one postpones it).
    if (view_->w() != area_w_ || view_->h() != area_h_) {
        area_w_ = view_->w();
        area_h_ = view_->h();
        Fl::remove_timeout(fit_cb, this);
        if (fit_->value() && !scene_.empty()) Fl::add_timeout(0.3, fit_cb, this);
    }
    if (show_messages_) {
        messages_->resize(0, bottom, W, msg_h);
        messages_->show();
    } else {
        messages_->hide();
    }
    layout_status();
    redraw();
}

// Scene, progress and message fields, each as wide as its text (the message takes the rest);
// a field too narrow for its text clips it, and its tooltip has it all.
void ViewerWindow::layout_status() {
    auto needs = [](const Fl_Box* b) {
        int tw = 0, th = 0;
        b->measure_label(tw, th);
        return tw + 10;  // the box's border and the label's margins
    };
    // The pixel readout (while the pointer is on the image) takes the right end.
    const int rw = pixel_text_.empty() ? 0 : std::min(needs(pixel_box_), w() / 3);
    if (rw) pixel_box_->show();
    else pixel_box_->hide();
    const int W = w() - rw, y = h() - kStatusH;
    pixel_box_->resize(W, y, rw, kStatusH);
    const int sw = std::min(needs(scene_box_), W / 3);
    // The progress text may take the message's room only while there is no message.
    const int pw = std::max(0, std::min(needs(progress_box_), W - sw - std::min(needs(message_box_), W / 3)));
    scene_box_->resize(0, y, sw, kStatusH);
    progress_box_->resize(sw, y, pw, kStatusH);
    message_box_->resize(sw + pw, y, W - sw - pw, kStatusH);
    for (Fl_Box* b : {scene_box_, progress_box_, message_box_, pixel_box_}) b->redraw();
}

// ---------------------------------------------------------------------------------------------

LoadOptions ViewerWindow::load_options() const {
    LoadOptions o;
    o.lenient = options_.lenient;
    o.time = options_.time;
    o.threads = int(threads_->value());  // the BVH build uses the same threads as the render
    o.textures.search_dirs = options_.texture_dirs;
    // The answers the user gave for this scene's missing textures (a file, or Cancel).
    if (auto it = texture_overrides_.find(scene_); it != texture_overrides_.end()) o.textures.overrides = it->second;
    if (auto it = declined_textures_.find(scene_); it != declined_textures_.end()) o.textures.checker_names = it->second;
    o.textures.missing = options_.checker_textures ? MissingTexturePolicy::Checker : MissingTexturePolicy::Error;
    o.cs1230_stage = options_.settings.integrator.cs1230_stage;  // the Intersect stage reads no texture (§9.5)
    return o;
}

void ViewerWindow::read_controls(RenderJob& s, bool& fit) {
    fit = fit_->value();
    if (fit) {
        s.width = std::max(1, view_->w());
        s.height = std::max(1, view_->h());
        width_->value(s.width);
        height_->value(s.height);
    } else {
        s.width = int(width_->value());
        s.height = int(height_->value());
    }
    s.integrator.max_depth = int(depth_->value());
    s.integrator.mode = RenderMode(std::max(0, mode_->value()));
    s.sampling.aa = int(aa_->value());
    s.sampling.spp = int(spp_->value());
    s.threads = int(threads_->value());
}

void ViewerWindow::open_scene(const std::string& path) {
    scene_ = path;
    std::string title = "whitted-view: " + base_name(path);
    copy_label(title.c_str());
    camera_.reset();  // another scene: its own camera
    file_camera_.reset();
    add_recent(path);
    render(true);
}

void ViewerWindow::render(bool force_reload) {
    if (scene_.empty()) {
        set_message("open a scene first (File > Open)");
        return;
    }
    RenderJob s = options_.settings;
    bool fit = false;
    read_controls(s, fit);
    extra_message_.clear();
    watched_stamp_ = watch_stamp();
    if (camera_) s.camera = make_camera(*camera_);  // the view the user moved to stays
    controller_.start(scene_, load_options(), s, force_reload);
    if (first_job_ == 0) first_job_ = controller_.status().job;
}

void ViewerWindow::stop() { controller_.stop(); }

void ViewerWindow::quit() {
    if (!quitting_) remember();
    quitting_ = true;
    controller_.stop();
    Fl::remove_timeout(poll_cb, this);
    Fl::remove_timeout(watch_cb, this);
    Fl::remove_timeout(fit_cb, this);
    // Every window, dialogs included: a dialog's own event loop ends when its window is hidden.
    while (Fl_Window* w = Fl::first_window()) w->hide();
    // Fl::wait() runs timers before it sleeps: with none left it would sleep until the next X
    // event, keeping a dialog's loop (and so the program) alive. A last one wakes it up.
    Fl::add_timeout(0.02, [](void*) {}, nullptr);
}

// Shown in the status bar (and, if an error or warning, in the messages panel) at the next poll.
void ViewerWindow::set_message(const std::string& text) { extra_message_ = text; }

// The scene's folder, absolute (file choosers need that), or the current one without a scene.
std::string ViewerWindow::scene_dir() const {
    std::error_code ec;
    fs::path dir = scene_.empty() ? fs::current_path(ec) : fs::absolute(scene_, ec).parent_path();
    return dir.string();
}

// ---------------------------------------------------------------------------------------------

void ViewerWindow::poll_cb(void* self) { static_cast<ViewerWindow*>(self)->poll(); }
void ViewerWindow::watch_cb(void* self) { static_cast<ViewerWindow*>(self)->watch(); }
void ViewerWindow::done_cb(void* self) { static_cast<ViewerWindow*>(self)->when_done(); }
void ViewerWindow::fit_cb(void* self) { static_cast<ViewerWindow*>(self)->fit_to_area(); }

void ViewerWindow::poll() {
    if (g_quit_requested) {
        quit();
        return;
    }
    controller_.reap();
    const RenderStatus st = controller_.status();

    const bool failed = st.state == RenderState::Failed || st.state == RenderState::MissingTextures;
    if (controller_.copy_image_if_changed(view_->image, image_version_)) view_->redraw();
    // The file's camera, once a load got that far (Home and the first move start from it).
    if (st.state == RenderState::Rendering || st.state == RenderState::Finished) file_camera_ = st.file_camera;
    // A failure keeps the last good image on screen, dimmed, under a banner with the errors.
    std::vector<std::string> overlay;
    if (failed) {
        overlay.push_back(st.state == RenderState::Failed ? "The scene could not be loaded (the last good image is kept):"
                                                          : "Textures were not found:");
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
    if (is_busy(st.state)) stop_button_->activate();
    else stop_button_->deactivate();

    update_status(st);
    show_messages(st);
    shown_ = st;
    // Every render that ends is reported, not only the first (e.g. after --watch reloads).
    if (!is_busy(st.state) && st.job != ended_job_) {
        ended_job_ = st.job;
        rewrite_ready_file_soon();
    }

    // The first render has ended: the hooks for tests and scripts, once it is on screen.
    // (Automated runs never open dialogs: a missing texture ends them like a scene error.)
    const bool automated = !options_.screenshot.empty() || options_.exit_when_done;
    const bool will_ask = st.state == RenderState::MissingTextures && !automated && st.job != asked_textures_job_;
    if (!done_handled_ && first_job_ != 0 && st.job >= first_job_ && !is_busy(st.state) &&
        st.state != RenderState::Idle && !will_ask) {
        if (automated || !options_.ready_file.empty()) {
            done_handled_ = true;
            Fl::add_timeout(0.3, done_cb, this);
        }
    }

    // While frames come (a moving camera), look often; otherwise ten times a second.
    Fl::repeat_timeout(is_busy(st.state) ? 0.015 : 0.1, poll_cb, this);

    // Last, as it opens modal dialogs (which run their own event loop).
    if (will_ask) {
        asked_textures_job_ = st.job;
        ask_for_textures(st);
    }
}

void ViewerWindow::update_status(const RenderStatus& st) {
    std::string stats;
    if (st.load_stats.objects || st.load_stats.lights || st.state == RenderState::Rendering ||
        st.state == RenderState::Finished)
        stats = ": " + std::to_string(st.load_stats.objects) + " objects, " + std::to_string(st.load_stats.lights) +
                (st.load_stats.lights == 1 ? " light" : " lights") + " (" + dialect_name(st.load_stats.dialect) +
                ")";

    char buf[200];
    const int pct = st.tiles_total ? int(100.0 * st.tiles_done / st.tiles_total) : 0;
    switch (st.state) {
        case RenderState::Idle: std::snprintf(buf, sizeof buf, "ready"); break;
        case RenderState::Loading: std::snprintf(buf, sizeof buf, "loading... %.1f s", st.elapsed_seconds); break;
        case RenderState::Rendering:
            if (st.passes_total > 1)
                std::snprintf(buf, sizeof buf, "rendering %d×%d: %d%%, %d of %d samples/pixel done, %.1f s",
                              st.settings.width, st.settings.height, pct, st.samples_done, st.samples_total,
                              st.elapsed_seconds);
            else
                std::snprintf(buf, sizeof buf, "rendering %d×%d: %d%% (%d/%d tiles), %.1f s", st.settings.width,
                              st.settings.height, pct, st.tiles_done, st.tiles_total, st.elapsed_seconds);
            break;
        case RenderState::Finished:
            if (st.samples_total > 1)
                std::snprintf(buf, sizeof buf, "done %d×%d, %d samples/pixel, in %.2f s", st.settings.width,
                              st.settings.height, st.samples_total, st.elapsed_seconds);
            else
                std::snprintf(buf, sizeof buf, "done %d×%d in %.2f s", st.settings.width, st.settings.height,
                              st.elapsed_seconds);
            break;
        case RenderState::Stopped:
            std::snprintf(buf, sizeof buf, "stopped at %d%% (%d/%d tiles, %d of %d samples/pixel complete), %.1f s",
                          pct, st.tiles_done, st.tiles_total, st.samples_done, st.samples_total, st.elapsed_seconds);
            break;
        case RenderState::Failed: std::snprintf(buf, sizeof buf, "the scene has errors"); break;
        case RenderState::MissingTextures: std::snprintf(buf, sizeof buf, "textures not found"); break;
    }

    const std::string& msg = extra_message_.empty() ? st.message : extra_message_;
    // Sets a field's text (first line; " " keeps it off the border), colour and tooltip (all of it).
    auto set = [](Fl_Box* b, const std::string& text, const std::string& tip_text, Fl_Color c) {
        const std::string label = escape_label(" " + split_lines(text).front()), tip = escape_label(tip_text);
        if (label == (b->label() ? b->label() : "") && tip == (b->tooltip() ? b->tooltip() : "") &&
            c == b->labelcolor())
            return false;
        b->copy_label(label.c_str());
        b->copy_tooltip(tip.empty() ? nullptr : tip.c_str());
        b->labelcolor(c);
        return true;
    };
    bool changed = scene_.empty() ? set(scene_box_, "no scene: File > Open", "", FL_FOREGROUND_COLOR)
                                  : set(scene_box_, base_name(scene_) + stats, scene_ + stats, FL_FOREGROUND_COLOR);
    changed |= set(progress_box_, buf, buf, FL_FOREGROUND_COLOR);
    const std::string shown_msg = extra_message_.empty() ? relative_to_scene(msg) : msg;
    changed |= set(message_box_, shown_msg, shown_msg, message_color(msg));
    changed |= set(pixel_box_, pixel_text_, pixel_text_, FL_FOREGROUND_COLOR);
    if (changed) layout_status();
}

// The messages panel: selectable text (copy with Ctrl+C), wrapped, errors red and warnings
// yellow, paths relative to the scene's folder. Each line is kept with its style letter first.
void ViewerWindow::show_messages(const RenderStatus& st) {
    auto styled = [](const std::string& line, Fl_Color c) {
        return std::string(1, c == FL_RED ? 'B' : c == FL_DARK_YELLOW ? 'C' : 'A') + line;
    };
    // Keep the previous load's messages while a new load runs, until it has its own.
    if (st.state != RenderState::Loading && st.job != shown_diagnostics_job_) {
        shown_diagnostics_job_ = st.job;
        diagnostic_lines_.clear();
        for (const auto& d : st.diagnostics)
            for (const std::string& line : split_lines(relative_to_scene(d.str())))
                diagnostic_lines_.push_back(styled(line, d.severity == Severity::Error ? FL_RED : FL_DARK_YELLOW));
        // A failure without a diagnostic still has its message in the status bar.
        if (st.diagnostics.empty() && message_color(st.message) != FL_FOREGROUND_COLOR)
            diagnostic_lines_.push_back(styled(relative_to_scene(st.message), message_color(st.message)));
    }
    // The viewer's own errors and warnings (e.g. a failed save) go last.
    std::vector<std::string> lines = diagnostic_lines_;
    const bool own = message_color(extra_message_) != FL_FOREGROUND_COLOR;
    if (own)
        for (const std::string& line : split_lines(extra_message_))
            lines.push_back(styled(line, message_color(extra_message_)));
    if (lines == message_lines_) return;
    message_lines_ = lines;
    std::string text, style;
    for (const std::string& line : lines) {
        text += line.substr(1) + "\n";
        style += std::string(line.size() - 1, line[0]) + "A";
    }
    message_text_->text(text.c_str());
    message_styles_->text(style.c_str());
    if (own) messages_->scroll(messages_->count_lines(0, message_text_->length(), true), 0);
    if (show_messages_ != !lines.empty()) {
        show_messages_ = !lines.empty();
        layout();
    }
    rewrite_ready_file_soon();
}

// Paths in messages are shown relative to the scene's folder (as the scene names its textures).
std::string ViewerWindow::relative_to_scene(std::string text) const {
    const std::string dir = fs::path(scene_).parent_path().string();
    if (dir.empty()) return text;
    const std::string prefix = dir + "/";
    for (std::size_t at; (at = text.find(prefix)) != std::string::npos;) text.erase(at, prefix.size());
    return text;
}

// The scene file's stamp (file_stamp), then those of the texture files of its last load.
std::string ViewerWindow::watch_stamp() const {
    std::string stamp = file_stamp(scene_);
    for (const std::string& t : shown_.texture_files) {
        stamp += '|';
        stamp += file_stamp(t);
    }
    return stamp;
}

void ViewerWindow::watch() {
    if (options_.watch && !scene_.empty()) {
        std::string stamp = watch_stamp();
        if (!stamp.empty() && stamp != watched_stamp_) {
            watched_stamp_ = stamp;
            render(true);
        }
    }
    ++watch_ticks_;
    rewrite_ready_file_soon();  // a test waits for ticks to know the file was (or would have been) checked
    Fl::repeat_timeout(1.0, watch_cb, this);
}

// The image area has a new size and Fit window is on: render at that size (the controller reuses
// the loaded scene). A load in progress is waited for, not restarted. Not after a stop (the user
// wanted it stopped), a failure or missing textures (it would fail, or ask, again), nor in
// automated runs (they end with the first render).
void ViewerWindow::fit_to_area() {
    if (!fit_->value() || scene_.empty() || options_.exit_when_done) return;
    const RenderStatus st = controller_.status();
    if (st.state == RenderState::Loading) {
        Fl::repeat_timeout(0.3, fit_cb, this);
        return;
    }
    const bool shown = st.state == RenderState::Rendering || st.state == RenderState::Finished;
    if (shown && (st.settings.width != view_->w() || st.settings.height != view_->h())) render();
}

}  // namespace whitted::viewer
