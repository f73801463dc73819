// The viewer's hooks for tests and scripts: the screenshot, the ready file, exit when done.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/fl_draw.H>
#include <FL/x.H>

#include "camera_text.h"
#include "film/image_io.h"
#include "viewer_window.h"

namespace whitted::viewer {

namespace fs = std::filesystem;

// The first render has ended and has been on screen for a moment: screenshot, ready file, exit.
void ViewerWindow::when_done() {
    Fl::flush();
    XSync(fl_display, False);
    const RenderStatus st = controller_.status();
    if ((st.state == RenderState::Failed || st.state == RenderState::MissingTextures) && options_.exit_when_done) {
        exit_code_ = 2;
        for (const auto& d : st.diagnostics) std::fprintf(stderr, "%s\n", d.str().c_str());
    }

    const Rect vis = visible_image();
    if (!options_.screenshot.empty()) {
        std::string err;
        if (vis.w <= 0 || vis.h <= 0 || (!view_->overlay.empty() && !view_->dimmed)) {
            err = "no image is shown";
        } else {
            make_current();
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
    if (options_.exit_when_done) quit();
}

// The visible part of the image, in window coordinates.
ViewerWindow::Rect ViewerWindow::visible_image() const {
    const int ix = view_->image_x(), iy = view_->image_y();
    const double s = view_->scale();
    const int x0 = std::max(ix, view_->x()), y0 = std::max(iy, view_->y());
    const int x1 = std::min(ix + int(std::ceil(view_->image.width * s)), view_->x() + view_->w());
    const int y1 = std::min(iy + int(std::ceil(view_->image.height * s)), view_->y() + view_->h());
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

// For tests and scripts. Geometry in root-window coordinates (where a screen grab finds things);
// the area is where the image is shown (Fit window renders at its size); a tool's x and w include
// its label; a field "needs" the width its text takes, and its label is as given to FLTK ("@@" for '@').
void ViewerWindow::write_ready_file() {
    // The status of the last poll, whose image, status bar and messages are what the window
    // shows; the controller may have moved on since (a small render can end in between).
    const RenderStatus& st = shown_;
    const Rect vis = visible_image();
    const std::string tmp = options_.ready_file + ".tmp";
    {
        std::ofstream out(tmp);
        out << "job " << st.job << " " << (st.scene_reused ? "reused" : "loaded") << "\n"
            << "state " << state_name(st.state) << "\n"
            << "window " << x() << " " << y() << " " << w() << " " << h() << "\n"
            << "area " << x() + view_->x() << " " << y() + view_->y() << " " << view_->w() << " "
            << view_->h() << "\n"
            << "image " << x() + vis.x << " " << y() + vis.y << " " << vis.w << " " << vis.h << "\n"
            << "watch_ticks " << watch_ticks_ << "\n"
            << "zoom " << view_->scale() << (view_->fitting() ? " fit" : "") << "\n"
            << "dimmed " << (view_->dimmed ? 1 : 0) << "\n"
            << "exposure " << view_->exposure() << "\n";
        if (const std::optional<CameraDesc> cam = current_camera())
            out << "camera " << (camera_ ? "moved " : "file ") << camera_block(*cam) << "\n";
        for (const std::string& r : recent_) out << "recent " << r << "\n";
        for (const Tool& t : tools_) {
            const Fl_Widget* tw = t.widget;
            out << "tool " << t.id << " " << x() + tw->x() - t.label_w << " " << y() + tw->y() << " "
                << t.label_w + tw->w() << " " << tw->h() << " " << (tw->visible() ? "shown" : "hidden") << "\n";
        }
        const std::pair<const char*, const Fl_Box*> fields[] = {
            {"scene", scene_box_}, {"progress", progress_box_}, {"message", message_box_}};
        for (const auto& [name, b] : fields) {
            int tw = 0, th = 0;
            b->measure_label(tw, th);
            out << "field " << name << " " << x() + b->x() << " " << y() + b->y() << " " << b->w() << " " << b->h()
                << " needs " << tw << " label " << (b->label() ? b->label() : "") << "\n";
        }
        for (const std::string& line : message_lines_) out << "panel " << line.substr(1) << "\n";  // after its style
    }
    std::error_code ec;
    fs::rename(tmp, options_.ready_file, ec);
}

void ViewerWindow::ready_cb(void* self) {
    auto* win = static_cast<ViewerWindow*>(self);
    Fl::flush();  // what the file describes is on screen
    XSync(fl_display, False);
    win->write_ready_file();
}

// After the first render has been reported, a render that ends, a new layout or new messages are
// reported too (once they have settled: a resize by dragging comes as many).
void ViewerWindow::rewrite_ready_file_soon() {
    if (!ready_written_) return;
    Fl::remove_timeout(ready_cb, this);
    Fl::add_timeout(0.3, ready_cb, this);
}

}  // namespace whitted::viewer
