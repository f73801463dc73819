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
#include <FL/Fl_Browser.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_Check_Button.H>
#include <FL/Fl_Choice.H>
#include <FL/Fl_Menu_Bar.H>
#include <FL/Fl_Native_File_Chooser.H>
#include <FL/Fl_Return_Button.H>
#include <FL/Fl_Scroll.H>
#include <FL/Fl_Spinner.H>
#include <FL/fl_draw.H>
#include <FL/x.H>

#include "film/image_io.h"
#include "inspector_window.h"  // [inspector]

namespace whitted::viewer {
namespace {

namespace fs = std::filesystem;

std::atomic<bool> g_quit_requested{false};

constexpr int kMenuH = 25, kToolH = 34, kStatusH = 24, kMessagesH = 110;
// In RenderMode's order.
constexpr const char* kModes[] = {"whitted", "raycast", "normals", "depth", "path"};

std::string base_name(const std::string& path) { return fs::path(path).filename().string(); }

// FLTK draws "@name" in a label or tooltip as a symbol; "@@" is a literal '@'. For names (scenes,
// textures, paths) that must show as written.
std::string escape_label(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '@') out += '@';
        out += c;
    }
    return out;
}

// Errors and warnings are coloured in the status bar and also listed in the messages panel.
Fl_Color message_color(const std::string& msg) {
    if (msg.find("error:") != std::string::npos) return FL_RED;
    if (msg.find("warning:") != std::string::npos) return FL_DARK_YELLOW;
    return FL_FOREGROUND_COLOR;
}

// A diagnostic's text may run over several lines (e.g. the paths a texture was looked for at).
std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
        lines.push_back(text.substr(start, nl - start));
    lines.push_back(text.substr(start));
    return lines;
}

// Asks whether to pick the file for a texture that was not found, listing every path tried (in a
// browser, which scrolls when there are many). 1 = choose a file, 0 = use the checkerboard.
int ask_texture_dialog(const MissingTexture& mt, const std::string& where, const Fl_Window& parent) {
    const int W = 640, line_h = 17, rows = std::clamp(int(mt.tried.size()), 2, 14);
    const std::string about = escape_label("The texture \"" + mt.name + "\" (" + where + ") could not be loaded: " +
                                           mt.reason + ".\n\nLooked at " + std::to_string(mt.tried.size()) +
                                           (mt.tried.size() == 1 ? " place:" : " places:"));
    int text_w = W - 20, text_h = 0;
    fl_font(FL_HELVETICA, FL_NORMAL_SIZE);
    fl_measure(about.c_str(), text_w, text_h);  // wrapped at the dialog's width
    const int list_y = 10 + text_h + 6, list_h = rows * line_h + 6, question_y = list_y + list_h + 6;
    Fl_Double_Window dlg(W, question_y + 24 + 50, "Texture not found");
    auto* text = new Fl_Box(10, 10, W - 20, text_h);
    text->align(FL_ALIGN_LEFT | FL_ALIGN_TOP | FL_ALIGN_INSIDE | FL_ALIGN_WRAP);
    text->copy_label(about.c_str());
    auto* list = new Fl_Browser(10, list_y, W - 20, list_h);
    list->textfont(FL_COURIER);
    list->textsize(13);
    for (const std::string& p : mt.tried) list->add(("@." + p).c_str());
    auto* question = new Fl_Box(10, question_y, W - 20, 24, "Choose the image file to use for it?");
    question->align(FL_ALIGN_LEFT | FL_ALIGN_INSIDE);
    int answer = 0;
    auto* cancel = new Fl_Button(W - 340, dlg.h() - 38, 180, 28, "Cancel (checkerboard)");
    auto* choose = new Fl_Return_Button(W - 150, dlg.h() - 38, 140, 28, "Choose file...");
    cancel->callback([](Fl_Widget* b, void*) { b->window()->hide(); });
    choose->callback([](Fl_Widget* b, void* a) {
        *static_cast<int*>(a) = 1;
        b->window()->hide();
    }, &answer);
    dlg.end();
    dlg.resizable(list);
    dlg.set_modal();
    dlg.position(parent.x() + (parent.w() - dlg.w()) / 2, parent.y() + std::max(0, (parent.h() - dlg.h()) / 2));
    dlg.show();
    // Ends when a button or Escape closes it, or when quitting hides every window.
    while (dlg.shown()) Fl::wait();
    return answer;
}

}  // namespace

