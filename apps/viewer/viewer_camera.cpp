// The viewer window's camera: gestures on the image move it (camera_navigation.h), every move
// renders coarse frames first; Home goes back to the file's camera. Also the image view's zoom,
// exposure and pixel readout, and re-rendering when a setting changes.
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/fl_ask.H>

#include "camera_navigation.h"
#include "flatten/flatten.h"
#include "viewer_window.h"

namespace whitted::viewer {

std::optional<CameraDesc> ViewerWindow::current_camera() const {
    if (camera_) return camera_;
    return file_camera_;
}

void ViewerWindow::connect_view() {
    view_->on_camera_drag = [this](ImageView::Drag kind, int dx, int dy, bool end) {
        if (!in_drag_) {
            const std::optional<CameraDesc> c = current_camera();
            if (!c) return;  // nothing loaded yet
            drag_start_ = navigable(*c);
            in_drag_ = true;
        }
        if (kind == ImageView::Drag::Orbit) {
            camera_ = orbit(drag_start_, float(dx), float(dy));
        } else {  // screen pixels to image pixels, so that the scene follows the mouse
            const double s = view_->scale();
            camera_ = pan(drag_start_, float(dx / s), float(dy / s), std::max(1, view_->image.height));
        }
        if (end) in_drag_ = false;
        render_view();
    };
    view_->on_wheel = [this](int steps, bool fov) {
        const std::optional<CameraDesc> c = current_camera();
        if (!c) return;
        camera_ = fov ? change_fov(navigable(*c), float(steps)) : dolly(navigable(*c), float(steps));
        render_view();
    };
    view_->on_hover = [this](int x, int y) {
        std::string text;
        if (x >= 0 && y >= 0 && x < view_->image.width && y < view_->image.height) {
            const glm::u8vec3 p = view_->image.at(x, y);
            char buf[96];
            std::snprintf(buf, sizeof buf, "x %d  y %d   RGB %d %d %d", x, y, p.x, p.y, p.z);
            text = buf;
        }
        if (text == pixel_text_) return;
        pixel_text_ = text;
        pixel_box_->copy_label((" " + text).c_str());
        layout_status();
    };
    // view_->on_inspect stays unset here: the pixel inspector connects to it.
}

// Renders with the camera on screen: coarse frames at once, the previous frame cancelled.
void ViewerWindow::render_view() {
    if (scene_.empty()) return;
    RenderJob s = options_.settings;
    bool fit = false;
    read_controls(s, fit);
    if (camera_) s.camera = make_camera(*camera_);
    controller_.start(scene_, load_options(), s, false, /*coarse_first=*/true);
    if (first_job_ == 0) first_job_ = controller_.status().job;
}

void ViewerWindow::home() {
    if (!camera_) return;
    camera_.reset();  // the file's camera: the very image of the file
    render_view();
}

void ViewerWindow::fly_key(char key) {
    const std::optional<CameraDesc> c = current_camera();
    if (!c) return;
    camera_ = fly(navigable(*c), key);
    render_view();
}

void ViewerWindow::change_exposure(int stops) {
    view_->set_exposure(stops == 0 ? 0.0f : view_->exposure() + float(stops));
    char buf[64];
    std::snprintf(buf, sizeof buf, "exposure %+g stops", double(view_->exposure()));
    set_message(buf);
    rewrite_ready_file_soon();
}

// A tool bar setting changed: render again once the user has stopped typing or clicking.
void ViewerWindow::settings_changed() {
    Fl::remove_timeout(settings_cb, this);
    if (!scene_.empty()) Fl::add_timeout(0.4, settings_cb, this);
}

void ViewerWindow::settings_cb(void* self) { static_cast<ViewerWindow*>(self)->render(); }

// Render ▸ AA threshold (--aa-threshold): adaptive anti-aliasing, 0 = every pixel.
void ViewerWindow::ask_aa_threshold() {
    char current[32];
    std::snprintf(current, sizeof current, "%g", double(options_.settings.sampling.aa_threshold));
    const char* answer = fl_input("Adaptive anti-aliasing threshold, 0 to 1 (0: every pixel gets AA x AA rays; "
                                  "takes effect with AA > 1 and SPP 1):", current);
    if (!answer) return;
    char* end = nullptr;
    const float t = std::strtof(answer, &end);
    if (end == answer || *end || !std::isfinite(t) || t < 0.0f || t > 1.0f) {
        fl_alert("Not a number from 0 to 1: %s", answer);
        return;
    }
    options_.settings.sampling.aa_threshold = t;
    render();
}

}  // namespace whitted::viewer
