#pragma once
// The viewer's main window (FLTK 1.3): it lays out the menu bar, the settings bar, the image, the
// messages panel and the status bar, and wires them to the render controller and to the parts of
// the session that have a file of their own (camera, preferences, missing textures, the watch
// timer, the pixel inspector, the scripted report). Everything here runs on the UI thread;
// rendering happens in the RenderController's threads, which this window polls ten times a second.
#include <cstdint>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include <FL/Fl_Double_Window.H>

#include "camera_session.h"
#include "preferences.h"
#include "render_controller.h"
#include "session/render_settings.h"
#include "texture_memory.h"

class Fl_Menu_Bar;

namespace whitted::viewer {

class ImageView;
class MessagesPanel;
class PixelInspection;
class ScriptedReport;
class SettingsBar;
class StatusBar;
class WatchTimer;

struct ViewerOptions {
    std::string scene;                       // "" = start empty
    RenderJob settings;
    RenderSettings render;                   // the command line's settings (its limits: --untrusted, --max-memory)
    bool fit_window = false;                 // image size follows the image area
    bool watch = false;                      // reload when the scene file changes on disk
    bool lenient = false;
    float time = 0;                          // scene time of velocity/angularrate (scene-format.md §9.4)
    bool checker_textures = false;           // never ask: draw missing textures as a checkerboard
    std::vector<std::string> texture_dirs;
    int window_width = 1000, window_height = 760;
    bool window_size_given = false;          // --window-size (else the remembered size)
    bool settings_given = false;             // a render setting on the command line (else the remembered ones)
    // For tests and scripts: after the first render ends (finished, failed or stopped) and is drawn,
    std::string screenshot;                  // save the image area's displayed pixels (fl_read_image) here,
    std::string ready_file;                  // write job, state, geometry and messages here (again when a
                                             // later render ends or the layout or messages change),
    bool exit_when_done = false;             // and exit (0 finished, 2 scene error, 3 I/O error).
};

class ViewerWindow : public Fl_Double_Window {
public:
    explicit ViewerWindow(const ViewerOptions& options);
    ~ViewerWindow() override;

    void open_scene(const std::string& path);  // and render it
    void render(bool force_reload = false);
    void stop();
    void quit();
    int exit_code() const;
    bool quitting() const { return quitting_; }

    void resize(int x, int y, int w, int h) override;
    int handle(int event) override;

    // The menus' commands (viewer_menus.cpp, viewer_dialogs.cpp).
    void choose_and_open();
    void save_image_as();
    void copy_camera();
    void save_camera_into_scene();
    void ask_time();  // Render ▸ Scene time: asks for t, then renders
    void home();
    void fly_key(char key);
    enum class Zoom { Fit, One, In, Out };
    void zoom_view(Zoom how);
    void change_exposure(int stops);  // 0 = back to 0
    void open_message_line(const std::string& line);  // a double-clicked message: its FILE:LINE in the editor

private:
    static void poll_cb(void* self);
    static void fit_cb(void* self);
    void build_menus();
    void connect_view();
    void layout();
    void poll();
    void show_failure(const RenderStatus& st);  // the banner over the (dimmed) last good image
    void fit_to_area();
    void render_view();  // renders with the camera on screen, coarse frames first
    void ask_for_textures(const RenderStatus& st);
    void remember();  // recent files, window size and (if the user chose them here) settings into the preferences
    void describe(std::ostream& out) const;  // the ready file's lines
    LoadOptions load_options() const;
    void set_message(const std::string& text);
    std::string scene_dir() const;
    std::string relative_to_scene(std::string text) const;

    ViewerOptions options_;
    RenderController controller_;
    Preferences preferences_;
    CameraSession camera_;
    TextureMemory textures_;  // the user's answers about missing textures

    // Widgets (the window owns and deletes them) and the parts that make some.
    Fl_Menu_Bar* menu_ = nullptr;
    ImageView* view_ = nullptr;
    std::unique_ptr<SettingsBar> settings_;
    std::unique_ptr<MessagesPanel> messages_;
    std::unique_ptr<StatusBar> status_;
    std::unique_ptr<PixelInspection> inspection_;
    std::unique_ptr<WatchTimer> watch_;
    std::unique_ptr<ScriptedReport> report_;

    std::string scene_;
    std::uint64_t image_version_ = 0;
    std::uint64_t asked_textures_job_ = 0;
    int area_w_ = 0, area_h_ = 0;  // the image area's size at the last layout
    RenderStatus shown_;  // the status the window was last brought up to date with (poll)
    bool quitting_ = false;
    float exposure_ = 0.0f;  // stops: the picture's linear values times 2^exposure_, then the view transform
    bool settings_chosen_ = false;  // the settings are the user's (recalled, or changed in the window): saved on quit
    std::string extra_message_;  // a message of the viewer's own (e.g. a failed save)
};

// Set by SIGINT/SIGTERM; the window quits cleanly at its next poll.
void request_quit_from_signal();

}  // namespace whitted::viewer
