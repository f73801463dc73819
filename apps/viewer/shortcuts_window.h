#pragma once
// Help ▸ Keyboard shortcuts: the table of shortcuts.h in a window of its own (made on first use),
// as large as the table (within the screen), over the main window.
class Fl_Window;

namespace whitted::viewer {

void show_shortcuts_window(const Fl_Window& over);

}  // namespace whitted::viewer
