#include "shortcuts_window.h"

#include <string>

#include <FL/Fl_Browser.H>
#include <FL/Fl_Double_Window.H>

#include "shortcuts.h"

namespace whitted::viewer {

void show_shortcuts_window() {
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
