#include "pixel_inspection.h"

#include <cstdio>

#include <FL/fl_ask.H>

#include "inspector_window.h"

namespace whitted::viewer {

PixelInspection::PixelInspection(const RenderController& controller) : controller_(controller) {}
PixelInspection::~PixelInspection() = default;

InspectorWindow& PixelInspection::window() {
    if (!window_) window_ = std::make_unique<InspectorWindow>();
    return *window_;
}

// Showing the inspector's window for the first time hands events to the image meanwhile (the
// pointer is over it, Shift still held): they must not inspect again while this one is under way,
// or each would show the window again, recursing until the stack runs out.
void PixelInspection::inspect(int x, int y) {
    if (busy_) return;
    busy_ = true;
    InspectorWindow& w = window();
    w.show_result(inspect_shown_pixel(controller_, x, y));
    if (!w.shown()) w.show();
    busy_ = false;
}

void PixelInspection::ask() {
    const RenderController::Shown shown = controller_.shown();
    InspectorWindow& w = window();
    w.show();
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

}  // namespace whitted::viewer
