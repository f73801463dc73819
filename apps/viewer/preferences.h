#pragma once
// What the viewer remembers between runs (FLTK's Fl_Preferences, in ~/.fltk/whitted/): the recent
// scenes (File ▸ Open recent), the window size and the render settings.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/render_job.h"

class Fl_Menu_Bar;

namespace whitted::viewer {

class Preferences {
public:
    // Reads the recent scenes, the window size and the settings remembered.
    Preferences();

    // The remembered window size, if it is a sane one.
    std::optional<std::pair<int, int>> window_size() const { return window_size_; }
    // The remembered render settings and Fit window, over `settings` (each clamped to its range).
    void recall_settings(RenderJob& settings, bool& fit) const;

    // Most recent first, absolute, no duplicates, at most ten.
    const std::vector<std::string>& recent() const { return recent_; }
    void add_recent(const std::string& path);
    // File ▸ Open recent's items (the submenu at `submenu`), each calling `open` with its path.
    void fill_recent_menu(Fl_Menu_Bar& menu, const char* submenu, std::function<void(const std::string&)> open);

    // Writes them all: the recent scenes, the window's size, the settings shown and Fit window.
    // `settings` (with `fit`) only when the user chose them in the window: a one-off command-line
    // option is not remembered (null: the remembered ones stay as they are).
    void save(int window_w, int window_h, const RenderJob* settings, bool fit) const;

private:
    std::vector<std::string> recent_;
    std::optional<std::pair<int, int>> window_size_;
    std::function<void(const std::string&)> open_recent_;
    std::string recent_submenu_;
};

}  // namespace whitted::viewer
