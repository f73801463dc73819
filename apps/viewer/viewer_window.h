#pragma once
// The viewer's main window (FLTK 1.3). Everything here runs on the UI thread; rendering happens in
// the RenderController's threads, which this window polls ten times a second.
#include <map>
#include <optional>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <FL/Fl_Double_Window.H>

#include "image_view.h"
#include "messages_view.h"
#include "render_controller.h"

class Fl_Menu_Bar;
class Fl_Button;
class Fl_Spinner;
class Fl_Check_Button;
class Fl_Choice;
class Fl_Box;
class Fl_Text_Display;
class Fl_Text_Buffer;
class Fl_Value_Slider;

namespace whitted::viewer {

class InspectorWindow;  // [inspector]

struct ViewerOptions {
    std::string scene;                       // "" = start empty
    RenderJob settings;
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
    void ask_time();  // Render ▸ Scene time: asks for t, then renders
    void inspect(int x, int y);  // [inspector] shows the report of image pixel (x, y) (inspector_window.cpp)
    void ask_inspect();          // [inspector] Render ▸ Inspect pixel: asks for X,Y
    void open_message_line(const std::string& line);  // a double-clicked message: its FILE:LINE in the editor
    void quit();
    int exit_code() const { return exit_code_; }
    bool quitting() const { return quitting_; }

    void resize(int x, int y, int w, int h) override;
    int handle(int event) override;

    // The camera: moved on the image, back to the file's (Home), into the text.
    void home();
    void copy_camera();
    void save_camera_into_scene();
    void fly_key(char key);
    enum class Zoom { Fit, One, In, Out };
    void zoom_view(Zoom how);
    void change_exposure(int stops);  // 0 = back to 0
    void ask_aa_threshold();

private:
    static void poll_cb(void* self);
    static void watch_cb(void* self);
    static void done_cb(void* self);
    static void fit_cb(void* self);
    void poll();
    void watch();
    void fit_to_area();
    void when_done();
    void layout();
    void layout_toolbar();
    void layout_status();
    void build_menus();
    void build_toolbar();
    void connect_view();
    void render_view();  // renders with the camera on screen, coarse frames first
    std::optional<CameraDesc> current_camera() const;  // the one on screen, if known
    void show_shortcuts();
    void remember();  // recent files, window size and settings into the preferences
    void add_recent(const std::string& path);
    void rebuild_recent_menu();
    void load_preferences();
    void settings_changed();
    static void settings_cb(void* self);
    std::string watch_stamp() const;  // the scene file's and its textures' stamps
    std::string relative_to_scene(std::string text) const;
    void read_controls(RenderJob& settings, bool& fit);
    void update_status(const RenderStatus& st);
    void show_messages(const RenderStatus& st);
    void ask_for_textures(const RenderStatus& st);
    void choose_and_open();
    void save_image_as();
    LoadOptions load_options() const;
    void set_message(const std::string& text);
    std::string scene_dir() const;
    struct Rect {
        int x, y, w, h;
    };
    Rect visible_image() const;
    static void ready_cb(void* self);
    void write_ready_file();
    void rewrite_ready_file_soon();

    ViewerOptions options_;
    RenderController controller_;

    Fl_Menu_Bar* menu_ = nullptr;
    Fl_Button *render_button_ = nullptr, *stop_button_ = nullptr;
    Fl_Spinner *width_ = nullptr, *height_ = nullptr, *depth_ = nullptr, *aa_ = nullptr, *spp_ = nullptr, *threads_ = nullptr;
    Fl_Check_Button* fit_ = nullptr;
    Fl_Choice* mode_ = nullptr;
    // The tool bar's widgets, left to right, with the size each was made at: layout() keeps it.
    struct Tool {
        Fl_Widget* widget;
        const char* id;  // names it in the ready file
        int gap, label_w, w, h;  // space before it, then its label (drawn to its left), then the widget
    };
    std::vector<Tool> tools_;
    ImageView* view_ = nullptr;
    MessagesView* messages_ = nullptr;
    Fl_Text_Buffer *message_text_ = nullptr, *message_styles_ = nullptr;
    Fl_Box *scene_box_ = nullptr, *progress_box_ = nullptr, *message_box_ = nullptr, *pixel_box_ = nullptr;
    bool show_messages_ = false;

    std::string scene_;
    std::string watched_stamp_;
    int watch_ticks_ = 0;  // times the watch timer has fired (and, with --watch, checked the file)
    std::uint64_t image_version_ = 0;
    std::uint64_t shown_diagnostics_job_ = ~0ull, asked_textures_job_ = 0, first_job_ = 0, ended_job_ = 0;
    int area_w_ = 0, area_h_ = 0;  // the image area's size at the last layout
    std::vector<std::string> diagnostic_lines_, message_lines_;  // of the last load; in the panel now
    RenderStatus shown_;  // the status the window was last brought up to date with (poll)
    bool done_handled_ = false;
    bool ready_written_ = false;
    bool quitting_ = false;
    std::string extra_message_;  // a message of the viewer's own (e.g. a failed save)
    int exit_code_ = 0;
    std::unique_ptr<InspectorWindow> inspector_;  // [inspector] made on first use

    // The camera on screen: none = the file's. The file's camera as written (of the last load that
    // got that far), and the camera when the current drag began.
    std::optional<CameraDesc> camera_;
    std::optional<CameraDesc> file_camera_;
    CameraDesc drag_start_;
    bool in_drag_ = false;
    std::string pixel_text_;  // the readout of the pixel under the pointer
    std::vector<std::string> recent_;  // most recent first

    // Remembered for the session: texture name as written → file the user picked; scenes for
    // which the user declined to pick (rendered with the checkerboard from then on).
    // Per scene file: the files the user picked for missing textures, and the textures they
    // declined to look for (checkerboards); remembered for the session.
    std::map<std::string, std::map<std::string, std::string>> texture_overrides_;
    std::map<std::string, std::set<std::string>> declined_textures_;
};

// Set by SIGINT/SIGTERM; the window quits cleanly at its next poll.
void request_quit_from_signal();

}  // namespace whitted::viewer