void request_quit_from_signal() { g_quit_requested = true; }

// Shows the image (row 0 at the top) centred in its area, or a message when there is none.
class ImageView : public Fl_Widget {
public:
    ImageView(int x, int y, int w, int h) : Fl_Widget(x, y, w, h) { box(FL_FLAT_BOX); color(fl_rgb_color(48, 48, 48)); }

    Image image;
    std::vector<std::string> overlay;  // lines drawn over a blank area instead of the image
    // [inspector] Called with an image pixel on a left click without drag, and on Shift+hover.
    std::function<void(int, int)> on_inspect;
    int handle(int event) override {  // [inspector]
        const bool shift_hover = event == FL_MOVE && (Fl::event_state() & FL_SHIFT);
        if (event == FL_PUSH && Fl::event_button() == FL_LEFT_MOUSE) press_x_ = Fl::event_x(), press_y_ = Fl::event_y();
        const bool click = event == FL_RELEASE && Fl::event_button() == FL_LEFT_MOUSE &&
                           std::abs(Fl::event_x() - press_x_) + std::abs(Fl::event_y() - press_y_) <= 3;
        if ((click || shift_hover) && on_inspect && overlay.empty()) {
            const int px = Fl::event_x() - image_x(), py = Fl::event_y() - image_y();
            if (px >= 0 && py >= 0 && px < image.width && py < image.height) on_inspect(px, py);
        }
        return event == FL_PUSH || event == FL_RELEASE || event == FL_ENTER || event == FL_MOVE ? 1
                                                                                                : Fl_Widget::handle(event);
    }
    int press_x_ = -1000, press_y_ = -1000;  // [inspector]

    // Top-left corner of the image, in window coordinates.
    int image_x() const { return x() + std::max(0, (w() - image.width) / 2); }
    int image_y() const { return y() + std::max(0, (h() - image.height) / 2); }

    void draw() override {
        fl_push_clip(x(), y(), w(), h());
        fl_color(color());
        fl_rectf(x(), y(), w(), h());
        if (overlay.empty() && image.width > 0 && image.height > 0) {
            fl_draw_image(image.rgb.data(), image_x(), image_y(), image.width, image.height, 3, 0);
        } else if (!overlay.empty()) {
            fl_font(FL_HELVETICA, 14);
            int line = fl_height() + 4, top = y() + 24;
            for (std::size_t i = 0; i < overlay.size(); ++i) {
                fl_color(i == 0 ? FL_WHITE : fl_rgb_color(255, 140, 120));
                fl_draw(overlay[i].c_str(), x() + 20, top + int(i) * line);
            }
        }
        fl_pop_clip();
    }
};

// ---------------------------------------------------------------------------------------------

