#include "shortcuts_window.h"

#include <algorithm>
#include <string>

#include <FL/Fl.H>
#include <FL/Fl_Browser.H>
#include <FL/Fl_Double_Window.H>
#include <FL/fl_draw.H>

#include "shortcuts.h"

namespace whitted::viewer {
namespace {

constexpr int kTextSize = 13, kPad = 8;

}  // namespace

void show_shortcuts_window(const Fl_Window& over) {
    static Fl_Double_Window* win = nullptr;
    static int widths[] = {0, 0};
    if (!win) {
        // The columns as wide as their widest text (keys in bold), every row shown.
        int keys_w = 0, actions_w = 0;
        for (const Shortcut& s : kShortcuts) {
            fl_font(FL_HELVETICA_BOLD, kTextSize);
            keys_w = std::max(keys_w, int(fl_width(s.keys)));
            fl_font(FL_HELVETICA, kTextSize);
            actions_w = std::max(actions_w, int(fl_width(s.action)));
        }
        widths[0] = keys_w + 20;
        const int rows = int(std::size(kShortcuts));
        // The browser's box and margins, a row's height (its text and 2 pixels of spacing).
        const int list_w = widths[0] + actions_w + 24, list_h = rows * (fl_height() + 2) + 8;
        win = new Fl_Double_Window(list_w + 2 * kPad, list_h + 2 * kPad, "Keyboard shortcuts");
        auto* list = new Fl_Browser(kPad, kPad, list_w, list_h);
        list->column_widths(widths);
        list->column_char('\t');
        list->textsize(kTextSize);
        for (const Shortcut& s : kShortcuts) list->add((std::string("@b") + s.keys + "\t@." + s.action).c_str());
        win->end();
        win->resizable(list);
    }
    if (!win->shown()) {
        // Centred over the main window, inside the screen's work area (smaller if it must be).
        int sx = 0, sy = 0, sw = 0, sh = 0;
        Fl::screen_work_area(sx, sy, sw, sh, over.x() + over.w() / 2, over.y() + over.h() / 2);
        const int w = std::min(win->w(), sw), h = std::min(win->h(), sh - 30);  // room for a title bar
        const int x = std::clamp(over.x() + (over.w() - w) / 2, sx, sx + sw - w);
        const int y = std::clamp(over.y() + (over.h() - h) / 2, sy + 30, sy + sh - h);
        win->resize(x, y, w, h);
    }
    win->show();
}

}  // namespace whitted::viewer
