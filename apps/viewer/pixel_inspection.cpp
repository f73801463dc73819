#include "pixel_inspection.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <FL/Fl.H>
#include <FL/Fl_Window.H>
#include <FL/fl_ask.H>

#include "image_view.h"
#include "inspector_window.h"

namespace whitted::viewer {

PixelInspection::PixelInspection(const RenderController& controller, ImageView& view)
    : controller_(controller), view_(view) {}
PixelInspection::~PixelInspection() = default;

InspectorWindow& PixelInspection::window() {
    if (!window_) {
        window_ = std::make_unique<InspectorWindow>();
        window_->on_tree = [this](bool on, int depth) {
            tree_on_ = on;
            depth_ = depth >= last_.report.ray_tree.deepest() ? -1 : depth;
            draw();
        };
    }
    return *window_;
}

// Showing the inspector's window for the first time hands events to the image meanwhile (the
// pointer is over it, Shift still held): they must not inspect again while this one is under way,
// or each would show the window again, recursing until the stack runs out.
void PixelInspection::inspect(int x, int y) {
    if (busy_) return;
    busy_ = true;
    InspectorWindow& w = window();
    last_ = inspect_shown_pixel(controller_, x, y);
    job_ = controller_.status().job;
    w.show_result(last_);
    draw();
    show(w);
    busy_ = false;
}

// The first time beside the picture (on the screen it is on), so that the image and the tree drawn
// over it stay in view: right of the main window if there is room, else in the wider of the screen's
// parts left and right of the image, narrower if it must be. Then where the user left it.
void PixelInspection::show(InspectorWindow& w) {
    if (w.shown()) return;
    const Fl_Window* main = view_.window();
    if (!placed_ && main) {
        placed_ = true;
        int sx = 0, sy = 0, sw = 0, sh = 0;
        Fl::screen_work_area(sx, sy, sw, sh, main->x() + main->w() / 2, main->y() + main->h() / 2);
        const ScreenRect vis = view_.visible();
        const int image_left = main->x() + vis.x, image_right = image_left + vis.w, gap = 8;
        int x = main->x() + main->w() + gap, width = w.w();
        if (x + width > sx + sw) {
            const int right_room = sx + sw - (image_right + gap), left_room = image_left - gap - sx;
            const bool right = right_room >= left_room;
            width = std::max(480, std::min(w.w(), right ? right_room : left_room));
            x = right ? std::min(image_right + gap, sx + sw - width) : std::max(sx, image_left - gap - width);
        }
        w.resize(x, std::clamp(main->y(), sy, std::max(sy, sy + sh - w.h())), width, w.h());
    }
    w.show();
}

void PixelInspection::ask() {
    const RenderController::Shown shown = controller_.shown();
    InspectorWindow& w = window();
    show(w);
    if (!shown.scene) return;
    const char* answer = fl_input("Pixel to inspect, X,Y (column, row; row 0 at the top):", "0,0");
    if (!answer) return;
    int x = -1, y = -1;
    char rest = 0;
    if (std::sscanf(answer, "%d,%d%c", &x, &y, &rest) != 2) {
        w.show_result(inspect_message(std::string("not a pixel: '") + answer + "' (write X,Y)"));
        return;
    }
    inspect(x, y);
}

void PixelInspection::ask_depth() {
    const int deepest = last_.report.ray_tree.deepest();
    char current[32];
    std::snprintf(current, sizeof current, "%d", !tree_on_ ? -1 : depth_ < 0 ? deepest : depth_);
    fl_message_title("Ray tree depth");  // a window named after its question (tests find it by name)
    const char* answer = fl_input("Bounces of the ray tree drawn over the image (0 to %d; -1 hides it):", current,
                                  deepest);
    if (!answer) return;
    char* end = nullptr;
    const long v = std::strtol(answer, &end, 10);
    if (end == answer || *end || v < -1) {
        fl_alert("Not a whole number from -1 up: %s", answer);
        return;
    }
    tree_on_ = v >= 0;
    depth_ = v < 0 || v >= deepest ? -1 : int(v);
    draw();
}

void PixelInspection::image_of_job(std::uint64_t job) {
    if (job == job_ || view_.rays.empty()) return;
    last_ = InspectResult{};
    draw();
}

void PixelInspection::draw() {
    const RayTree& tree = last_.report.ray_tree;
    const int deepest = tree.deepest();
    view_.rays = last_.ok && tree_on_ ? ray_overlay(tree, depth_ < 0 ? deepest : depth_) : RayOverlay{};
    view_.redraw();
    if (window_) window_->set_tree(deepest, depth_ < 0 ? deepest : depth_, tree_on_);
    if (on_drawn) on_drawn();
}

}  // namespace whitted::viewer