ViewerWindow::ViewerWindow(const ViewerOptions& options)
    : Fl_Double_Window(options.window_width, options.window_height, "whitted-view"), options_(options) {
    const int W = w();
    menu_ = new Fl_Menu_Bar(0, 0, W, kMenuH);
    menu_->add("&File/&Open...", FL_CTRL + 'o', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->choose_and_open(); }, this);
    menu_->add("&File/&Reload", FL_CTRL + 'r', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->render(true); }, this);
    menu_->add("&File/Reload on &change", 0, [](Fl_Widget* m, void* v) {
        auto* self = static_cast<ViewerWindow*>(v);
        const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(m)->mvalue();
        self->options_.watch = item && item->value();
        self->watched_stamp_ = file_stamp(self->scene_);
    }, this, FL_MENU_TOGGLE | (options.watch ? FL_MENU_VALUE : 0));
    menu_->add("&File/&Save image as...", FL_CTRL + 's', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->save_image_as(); }, this, FL_MENU_DIVIDER);
    menu_->add("&File/&Quit", FL_CTRL + 'q', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->quit(); }, this);
    menu_->add("&Render/&Render", FL_F + 5, [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->render(); }, this);
    menu_->add("&Render/&Stop", FL_Escape, [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->stop(); }, this);
    menu_->add("&Render/Scene &time...", FL_CTRL + 't', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->ask_time(); }, this);
    menu_->add("&Render/&Inspect pixel...", FL_CTRL + 'i', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->ask_inspect(); }, this);  // [inspector]

    // Tool bar: the render controls. Changing one and pressing Render uses it.
    // Made at their final sizes; layout() places them left to right.
    const int h = 24;
    auto tool = [this](Fl_Widget* w, const char* id, int gap) {
        const Fl_Align a = w->align();
        int lw = 0, lh = 0;
        if ((a & FL_ALIGN_LEFT) && !(a & FL_ALIGN_INSIDE)) {  // a label drawn to its left needs room
            w->measure_label(lw, lh);
            lw += 5;
        }
        tools_.push_back({w, id, gap, lw, w->w(), w->h()});
    };
    render_button_ = new Fl_Button(0, 0, 70, h, "Render");
    render_button_->callback([](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->render(); }, this);
    render_button_->tooltip("Render with these settings (F5)");
    tool(render_button_, "render", 0);
    stop_button_ = new Fl_Button(0, 0, 56, h, "Stop");
    stop_button_->callback([](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->stop(); }, this);
    stop_button_->tooltip("Stop rendering, keeping what is done (Esc)");
    tool(stop_button_, "stop", 4);
    auto spinner = [&](const char* id, const char* label, int gap, int sw, int lo, int hi, int value, const char* tip) {
        auto* s = new Fl_Spinner(0, 0, sw, h, label);
        s->type(FL_INT_INPUT);
        s->range(lo, hi);
        s->step(1);
        s->value(value);
        s->tooltip(tip);
        tool(s, id, gap);
        return s;
    };
    // Sized so that every tool fits the default 1000-pixel window.
    width_ = spinner("width", "Width", 12, 64, 1, 32768, options.settings.width, "Image width in pixels");
    height_ = spinner("height", "Height", 8, 64, 1, 32768, options.settings.height, "Image height in pixels");
    fit_ = new Fl_Check_Button(0, 0, 88, h, "Fit window");
    fit_->value(options.fit_window);
    fit_->tooltip("Render at the size of the image area");
    fit_->callback([](Fl_Widget* w, void* v) {
        auto* self = static_cast<ViewerWindow*>(v);
        bool on = static_cast<Fl_Check_Button*>(w)->value();
        if (on) self->width_->deactivate(), self->height_->deactivate();
        else self->width_->activate(), self->height_->activate();
    }, this);
    fit_->do_callback();
    tool(fit_, "fit", 8);
    depth_ = spinner("depth", "Depth", 8, 46, 0, 1000, options.settings.integrator.max_depth,
                     "Recursion limit for reflection and refraction (the camera ray is depth 0)");
    mode_ = new Fl_Choice(0, 0, 80, h, "Mode");
    for (const char* m : kModes) mode_->add(m);
    mode_->value(int(options.settings.integrator.mode));
    mode_->tooltip("whitted: the lab's lighting; raycast: unlit colour; normals, depth: debugging views; path: "
                   "physically based path tracing (set SPP to 64 or more)");
    tool(mode_, "mode", 8);
    aa_ = spinner("aa", "AA", 8, 40, 1, Sampler::kMaxAa, options.settings.sampling.aa,
                  "Anti-aliasing: N x N rays per pixel, averaged (1 = one ray through the pixel centre)");
    spp_ = spinner("spp", "SPP", 8, 54, 1, Sampler::kMaxSpp, options.settings.sampling.spp,
                   "Samples per pixel (per anti-aliasing cell) for soft shadows, depth of field and gloss: they "
                   "arrive in passes, the image refining as you watch; Stop keeps the passes done");
    const int hw = int(std::max(1u, std::thread::hardware_concurrency()));
    threads_ = spinner("threads", "Threads", 8, 46, 1, 1024,
                       options.settings.threads > 0 ? options.settings.threads : hw, "Worker threads");

    scroll_ = new Fl_Scroll(0, kMenuH + kToolH, W, 100);
    scroll_->box(FL_FLAT_BOX);
    scroll_->color(fl_rgb_color(48, 48, 48));
    view_ = new ImageView(0, kMenuH + kToolH, W, 100);
    view_->on_inspect = [this](int px, int py) { inspect(px, py); };  // [inspector]
    scroll_->end();

    messages_ = new Fl_Browser(0, 0, W, kMessagesH);
    messages_->textfont(FL_COURIER);
    messages_->textsize(13);

    scene_box_ = new Fl_Box(0, 0, 10, kStatusH);
    progress_box_ = new Fl_Box(0, 0, 10, kStatusH);
    message_box_ = new Fl_Box(0, 0, 10, kStatusH);
    for (Fl_Box* b : {scene_box_, progress_box_, message_box_}) {
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
    layout();  // places the children exactly (Fl_Group only scales them)
    rewrite_ready_file_soon();
}

