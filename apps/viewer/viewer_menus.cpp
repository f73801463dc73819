// The viewer window's menus, tool bar and keyboard shortcuts (one table: the menus, the Help ▸
// Keyboard shortcuts window and the README list the same keys).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/Fl_Browser.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_Check_Button.H>
#include <FL/Fl_Choice.H>
#include <FL/Fl_Double_Window.H>
#include <FL/Fl_Menu_Bar.H>
#include <FL/Fl_Spinner.H>
#include <FL/fl_ask.H>

#include "shortcuts.h"
#include "viewer_util.h"
#include "viewer_window.h"

namespace whitted::viewer {

namespace {

template <void (ViewerWindow::*F)()>
void call(Fl_Widget*, void* v) {
    (static_cast<ViewerWindow*>(v)->*F)();
}

// Asks for a new value of a tool bar spinner (the Render menu reaches every control, also those
// a narrow window hides), then applies it as if typed there.
void ask_spinner(Fl_Spinner* s, const char* what) {
    char current[32];
    std::snprintf(current, sizeof current, "%d", int(s->value()));
    fl_message_title(what);  // a window named after its question (tests find it by name)
    const char* answer = fl_input("%s (%d to %d):", current, what, int(s->minimum()), int(s->maximum()));
    if (!answer) return;
    char* end = nullptr;
    const long v = std::strtol(answer, &end, 10);
    if (end == answer || *end || v < long(s->minimum()) || v > long(s->maximum())) {
        fl_alert("Not a whole number from %d to %d: %s", int(s->minimum()), int(s->maximum()), answer);
        return;
    }
    s->value(double(v));
    s->do_callback();
}

}  // namespace

void ViewerWindow::build_menus() {
    menu_ = new Fl_Menu_Bar(0, 0, w(), kMenuH);
    Fl_Menu_Bar* m = menu_;
    m->add("&File/&Open...", FL_CTRL + 'o', call<&ViewerWindow::choose_and_open>, this);
    m->add("&File/Open &recent", 0, nullptr, nullptr, FL_SUBMENU);
    m->add("&File/&Reload", FL_CTRL + 'r', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->render(true); }, this);
    m->add("&File/Reload on &change", 0, [](Fl_Widget* w, void* v) {
        auto* self = static_cast<ViewerWindow*>(v);
        const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
        self->options_.watch = item && item->value();
        self->watched_stamp_ = self->watch_stamp();
    }, this, FL_MENU_TOGGLE | (options_.watch ? FL_MENU_VALUE : 0));
    m->add("&File/&Save image as...", FL_CTRL + 's', call<&ViewerWindow::save_image_as>, this, FL_MENU_DIVIDER);
    m->add("&File/&Copy camera", FL_CTRL + FL_SHIFT + 'c', call<&ViewerWindow::copy_camera>, this);
    m->add("&File/Save camera &into scene...", FL_CTRL + FL_SHIFT + 's', call<&ViewerWindow::save_camera_into_scene>,
           this, FL_MENU_DIVIDER);
    m->add("&File/&Quit", FL_CTRL + 'q', call<&ViewerWindow::quit>, this);

    m->add("&Render/&Render", FL_F + 5, [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->render(); }, this);
    m->add("&Render/&Stop", FL_Escape, call<&ViewerWindow::stop>, this);
    m->add("&Render/Scene &time...", FL_CTRL + 't', call<&ViewerWindow::ask_time>, this);
    m->add("&Render/&Inspect pixel...", FL_CTRL + 'i', call<&ViewerWindow::ask_inspect>, this, FL_MENU_DIVIDER);
    // Every tool bar control, also when the window is too narrow to show it.
    m->add("&Render/&Width...", 0, [](Fl_Widget*, void* v) { ask_spinner(static_cast<ViewerWindow*>(v)->width_, "Image width"); }, this);
    m->add("&Render/&Height...", 0, [](Fl_Widget*, void* v) { ask_spinner(static_cast<ViewerWindow*>(v)->height_, "Image height"); }, this);
    m->add("&Render/&Fit window", 0, [](Fl_Widget*, void* v) {
        auto* self = static_cast<ViewerWindow*>(v);
        self->fit_->value(!self->fit_->value());
        self->fit_->do_callback();
    }, this);
    m->add("&Render/&Depth...", 0, [](Fl_Widget*, void* v) { ask_spinner(static_cast<ViewerWindow*>(v)->depth_, "Recursion depth"); }, this);
    for (int i = 0; i < int(std::size(kModes)); ++i)
        m->add((std::string("&Render/&Mode/") + kModes[i]).c_str(), 0, [](Fl_Widget* w, void* v) {
            auto* self = static_cast<ViewerWindow*>(v);
            const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
            for (int k = 0; k < int(std::size(kModes)); ++k)
                if (item && item->label() && std::string(item->label()) == kModes[k]) self->mode_->value(k);
            self->mode_->do_callback();
        }, this);
    m->add("&Render/&Anti-aliasing...", 0, [](Fl_Widget*, void* v) { ask_spinner(static_cast<ViewerWindow*>(v)->aa_, "Anti-aliasing N (N x N rays per pixel)"); }, this);
    m->add("&Render/Samples &per pixel...", 0, [](Fl_Widget*, void* v) { ask_spinner(static_cast<ViewerWindow*>(v)->spp_, "Samples per pixel"); }, this);
    m->add("&Render/T&hreads...", 0, [](Fl_Widget*, void* v) { ask_spinner(static_cast<ViewerWindow*>(v)->threads_, "Worker threads"); }, this, FL_MENU_DIVIDER);
    // The load options of the command line.
    m->add("&Render/AA thres&hold...", 0, call<&ViewerWindow::ask_aa_threshold>, this);
    m->add("&Render/&Lenient (skip unknown keywords)", 0, [](Fl_Widget* w, void* v) {
        auto* self = static_cast<ViewerWindow*>(v);
        const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
        self->options_.lenient = item && item->value();
        self->render(true);
    }, this, FL_MENU_TOGGLE | (options_.lenient ? FL_MENU_VALUE : 0));
    m->add("&Render/Missing textures as &checkerboard", 0, [](Fl_Widget* w, void* v) {
        auto* self = static_cast<ViewerWindow*>(v);
        const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
        self->options_.checker_textures = item && item->value();
        self->render(true);
    }, this, FL_MENU_TOGGLE | (options_.checker_textures ? FL_MENU_VALUE : 0));

