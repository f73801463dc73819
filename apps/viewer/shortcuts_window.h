#pragma once
// Help ▸ Keyboard shortcuts: the table of shortcuts.h in a window of its own (made on first use).
namespace whitted::viewer {

void show_shortcuts_window();

}  // namespace whitted::viewer