void ViewerWindow::layout() {
    const int W = w(), H = h();
    menu_->resize(0, 0, W, kMenuH);
    layout_toolbar();
    const int msg_h = show_messages_ ? kMessagesH : 0;
    const int top = kMenuH + kToolH, bottom = H - kStatusH - msg_h;
    scroll_->resize(0, top, W, std::max(10, bottom - top));
    // With Fit window on, the image follows its area: render again once resizing has settled
    // (a drag comes as many resizes; each one postpones it).
    if (scroll_->w() != area_w_ || scroll_->h() != area_h_) {
        area_w_ = scroll_->w();
        area_h_ = scroll_->h();
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
    // The image widget is as big as the image, or as the visible area if that is bigger.
    const int vw = std::max(scroll_->w(), view_->image.width), vh = std::max(scroll_->h(), view_->image.height);
    view_->resize(scroll_->x() - scroll_->xposition(), scroll_->y() - scroll_->yposition(), vw, vh);
    scroll_->init_sizes();
    scroll_->redraw();
    redraw();
}

// Every tool at the size it was made at; those that no longer fit the window's width are hidden
// (they come last, so the ones shown never move).
void ViewerWindow::layout_toolbar() {
    const int y = kMenuH + 5, right = w() - 6;
    int x = 6;
    for (const Tool& t : tools_) {
        x += t.gap + t.label_w;
        t.widget->resize(x, y, t.w, t.h);
        if (x + t.w <= right) t.widget->show();
        else t.widget->hide();
        x += t.w;
    }
}

// Scene, progress and message fields, each as wide as its text (the message takes the rest);
// a field too narrow for its text clips it, and its tooltip has it all.
void ViewerWindow::layout_status() {
    auto needs = [](const Fl_Box* b) {
        int tw = 0, th = 0;
        b->measure_label(tw, th);
        return tw + 10;  // the box's border and the label's margins
    };
    const int W = w(), y = h() - kStatusH;
    const int sw = std::min(needs(scene_box_), W / 3);
    // The progress text may take the message's room only while there is no message.
    const int pw = std::max(0, std::min(needs(progress_box_), W - sw - std::min(needs(message_box_), W / 3)));
    scene_box_->resize(0, y, sw, kStatusH);
    progress_box_->resize(sw, y, pw, kStatusH);
    message_box_->resize(sw + pw, y, W - sw - pw, kStatusH);
    for (Fl_Box* b : {scene_box_, progress_box_, message_box_}) b->redraw();
}

// ---------------------------------------------------------------------------------------------

// Scene time t of `velocity` / `angularrate` (scene-format.md §9.4): asked for, then rendered.
void ViewerWindow::ask_time() {
    char current[32];
    std::snprintf(current, sizeof current, "%g", double(options_.time));
    const char* answer = fl_input("Scene time t ('velocity' moves by t times its vector, 'angularrate' turns by "
                                  "t times its rate; 0 is the still image):", current);
    if (!answer) return;
    char* end = nullptr;
    const float t = std::strtof(answer, &end);
    if (end == answer || !std::isfinite(t)) {
        fl_alert("Not a finite number: %s", answer);
        return;
    }
    options_.time = t;
    render();
}

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
    return o;
}

