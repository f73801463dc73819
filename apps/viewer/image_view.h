#pragma once
// The image area of the viewer: shows the image (row 0 at the top) zoomed and panned, dimmed under
// an error banner when the scene no longer loads, and turns mouse gestures on it into calls the
// window sets: camera drags, the wheel, the pixel under the cursor, and inspect clicks.
#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <FL/Fl_Widget.H>

#include "film/image.h"
#include "ray_overlay.h"

namespace whitted::viewer {

// A rectangle in window coordinates.
struct ScreenRect {
    int x = 0, y = 0, w = 0, h = 0;
};

class ImageView : public Fl_Widget {
public:
    ImageView(int x, int y, int w, int h);

    Image image;
    // Lines drawn over the image in a banner (an error: the image stays, dimmed), or over a blank
    // area when there is no image yet. The first line is the title.
    std::vector<std::string> overlay;
    bool dimmed = false;
    // Drawn over the image: the inspected pixel's ray tree (image pixel coordinates).
    RayOverlay rays;

    // Camera gestures. Drag kinds: Orbit (left drag), Pan (middle drag, Shift + left drag).
    enum class Drag { Orbit, Pan };
    // The displacement (dx right, dy down, in screen pixels) since the button went down, at every
    // motion of a drag that moved at least kClickSlop pixels; end = the button is released.
    std::function<void(Drag kind, int dx, int dy, bool end)> on_camera_drag;
    // Wheel clicks (positive = away from the user: closer, narrower); fov = Ctrl was held.
    std::function<void(int steps, bool fov)> on_wheel;
    // The image pixel under the pointer (row 0 at the top), or (-1, -1) when it is off the image.
    std::function<void(int x, int y)> on_hover;
    // The inspect gestures: a left click without drag, or moving with Shift held (image pixel
    // coordinates, row 0 at the top, after zoom and pan). Unset = nothing happens.
    std::function<void(int x, int y)> on_inspect;
    // A key pressed while the image has the keyboard focus; returns whether it was used.
    std::function<bool(int key)> on_key;
    static constexpr int kClickSlop = 4;

    // Zoom: 1:1 (the default), fit (the whole image in the area), or 1/16 .. 16 times, nearest
    // neighbour. Zooming keeps the pixel at the centre of the area where it is.
    void zoom_fit();
    void zoom_one();
    void zoom_by(int steps);  // each step doubles (or halves) the magnification
    double scale() const;     // screen pixels per image pixel now
    bool fitting() const { return fit_; }

    // The image's top-left corner in window coordinates (may lie outside the widget).
    int image_x() const;
    int image_y() const;
    // The part of the image that is visible, in window coordinates (empty without an image).
    ScreenRect visible() const;
    // The window point where image point p (image pixel coordinates, not rounded) is shown.
    glm::vec2 to_window(const glm::vec2& p) const;
    // The image pixel shown at window point (wx, wy); false when the point is off the image.
    bool to_image(int wx, int wy, int& ix, int& iy) const;

    void draw() override;
    int handle(int event) override;
    void resize(int x, int y, int w, int h) override;

private:
    void clamp_pan();
    void draw_rays() const;
    bool fit_ = false;
    double zoom_ = 1.0;            // when not fitting
    double pan_x_ = 0, pan_y_ = 0;  // offset of the image's centre from the area's centre, screen px
    std::array<std::uint8_t, 256> lut_{};
    std::vector<std::uint8_t> buffer_;  // the pixels of the area as drawn
    // The press that started the current gesture.
    int button_ = 0, press_x_ = 0, press_y_ = 0;
    bool shift_at_press_ = false, dragging_ = false;
    double pan_at_press_x_ = 0, pan_at_press_y_ = 0;
    int hover_x_ = -1, hover_y_ = -1;  // the pixel inspected last (-1: none since the pointer came)
};

}  // namespace whitted::viewer
