// The viewer window's menus and keyboard shortcuts (one table: the menus, the Help ▸ Keyboard
// shortcuts window and the README list the same keys), the view's zoom and exposure, the camera's
// keys, and files dropped on the window.
#include <algorithm>
#include <cstdio>
#include <string>

#include <FL/Fl.H>
#include <FL/Fl_Menu_Bar.H>

#include "image_view.h"
#include "pixel_inspection.h"
#include "scripted_report.h"
#include "settings_bar.h"
#include "shortcuts_window.h"
#include "viewer_window.h"
#include "watch_timer.h"

namespace whitted::viewer {

namespace {

template <void (ViewerWindow::*F)()>
void call(Fl_Widget*, void* v) {
    (static_cast<ViewerWindow*>(v)->*F)();
}

ViewerWindow* self(void* v) { return static_cast<ViewerWindow*>(v); }

}  // namespace

void ViewerWindow::build_menus() {
    Fl_Menu_Bar* m = menu_;
    m->add("&File/&Open...", FL_CTRL + 'o', call<&ViewerWindow::choose_and_open>, this);
    m->add("&File/Open &recent", 0, nullptr, nullptr, FL_SUBMENU);
    m->add("&File/&Reload", FL_CTRL + 'r', [](Fl_Widget*, void* v) { self(v)->render(true); }, this);
    m->add("&File/Reload on &change", 0, [](Fl_Widget* w, void* v) {
        const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
        self(v)->watch_->set_enabled(item && item->value());
    }, this, FL_MENU_TOGGLE | (options_.watch ? FL_MENU_VALUE : 0));
    m->add("&File/&Save image as...", FL_CTRL + 's', call<&ViewerWindow::save_image_as>, this, FL_MENU_DIVIDER);
    m->add("&File/&Copy camera", FL_CTRL + FL_SHIFT + 'c', call<&ViewerWindow::copy_camera>, this);
    m->add("&File/Save camera &into scene...", FL_CTRL + FL_SHIFT + 's', call<&ViewerWindow::save_camera_into_scene>,
           this, FL_MENU_DIVIDER);
    m->add("&File/&Quit", FL_CTRL + 'q', call<&ViewerWindow::quit>, this);

    m->add("&Render/&Render", FL_F + 5, [](Fl_Widget*, void* v) { self(v)->render(); }, this);
    m->add("&Render/&Stop", FL_Escape, call<&ViewerWindow::stop>, this);
    m->add("&Render/Scene &time...", FL_CTRL + 't', call<&ViewerWindow::ask_time>, this);
    m->add("&Render/&Inspect pixel...", FL_CTRL + 'i', [](Fl_Widget*, void* v) { self(v)->inspection_->ask(); },
           this, FL_MENU_DIVIDER);
    // Every tool bar control, also when the window is too narrow to show it.
    settings_->add_menu_items(*m);
    m->add("&Render/&Lenient (skip unknown keywords)", 0, [](Fl_Widget* w, void* v) {
        const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
        self(v)->options_.lenient = item && item->value();
        self(v)->render(true);
    }, this, FL_MENU_TOGGLE | (options_.lenient ? FL_MENU_VALUE : 0));
    m->add("&Render/Missing textures as &checkerboard", 0, [](Fl_Widget* w, void* v) {
        const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
        self(v)->options_.checker_textures = item && item->value();
        self(v)->render(true);
    }, this, FL_MENU_TOGGLE | (options_.checker_textures ? FL_MENU_VALUE : 0));

    m->add("&View/&Fit", 'f', [](Fl_Widget*, void* v) { self(v)->zoom_view(Zoom::Fit); }, this);
    m->add("&View/&1:1", '1', [](Fl_Widget*, void* v) { self(v)->zoom_view(Zoom::One); }, this);
    m->add("&View/Zoom &in", '+', [](Fl_Widget*, void* v) { self(v)->zoom_view(Zoom::In); }, this);
    m->add("&View/Zoom &out", '-', [](Fl_Widget*, void* v) { self(v)->zoom_view(Zoom::Out); }, this, FL_MENU_DIVIDER);
    m->add("&View/&Exposure up", ']', [](Fl_Widget*, void* v) { self(v)->change_exposure(1); }, this);
    m->add("&View/E&xposure down", '[', [](Fl_Widget*, void* v) { self(v)->change_exposure(-1); }, this);
    m->add("&View/Exposure &0", '\\', [](Fl_Widget*, void* v) { self(v)->change_exposure(0); }, this, FL_MENU_DIVIDER);
    m->add("&View/Ray &tree depth...", 0, [](Fl_Widget*, void* v) { self(v)->inspection_->ask_depth(); }, this,
           FL_MENU_DIVIDER);
    m->add("&View/&Camera to the file's (Home)", FL_Home, call<&ViewerWindow::home>, this);
    // The fly keys, here so that they are found (and work wherever the focus is not a text field).
    const std::pair<char, const char*> fly[] = {{'w', "forwards"}, {'s', "backwards"}, {'a', "left"},
                                                {'d', "right"},    {'q', "down"},      {'e', "up"}};
    for (const auto& [key, what] : fly)
        m->add((std::string("&View/Fl&y/") + what).c_str(), key, [](Fl_Widget* w, void* v) {
            const Fl_Menu_Item* item = static_cast<Fl_Menu_Bar*>(w)->mvalue();
            if (item) self(v)->fly_key(char(item->shortcut()));
        }, this);

    m->add("&Help/&Keyboard shortcuts", FL_F + 1, [](Fl_Widget*, void* v) { show_shortcuts_window(*self(v)); }, this);
    preferences_.fill_recent_menu(*m, "&File/Open &recent", [this](const std::string& p) { open_scene(p); });
}

void ViewerWindow::zoom_view(Zoom how) {
    switch (how) {
        case Zoom::Fit: view_->zoom_fit(); break;
        case Zoom::One: view_->zoom_one(); break;
        case Zoom::In: view_->zoom_by(1); break;
        case Zoom::Out: view_->zoom_by(-1); break;
    }
    report_->changed();
}

void ViewerWindow::change_exposure(int stops) {
    exposure_ = stops == 0 ? 0.0f : std::clamp(exposure_ + float(stops), -10.0f, 10.0f);
    controller_.set_display(settings_->view(), exposure_);
    char buf[64];
    std::snprintf(buf, sizeof buf, "exposure %+g stops", double(exposure_));
    set_message(buf);
    report_->changed();
}

void ViewerWindow::home() {
    if (camera_.home()) render_view();
}

void ViewerWindow::fly_key(char key) {
    if (camera_.fly(key)) render_view();
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

}  // namespace whitted::viewer
