#pragma once
// The viewer's hooks for tests and scripts: when the first render has ended and is on screen, a
// screenshot of the image as shown (--screenshot), a ready file describing the window (--ready-file;
// written again when a later render ends or the layout or messages change), and the exit
// (--exit-when-done: 0 finished, 2 scene error, 3 I/O error).
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

#include "render_controller.h"

class Fl_Window;

namespace whitted::viewer {

class ImageView;

struct ScriptOptions {
    std::string screenshot;  // save the image area's displayed pixels (fl_read_image) here,
    std::string ready_file;  // write job, state, geometry and messages here,
    bool exit_when_done = false;  // and exit.
};

class ScriptedReport {
public:
    // `describe` writes the ready file's lines; `quit` ends the program (exit_when_done).
    ScriptedReport(const ScriptOptions& options, Fl_Window& window, const ImageView& view,
                   const RenderController& controller, std::function<void(std::ostream&)> describe,
                   std::function<void()> quit);
    ~ScriptedReport();
    ScriptedReport(const ScriptedReport&) = delete;
    ScriptedReport& operator=(const ScriptedReport&) = delete;

    // Automated runs never open dialogs: a missing texture ends them like a scene error.
    bool automated() const { return !options_.screenshot.empty() || options_.exit_when_done; }
    // A job was started (the first one is the render reported).
    void job_started(std::uint64_t job);
    // The window was brought up to date with `st`. `will_ask`: it is about to ask for textures, so
    // the render has not really ended.
    void polled(const RenderStatus& st, bool will_ask);
    // Something the ready file describes changed (layout, messages, zoom): written again soon.
    void changed();
    int exit_code() const { return exit_code_; }

private:
    static void done_cb(void* self);
    static void ready_cb(void* self);
    void when_done();
    void write_ready_file();

    ScriptOptions options_;
    Fl_Window& window_;
    const ImageView& view_;
    const RenderController& controller_;
    std::function<void(std::ostream&)> describe_;
    std::function<void()> quit_;
    std::uint64_t first_job_ = 0, ended_job_ = 0;
    bool done_handled_ = false;
    bool ready_written_ = false;
    int exit_code_ = 0;
};

}  // namespace whitted::viewer
