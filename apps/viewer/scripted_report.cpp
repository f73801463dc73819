#include "scripted_report.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include <FL/Fl.H>
#include <FL/Fl_Window.H>
#include <FL/fl_draw.H>
#include <FL/x.H>

#include "film/image_io.h"
#include "image_view.h"

namespace whitted::viewer {

namespace fs = std::filesystem;

ScriptedReport::ScriptedReport(const ScriptOptions& options, Fl_Window& window, const ImageView& view,
                               const RenderController& controller, std::function<void(std::ostream&)> describe,
                               std::function<void()> quit)
    : options_(options), window_(window), view_(view), controller_(controller), describe_(std::move(describe)),
      quit_(std::move(quit)) {}

ScriptedReport::~ScriptedReport() {
    Fl::remove_timeout(done_cb, this);
    Fl::remove_timeout(ready_cb, this);
}

void ScriptedReport::job_started(std::uint64_t job) {
    if (first_job_ == 0) first_job_ = job;
}

void ScriptedReport::polled(const RenderStatus& st, bool will_ask) {
    // Every render that ends is reported, not only the first (e.g. after --watch reloads).
    if (!is_busy(st.state) && st.job != ended_job_) {
        ended_job_ = st.job;
        changed();
    }
    // The first render has ended: the hooks, once it is on screen.
    if (!done_handled_ && first_job_ != 0 && st.job >= first_job_ && !is_busy(st.state) &&
        st.state != RenderState::Idle && !will_ask) {
        if (automated() || !options_.ready_file.empty()) {
            done_handled_ = true;
            Fl::add_timeout(0.3, done_cb, this);
        }
    }
}

void ScriptedReport::done_cb(void* self) { static_cast<ScriptedReport*>(self)->when_done(); }

// The first render has ended and has been on screen for a moment: screenshot, ready file, exit.
void ScriptedReport::when_done() {
    Fl::flush();
    XSync(fl_display, False);
    const RenderStatus st = controller_.status();
    if ((st.state == RenderState::Failed || st.state == RenderState::MissingTextures) && options_.exit_when_done) {
        exit_code_ = 2;
        for (const auto& d : st.diagnostics) std::fprintf(stderr, "%s\n", d.str().c_str());
    }

    const ScreenRect vis = view_.visible();
    if (!options_.screenshot.empty()) {
        std::string err;
        if (vis.w <= 0 || vis.h <= 0 || (!view_.overlay.empty() && !view_.dimmed)) {
            err = "no image is shown";
        } else {
            window_.make_current();
            Image shot(vis.w, vis.h);
            if (!fl_read_image(shot.rgb.data(), vis.x, vis.y, shot.width, shot.height)) err = "fl_read_image failed";
            else err = write_image(shot, options_.screenshot);
        }
        if (!err.empty()) {
            std::fprintf(stderr, "whitted-view: error: screenshot: %s\n", err.c_str());
            if (exit_code_ == 0 && options_.exit_when_done) exit_code_ = 3;
        }
    }
    if (!options_.ready_file.empty()) {
        write_ready_file();
        ready_written_ = true;
    }
    if (options_.exit_when_done) quit_();
}

// Written under another name and renamed: a reader never sees half of it.
void ScriptedReport::write_ready_file() {
    const std::string tmp = options_.ready_file + ".tmp";
    {
        std::ofstream out(tmp);
        describe_(out);
    }
    std::error_code ec;
    fs::rename(tmp, options_.ready_file, ec);
}

void ScriptedReport::ready_cb(void* self) {
    Fl::flush();  // what the file describes is on screen
    XSync(fl_display, False);
    static_cast<ScriptedReport*>(self)->write_ready_file();
}

// After the first render has been reported, a render that ends, a new layout or new messages are
// reported too (once they have settled: a resize by dragging comes as many).
void ScriptedReport::changed() {
    if (!ready_written_) return;
    Fl::remove_timeout(ready_cb, this);
    Fl::add_timeout(0.3, ready_cb, this);
}

}  // namespace whitted::viewer