    m->add("&View/&Fit", 'f', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->zoom_view(Zoom::Fit); }, this);
    m->add("&View/&1:1", '1', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->zoom_view(Zoom::One); }, this);
    m->add("&View/Zoom &in", '+', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->zoom_view(Zoom::In); }, this);
    m->add("&View/Zoom &out", '-', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->zoom_view(Zoom::Out); }, this, FL_MENU_DIVIDER);
    m->add("&View/&Exposure up", ']', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->change_exposure(1); }, this);
    m->add("&View/E&xposure down", '[', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->change_exposure(-1); }, this);
    m->add("&View/Exposure &0", '\\', [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->change_exposure(0); }, this, FL_MENU_DIVIDER);
    m->add("&View/&Camera to the file's (Home)", FL_Home, call<&ViewerWindow::home>, this);
    // The fly keys, here so that they are found (and work wherever the focus is not a text field).
    const std::pair<char, const char*> fly[] = {{'w', "forwards"}, {'s', "backwards"}, {'a', "left"},
                                                {'d', "right"},    {'q', "down"},      {'e', "up"}};
    for (const auto& [key, what] : fly)
        m->add((std::string("&View/Fl&y/") + what).c_str(), key, [](Fl_Widget* w, void* v) {
            const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
            if (item) static_cast<ViewerWindow*>(v)->fly_key(char(item->shortcut()));
        }, this);

    m->add("&Help/&Keyboard shortcuts", FL_F + 1, call<&ViewerWindow::show_shortcuts>, this);
    rebuild_recent_menu();
}

void ViewerWindow::rebuild_recent_menu() {
    const int at = menu_->find_index("&File/Open &recent");
    if (at < 0) return;
    menu_->clear_submenu(at);
    if (recent_.empty()) {
        menu_->add("&File/Open &recent/(none)", 0, nullptr, nullptr, FL_MENU_INACTIVE);
        return;
    }
    for (const std::string& path : recent_) {
        // '/' would make a submenu and '&' a shortcut: escaped for the menu label.
        std::string label;
        for (char c : path) {
            if (c == '/' || c == '\\' || c == '&' || c == '_') label += '\\';
            label += c;
        }
        // The item's place in the submenu says which path it is (its user data is the window).
        menu_->add(("&File/Open &recent/" + label).c_str(), 0, [](Fl_Widget* w, void* v) {
            auto* self = static_cast<ViewerWindow*>(v);
            auto* menu = static_cast<Fl_Menu_Bar*>(w);
            const int at = menu->find_index("&File/Open &recent"), i = menu->value() - at - 1;
            if (at >= 0 && i >= 0 && i < int(self->recent_.size())) self->open_scene(std::string(self->recent_[std::size_t(i)]));
        }, this);
    }
}

