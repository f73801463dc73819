#pragma once
// The status bar: the scene (and what was loaded), the render's progress, the last message
// (errors red, warnings yellow) and, while the pointer is on the image, the pixel under it. Each
// field is as wide as its text (the message takes the rest); a field too narrow for its text clips
// it, and its tooltip has it all.
#include <iosfwd>
#include <string>

class Fl_Box;

namespace whitted::viewer {

struct RenderStatus;

class StatusBar {
public:
    // Makes its fields in the current group (the window's).
    StatusBar();

    // Brings the fields up to date: the scene's path ("" = none), the render's status, and the
    // message to show (paths already relative to the scene). Lays them out again if any changed.
    void update(const std::string& scene, const RenderStatus& st, const std::string& message);
    // The readout of the pixel under the pointer ("" = off the image).
    void set_pixel(const std::string& text);

    // Across a window `window_w` wide, at height y.
    void layout(int y, int window_w);
    // For the ready file: "field NAME X Y W H needs TEXT_W label LABEL" per field, in root
    // coordinates of a window at (wx, wy); the label as given to FLTK ("@@" for '@').
    void describe(std::ostream& out, int wx, int wy) const;

private:
    void relayout();

    Fl_Box *scene_ = nullptr, *progress_ = nullptr, *message_ = nullptr, *pixel_ = nullptr;
    std::string pixel_text_;
    int y_ = 0, window_w_ = 0;
};

}  // namespace whitted::viewer
