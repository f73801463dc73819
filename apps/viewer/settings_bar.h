#pragma once
// The render settings on screen: the tool bar (Render, Stop, width, height, Fit window, depth,
// mode, AA, SPP, threads) and the Render menu's items for each of them (also those a narrow
// window hides), with the settings no widget shows (the AA threshold, and the rest of the job the
// command line gave). The one place where widgets meet RenderJob.
#include <functional>
#include <iosfwd>
#include <set>
#include <string>
#include <vector>

#include "film/view_transform.h"
#include "render/render_job.h"

class Fl_Button;
class Fl_Check_Button;
class Fl_Choice;
class Fl_Menu_Bar;
class Fl_Spinner;
class Fl_Widget;
class Fl_Window;

namespace whitted::viewer {

class SettingsBar {
public:
    // Makes the tool bar's widgets in the current group (the window's), showing `settings` and `fit`.
    // `given`: the settings the user chose on the command line (the table's names); with those chosen
    // here, a change of mode leaves them alone and gives the others the mode's defaults.
    SettingsBar(const RenderJob& settings, bool fit, std::set<std::string> given = {});
    ~SettingsBar();
    SettingsBar(const SettingsBar&) = delete;
    SettingsBar& operator=(const SettingsBar&) = delete;

    // The Render menu's items for the settings: Width … Threads, then AA threshold.
    void add_menu_items(Fl_Menu_Bar& menu);

    // The job to render now, in an image area of area_w × area_h (with Fit window on, that is the
    // image's size, and the width and height fields show it).
    RenderJob job(int area_w, int area_h);
    // The settings as the tool bar shows them (what is remembered between runs).
    RenderJob shown() const;
    bool fit() const;
    int threads() const;  // the BVH build uses the render's threads
    // How the picture is shown: the Render menu's View transform; a mode chosen gives the mode's
    // (sRGB for path, linear for the others) unless the user chose one.
    ViewTransform view() const { return view_; }
    void set_view(ViewTransform view);  // the user's choice (the command line's or the menu's)

    // The Stop button is active while a job loads or renders.
    void set_busy(bool busy);
    // Every tool at the size it was made at, left to right under the menu bar; those that do not
    // fit a window `window_w` wide are hidden (they come last, so the ones shown never move).
    void layout(int window_w);
    // For the ready file: a line "tool ID X Y W H shown|hidden" per tool, in root coordinates of a
    // window at (wx, wy), x and w including the tool's label; then "setting ID VALUE" per setting.
    void describe(std::ostream& out, int wx, int wy) const;

    // Where the keys go when a field is done with them (the image, whose keys are the view's): a
    // key that is not part of a number (a view key such as + or F), Enter, and the setting being
    // applied (typing has paused) end the editing of a field.
    void set_focus_home(Fl_Widget* home) { focus_home_ = home; }

    std::function<void()> on_render;  // the Render button, a new AA threshold: render now
    std::function<void()> on_stop;    // the Stop button
    std::function<void()> on_change;  // a tool changed: once the typing or clicking has paused
    std::function<void()> on_view;    // the view transform changed: show the picture through it

private:
    static void changed_cb(Fl_Widget*, void* self);
    static void settled_cb(void* self);
    void changed();
    void ask_aa_threshold();
    void apply_mode_defaults();  // the chosen mode's samples and depth where the user set none
    bool editing() const;  // the keyboard focus is in one of the spinners
    static int dispatch(int event, Fl_Window* window);

    void show_view();  // the menu's radio items, the view's notice
    RenderJob base_;  // what the tools do not show comes from here
    ViewTransform view_ = ViewTransform::Linear;
    Fl_Menu_Bar* menu_ = nullptr;
    std::set<std::string> given_;  // settings the user chose (command line or these tools)
    Fl_Button *render_ = nullptr, *stop_ = nullptr;
    Fl_Spinner *width_ = nullptr, *height_ = nullptr, *depth_ = nullptr, *aa_ = nullptr, *spp_ = nullptr,
               *threads_ = nullptr;
    Fl_Check_Button* fit_ = nullptr;
    Fl_Choice* mode_ = nullptr;
    // The tools, left to right, with the size each was made at: layout() keeps it.
    struct Tool {
        Fl_Widget* widget;
        const char* id;          // names it in the ready file
        int gap, label_w, w, h;  // space before it, then its label (drawn to its left), then the widget
    };
    std::vector<Tool> tools_;
    Fl_Widget* focus_home_ = nullptr;
    static SettingsBar* active_;  // the one whose keys dispatch() looks at
};

}  // namespace whitted::viewer