// Tool bar: the render controls, made at their final sizes; layout() places them left to right.
// Changing one renders again (after a moment, so that typing a number renders once).
void ViewerWindow::build_toolbar() {
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
    auto changed = [](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->settings_changed(); };
    render_button_ = new Fl_Button(0, 0, 70, h, "Render");
    render_button_->callback([](Fl_Widget*, void* v) { static_cast<ViewerWindow*>(v)->render(); }, this);
    render_button_->tooltip("Render with these settings (F5)");
    tool(render_button_, "render", 0);
    stop_button_ = new Fl_Button(0, 0, 56, h, "Stop");
    stop_button_->callback(call<&ViewerWindow::stop>, this);
    stop_button_->tooltip("Stop rendering, keeping what is done (Esc)");
    tool(stop_button_, "stop", 4);
    auto spinner = [&](const char* id, const char* label, int gap, int sw, int lo, int hi, int value, const char* tip) {
        auto* s = new Fl_Spinner(0, 0, sw, h, label);
        s->type(FL_INT_INPUT);
        s->range(lo, hi);
        s->step(1);
        s->value(value);
        s->tooltip(tip);
        s->callback(changed, this);
        tool(s, id, gap);
        return s;
    };
    const RenderJob& st = options_.settings;
    // Sized so that every tool fits the default 1000-pixel window.
    width_ = spinner("width", "Width", 12, 64, 1, 32768, st.width, "Image width in pixels");
    height_ = spinner("height", "Height", 8, 64, 1, 32768, st.height, "Image height in pixels");
    fit_ = new Fl_Check_Button(0, 0, 88, h, "Fit window");
    fit_->value(options_.fit_window);
    fit_->tooltip("Render at the size of the image area");
    fit_->callback([](Fl_Widget* w, void* v) {
        auto* self = static_cast<ViewerWindow*>(v);
        bool on = static_cast<Fl_Check_Button*>(w)->value();
        if (on) self->width_->deactivate(), self->height_->deactivate();
        else self->width_->activate(), self->height_->activate();
        self->settings_changed();
    }, this);
    if (options_.fit_window) width_->deactivate(), height_->deactivate();
    tool(fit_, "fit", 8);
    depth_ = spinner("depth", "Depth", 8, 46, 0, 1000, st.integrator.max_depth,
                     "Recursion limit for reflection and refraction (the camera ray is depth 0)");
    mode_ = new Fl_Choice(0, 0, 80, h, "Mode");
    for (const char* md : kModes) mode_->add(md);
    mode_->value(int(st.integrator.mode));
    mode_->tooltip("whitted: the lab's lighting; raycast: unlit colour; normals, depth: debugging views; path: "
                   "physically based path tracing (set SPP to 64 or more)");
    mode_->callback(changed, this);
    tool(mode_, "mode", 8);
    aa_ = spinner("aa", "AA", 8, 40, 1, Sampler::kMaxAa, st.sampling.aa,
                  "Anti-aliasing: N x N rays per pixel, averaged (1 = one ray through the pixel centre)");
    spp_ = spinner("spp", "SPP", 8, 54, 1, Sampler::kMaxSpp, st.sampling.spp,
                   "Samples per pixel (per anti-aliasing cell) for soft shadows, depth of field and gloss: they "
                   "arrive in passes, the image refining as you watch; Stop keeps the passes done");
    const int hw = int(std::max(1u, std::thread::hardware_concurrency()));
    threads_ = spinner("threads", "Threads", 8, 46, 1, 1024, st.threads > 0 ? st.threads : hw, "Worker threads");
}

// Every tool at the size it was made at; those that no longer fit the window's width are hidden
// (they come last, so the ones shown never move; the Render menu has each of them).
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

void ViewerWindow::zoom_view(Zoom how) {
    switch (how) {
        case Zoom::Fit: view_->zoom_fit(); break;
        case Zoom::One: view_->zoom_one(); break;
        case Zoom::In: view_->zoom_by(1); break;
        case Zoom::Out: view_->zoom_by(-1); break;
    }
    rewrite_ready_file_soon();
}

// Drag and drop: a scene file dropped on the window (text/uri-list, or a plain path) is opened.
int ViewerWindow::handle(int event) {
    if (event == FL_DND_ENTER || event == FL_DND_DRAG || event == FL_DND_RELEASE) return 1;  // accept drops
    if (event == FL_DND_LEAVE) return 1;
    if (event == FL_PASTE) {  // a dropped file: the first path of the text/uri-list
        std::string text(Fl::event_text() ? Fl::event_text() : "", std::size_t(std::max(0, Fl::event_length())));
        std::string first = text.substr(0, text.find_first_of("\r\n"));
        if (first.rfind("file://", 0) == 0) {
            first = first.substr(7);
            std::string decoded;  // %20 and friends
            for (std::size_t i = 0; i < first.size(); ++i) {
                if (first[i] == '%' && i + 2 < first.size()) {
                    decoded += char(std::stoi(first.substr(i + 1, 2), nullptr, 16));
                    i += 2;
                } else {
                    decoded += first[i];
                }
            }
            first = decoded;
        }
        if (!first.empty()) open_scene(first);
        return 1;
    }
    return Fl_Double_Window::handle(event);
}

// Help ▸ Keyboard shortcuts: the table, in a window of its own.
void ViewerWindow::show_shortcuts() {
    static Fl_Double_Window* win = nullptr;
    if (!win) {
        win = new Fl_Double_Window(560, 420, "Keyboard shortcuts");
        auto* list = new Fl_Browser(8, 8, 544, 404);
        static int widths[] = {190, 0};
        list->column_widths(widths);
        list->column_char('\t');
        list->textsize(13);
        for (const Shortcut& s : kShortcuts) list->add((std::string("@b") + s.keys + "\t@." + s.action).c_str());
        win->end();
        win->resizable(list);
    }
    win->show();
}

}  // namespace whitted::viewer