void ViewerWindow::read_controls(RenderJob& s, bool& fit) {
    fit = fit_->value();
    if (fit) {
        s.width = std::max(1, scroll_->w());
        s.height = std::max(1, scroll_->h());
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
    watched_stamp_ = file_stamp(scene_);
    controller_.start(scene_, load_options(), s, force_reload);
    if (first_job_ == 0) first_job_ = controller_.status().job;
}

void ViewerWindow::stop() { controller_.stop(); }

void ViewerWindow::quit() {
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
    if (controller_.copy_image_if_changed(view_->image, image_version_)) {
        layout();
        view_->redraw();
    }
    std::vector<std::string> overlay;
    if (failed) {
        overlay.push_back(st.state == RenderState::Failed ? "The scene could not be loaded:"
                                                          : "Textures were not found:");
        for (const auto& d : st.diagnostics)
            if (d.severity == Severity::Error)
                for (const std::string& line : split_lines(d.str()))
                    if (overlay.size() < 16) overlay.push_back(line);
    }
    if (overlay != view_->overlay) {
        view_->overlay = overlay;
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

    Fl::repeat_timeout(0.1, poll_cb, this);

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
    changed |= set(message_box_, msg, msg, message_color(msg));
    if (changed) layout_status();
}

void ViewerWindow::show_messages(const RenderStatus& st) {
    // "@C<n>@." colours a line and makes the rest literal text.
    auto coloured = [](const std::string& line, Fl_Color c) { return "@C" + std::to_string(int(c)) + "@." + line; };
    // Keep the previous load's messages while a new load runs, until it has its own.
    if (st.state != RenderState::Loading && st.job != shown_diagnostics_job_) {
        shown_diagnostics_job_ = st.job;
        diagnostic_lines_.clear();
        for (const auto& d : st.diagnostics)
            for (const std::string& line : split_lines(d.str()))
                diagnostic_lines_.push_back(coloured(line, d.severity == Severity::Error ? FL_RED : FL_DARK_YELLOW));
        // A failure without a diagnostic still has its message in the status bar.
        if (st.diagnostics.empty() && message_color(st.message) != FL_FOREGROUND_COLOR)
            diagnostic_lines_.push_back(coloured(st.message, message_color(st.message)));
    }
    // The viewer's own errors and warnings (e.g. a failed save) go last.
    std::vector<std::string> lines = diagnostic_lines_;
    const bool own = message_color(extra_message_) != FL_FOREGROUND_COLOR;
    if (own)
        for (const std::string& line : split_lines(extra_message_))
            lines.push_back(coloured(line, message_color(extra_message_)));
    if (lines == message_lines_) return;
    message_lines_ = lines;
    messages_->clear();
    for (const std::string& line : lines) messages_->add(line.c_str());
    if (own) messages_->bottomline(messages_->size());
    if (show_messages_ != !lines.empty()) {
        show_messages_ = !lines.empty();
        layout();
    }
    rewrite_ready_file_soon();
}

void ViewerWindow::ask_for_textures(const RenderStatus& st) {
    bool declined = false;
    std::string declined_names;  // for the status bar: which textures are checkerboards now
    std::set<std::string>& declined_here = declined_textures_[scene_];
    for (const MissingTexture& mt : st.missing_textures) {
        if (declined_here.count(mt.name)) continue;  // answered before: drawn as a checkerboard
        std::string where = base_name(mt.loc.file.empty() ? scene_ : mt.loc.file) + " line " + std::to_string(mt.loc.line);
        const int answer = ask_texture_dialog(mt, where, *this);
        if (quitting_) return;
        std::string picked;
        if (answer == 1) {
            Fl_Native_File_Chooser chooser;
            chooser.title(("Texture \"" + mt.name + "\"").c_str());
            chooser.type(Fl_Native_File_Chooser::BROWSE_FILE);
            chooser.filter("Images\t*.{bmp,png,jpg,jpeg,ppm,pgm,tga,gif,psd,hdr,pic}\nAll files\t*");
            chooser.directory(scene_dir().c_str());
            if (chooser.show() == 0 && chooser.filename()) picked = chooser.filename();
        }
        if (quitting_) return;
        if (picked.empty()) {
            declined = true;
            declined_here.insert(mt.name);
            declined_names += (declined_names.empty() ? "'" : ", '") + mt.name + "'";
        } else {
            texture_overrides_[scene_][mt.name] = picked;
        }
    }
    if (declined) extra_message_ = "";
    render(true);
    if (declined) set_message("warning: texture " + declined_names + " drawn as a checkerboard (not found)");
}

void ViewerWindow::watch() {
    if (options_.watch && !scene_.empty()) {
        std::string stamp = file_stamp(scene_);
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
    if (shown && (st.settings.width != scroll_->w() || st.settings.height != scroll_->h())) render();
}

// ---------------------------------------------------------------------------------------------

void ViewerWindow::choose_and_open() {
    Fl_Native_File_Chooser chooser;
    chooser.title("Open scene");
    chooser.type(Fl_Native_File_Chooser::BROWSE_FILE);
    chooser.filter("Scenes\t*.sc\nAll files\t*");
    chooser.directory(scene_dir().c_str());
    if (chooser.show() == 0 && chooser.filename()) open_scene(chooser.filename());
}

void ViewerWindow::save_image_as() {
    Image img = controller_.image();
    if (img.width == 0) {
        set_message("error: nothing rendered yet");
        return;
    }
    Fl_Native_File_Chooser chooser;
    chooser.title("Save image as");
    chooser.type(Fl_Native_File_Chooser::BROWSE_SAVE_FILE);
    chooser.options(Fl_Native_File_Chooser::SAVEAS_CONFIRM | Fl_Native_File_Chooser::NEW_FOLDER);
    chooser.filter("PNG\t*.png\nBMP\t*.bmp\nPPM\t*.ppm\nJPEG\t*.{jpg,jpeg}");
    // In the scene's folder, named after it.
    chooser.directory(scene_dir().c_str());
    std::string suggested = scene_.empty() ? "image.png" : fs::path(scene_).stem().string() + ".png";
    chooser.preset_file(suggested.c_str());
    if (chooser.show() != 0 || !chooser.filename()) return;
    std::string path = chooser.filename();
    if (fs::path(path).extension().empty()) {
        static const char* exts[] = {".png", ".bmp", ".ppm", ".jpg"};
        int f = chooser.filter_value();
        path += exts[f >= 0 && f < 4 ? f : 0];
    }
    if (!is_supported_output(path)) {
        set_message("error: cannot write '" + path + "': use .png, .bmp, .ppm, .jpg or .jpeg");
        return;
    }
    std::string err = write_image(img, path);
    set_message(err.empty() ? "saved " + path : "error: " + err);
}

// The first render has ended and has been on screen for a moment: screenshot, ready file, exit.
void ViewerWindow::when_done() {
    Fl::flush();
    XSync(fl_display, False);
    const RenderStatus st = controller_.status();
    if ((st.state == RenderState::Failed || st.state == RenderState::MissingTextures) && options_.exit_when_done) {
        exit_code_ = 2;
        for (const auto& d : st.diagnostics) std::fprintf(stderr, "%s\n", d.str().c_str());
    }

    const Rect vis = visible_image();
    if (!options_.screenshot.empty()) {
        std::string err;
        if (vis.w <= 0 || vis.h <= 0 || !view_->overlay.empty()) {
            err = "no image is shown";
        } else {
            make_current();
            Image shot(vis.w, vis.h);
            if (!fl_read_image(shot.rgb.data(), vis.x, vis.y, shot.width, shot.height)) err = "fl_read_image failed";
            else err = write_image(shot, options_.screenshot);
        }
        if (!err.empty()) {
            std::fprintf(stderr, "whitted-view: error: screenshot: %s\n", err.c_str());
            if (exit_code_ == 0 && options_.exit_when_done) exit_code_ = 3;
        }
    }
    if (!options_.ready_file.empty()) {
        write_ready_file();
        ready_written_ = true;
    }
    if (options_.exit_when_done) quit();
}

// The visible part of the image, in window coordinates.
ViewerWindow::Rect ViewerWindow::visible_image() const {
    const int ix = view_->image_x(), iy = view_->image_y();
    const int x0 = std::max(ix, scroll_->x()), y0 = std::max(iy, scroll_->y());
    const int x1 = std::min(ix + view_->image.width, scroll_->x() + scroll_->w());
    const int y1 = std::min(iy + view_->image.height, scroll_->y() + scroll_->h());
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

// For tests and scripts. Geometry in root-window coordinates (where a screen grab finds things);
// the area is where the image is shown (Fit window renders at its size); a tool's x and w include
// its label; a field "needs" the width its text takes, and its label is as given to FLTK ("@@" for '@').
void ViewerWindow::write_ready_file() {
    // The status of the last poll, whose image, status bar and messages are what the window
    // shows; the controller may have moved on since (a small render can end in between).
    const RenderStatus& st = shown_;
    const Rect vis = visible_image();
    const std::string tmp = options_.ready_file + ".tmp";
    {
        std::ofstream out(tmp);
        out << "job " << st.job << " " << (st.scene_reused ? "reused" : "loaded") << "\n"
            << "state " << state_name(st.state) << "\n"
            << "window " << x() << " " << y() << " " << w() << " " << h() << "\n"
            << "area " << x() + scroll_->x() << " " << y() + scroll_->y() << " " << scroll_->w() << " "
            << scroll_->h() << "\n"
            << "image " << x() + vis.x << " " << y() + vis.y << " " << vis.w << " " << vis.h << "\n"
            << "watch_ticks " << watch_ticks_ << "\n";
        for (const Tool& t : tools_) {
            const Fl_Widget* tw = t.widget;
            out << "tool " << t.id << " " << x() + tw->x() - t.label_w << " " << y() + tw->y() << " "
                << t.label_w + tw->w() << " " << tw->h() << " " << (tw->visible() ? "shown" : "hidden") << "\n";
        }
        const std::pair<const char*, const Fl_Box*> fields[] = {
            {"scene", scene_box_}, {"progress", progress_box_}, {"message", message_box_}};
        for (const auto& [name, b] : fields) {
            int tw = 0, th = 0;
            b->measure_label(tw, th);
            out << "field " << name << " " << x() + b->x() << " " << y() + b->y() << " " << b->w() << " " << b->h()
                << " needs " << tw << " label " << (b->label() ? b->label() : "") << "\n";
        }
        for (int i = 1; i <= messages_->size(); ++i) {
            const std::string line = messages_->text(i);
            const std::size_t text = line.find("@.");  // after the colour
            out << "panel " << (text == std::string::npos ? line : line.substr(text + 2)) << "\n";
        }
    }
    std::error_code ec;
    fs::rename(tmp, options_.ready_file, ec);
}

void ViewerWindow::ready_cb(void* self) {
    auto* win = static_cast<ViewerWindow*>(self);
    Fl::flush();  // what the file describes is on screen
    XSync(fl_display, False);
    win->write_ready_file();
}

// After the first render has been reported, a render that ends, a new layout or new messages are
// reported too (once they have settled: a resize by dragging comes as many).
void ViewerWindow::rewrite_ready_file_soon() {
    if (!ready_written_) return;
    Fl::remove_timeout(ready_cb, this);
    Fl::add_timeout(0.3, ready_cb, this);
}

}  // namespace whitted::viewer
