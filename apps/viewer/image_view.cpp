#include "image_view.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include <FL/Fl.H>
#include <FL/fl_draw.H>

namespace whitted::viewer {

ImageView::ImageView(int x, int y, int w, int h) : Fl_Widget(x, y, w, h) {
    box(FL_FLAT_BOX);
    color(fl_rgb_color(48, 48, 48));
    // Takes the keyboard (its keys are the view's: the menus' shortcuts); draw() draws no focus
    // box. (Without visible focus FLTK would never give it the focus: Fl::focus() ignores such a widget.)
    visible_focus(1);
    for (int i = 0; i < 256; ++i) lut_[std::size_t(i)] = std::uint8_t(i);
}

double ImageView::scale() const {
    if (!fit_) return zoom_;
    if (image.width <= 0 || image.height <= 0) return 1.0;
    return std::clamp(std::min(double(w()) / image.width, double(h()) / image.height), 1.0 / 16, 16.0);
}

void ImageView::zoom_fit() {
    fit_ = true;
    pan_x_ = pan_y_ = 0;
    redraw();
}

void ImageView::zoom_one() {
    fit_ = false;
    zoom_ = 1.0;
    pan_x_ = pan_y_ = 0;
    redraw();
}

void ImageView::zoom_by(int steps) {
    const double before = scale();
    const double after = std::clamp(std::exp2(std::round(std::log2(before)) + steps), 1.0 / 16, 16.0);
    // The image point at the area's centre stays there.
    pan_x_ *= after / before;
    pan_y_ *= after / before;
    fit_ = false;
    zoom_ = after;
    clamp_pan();
    redraw();
}

// The image stays at least partly in view.
void ImageView::clamp_pan() {
    const double s = scale();
    const double lim_x = (image.width * s + w()) / 2.0 - 16, lim_y = (image.height * s + h()) / 2.0 - 16;
    pan_x_ = std::clamp(pan_x_, -std::max(0.0, lim_x), std::max(0.0, lim_x));
    pan_y_ = std::clamp(pan_y_, -std::max(0.0, lim_y), std::max(0.0, lim_y));
}

// Centred (whole pixels, as before zooming existed: a 1:1 image is drawn byte for byte).
int ImageView::image_x() const {
    return x() + int(std::floor((w() - image.width * scale()) / 2.0 + pan_x_));
}
int ImageView::image_y() const {
    return y() + int(std::floor((h() - image.height * scale()) / 2.0 + pan_y_));
}

bool ImageView::to_image(int wx, int wy, int& ix, int& iy) const {
    const double s = scale();
    ix = int(std::floor((wx - image_x()) / s));
    iy = int(std::floor((wy - image_y()) / s));
    return image.width > 0 && ix >= 0 && iy >= 0 && ix < image.width && iy < image.height;
}

glm::vec2 ImageView::to_window(const glm::vec2& p) const {
    const double s = scale();
    return {float(image_x() + p.x * s), float(image_y() + p.y * s)};
}

// The ray tree over the image: lines two pixels wide, marks outlined in black so that they show on
// any colour. Inside the visible image only.
void ImageView::draw_rays() const {
    if (rays.empty() || image.width <= 0) return;
    const ScreenRect vis = visible();
    fl_push_clip(vis.x, vis.y, vis.w, vis.h);
    fl_line_style(FL_SOLID | FL_CAP_ROUND, 2);
    for (const OverlayLine& l : rays.lines) {
        const glm::vec2 a = to_window(l.a), b = to_window(l.b);
        fl_color(l.color.x, l.color.y, l.color.z);
        fl_line(int(std::floor(a.x)), int(std::floor(a.y)), int(std::floor(b.x)), int(std::floor(b.y)));
    }
    fl_line_style(FL_SOLID, 1);
    for (const OverlayMark& m : rays.marks) {
        const glm::vec2 c = to_window(m.at);
        const int x = int(std::floor(c.x)), y = int(std::floor(c.y));
        switch (m.shape) {
            case MarkShape::Hit:
                fl_color(m.color.x, m.color.y, m.color.z);
                fl_rectf(x - 2, y - 2, 5, 5);
                fl_color(FL_BLACK);
                fl_rect(x - 3, y - 3, 7, 7);
                break;
            case MarkShape::Blocked:
                fl_line_style(FL_SOLID, 2);
                fl_color(m.color.x, m.color.y, m.color.z);
                fl_line(x - 4, y - 4, x + 4, y + 4);
                fl_line(x - 4, y + 4, x + 4, y - 4);
                fl_line_style(FL_SOLID, 1);
                break;
            case MarkShape::Light:
                fl_color(m.color.x, m.color.y, m.color.z);
                fl_pie(x - 4, y - 4, 9, 9, 0, 360);
                fl_color(FL_BLACK);
                fl_arc(x - 4, y - 4, 9, 9, 0, 360);
                break;
            case MarkShape::TotalInternalReflection:
                fl_color(m.color.x, m.color.y, m.color.z);
                fl_polygon(x, y - 6, x + 6, y, x, y + 6, x - 6, y);
                fl_color(FL_BLACK);
                fl_loop(x, y - 6, x + 6, y, x, y + 6, x - 6, y);
                break;
        }
    }
    fl_line_style(0);
    fl_pop_clip();
}

ScreenRect ImageView::visible() const {
    const int ix = image_x(), iy = image_y();
    const double s = scale();
    const int x0 = std::max(ix, x()), y0 = std::max(iy, y());
    const int x1 = std::min(ix + int(std::ceil(image.width * s)), x() + w());
    const int y1 = std::min(iy + int(std::ceil(image.height * s)), y() + h());
    return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

void ImageView::resize(int X, int Y, int W, int H) {
    Fl_Widget::resize(X, Y, W, H);
    clamp_pan();
}

void ImageView::draw() {
    fl_push_clip(x(), y(), w(), h());
    fl_color(color());
    fl_rectf(x(), y(), w(), h());
    const bool have_image = image.width > 0 && image.height > 0;
    if (have_image) {
        // The visible part of the image, in window coordinates; each screen pixel shows the image
        // pixel under its top-left corner (nearest neighbour), dimmed through the table.
        const double s = scale();
        const int ix = image_x(), iy = image_y();
        const int x0 = std::max(x(), ix), y0 = std::max(y(), iy);
        const int x1 = std::min(x() + w(), ix + int(std::ceil(image.width * s)));
        const int y1 = std::min(y() + h(), iy + int(std::ceil(image.height * s)));
        if (x1 > x0 && y1 > y0) {
            const int bw = x1 - x0, bh = y1 - y0;
            buffer_.resize(std::size_t(bw) * bh * 3);
            std::array<std::uint8_t, 256> lut = lut_;
            if (dimmed)
                for (auto& v : lut) v = std::uint8_t(v * 2 / 5);
            std::vector<int> src_x(std::size_t(bw), 0);
            for (int sx = 0; sx < bw; ++sx)
                src_x[std::size_t(sx)] = std::min(image.width - 1, int(std::floor((x0 + sx - ix) / s)));
            for (int sy = 0; sy < bh; ++sy) {
                const int row = std::min(image.height - 1, int(std::floor((y0 + sy - iy) / s)));
                const std::uint8_t* src = &image.rgb[std::size_t(row) * image.width * 3];
                std::uint8_t* dst = &buffer_[std::size_t(sy) * bw * 3];
                for (int sx = 0; sx < bw; ++sx) {
                    const std::uint8_t* p = src + std::size_t(src_x[std::size_t(sx)]) * 3;
                    dst[sx * 3] = lut[p[0]];
                    dst[sx * 3 + 1] = lut[p[1]];
                    dst[sx * 3 + 2] = lut[p[2]];
                }
            }
            fl_draw_image(buffer_.data(), x0, y0, bw, bh, 3, 0);
        }
    }
    if (have_image) draw_rays();
    if (!overlay.empty()) {
        // A banner at the top of the area: the image (if any) stays visible, dimmed, below it.
        fl_font(FL_HELVETICA, 14);
        const int line = fl_height() + 4;
        const int banner_h = std::min(h(), 12 + line * int(overlay.size()));
        if (have_image) {
            fl_color(fl_rgb_color(70, 20, 20));
            fl_rectf(x(), y(), w(), banner_h);
        }
        const int top = y() + 6 + fl_height() - fl_descent();
        for (std::size_t i = 0; i < overlay.size(); ++i) {
            fl_color(i == 0 ? FL_WHITE : fl_rgb_color(255, 140, 120));
            fl_draw(overlay[i].c_str(), x() + 12, top + int(i) * line);
        }
    }
    fl_pop_clip();
}

int ImageView::handle(int event) {
    switch (event) {
        case FL_FOCUS:
        case FL_UNFOCUS:
            return 1;
        case FL_ENTER:
            return 1;  // to get FL_MOVE
        case FL_LEAVE:
            hover_x_ = hover_y_ = -1;
            if (on_hover) on_hover(-1, -1);
            return 1;
        case FL_MOVE: {
            int ix = -1, iy = -1;
            const bool on = to_image(Fl::event_x(), Fl::event_y(), ix, iy);
            if (on_hover) on ? on_hover(ix, iy) : on_hover(-1, -1);
            // Shift+hover inspects a pixel other than the one shown (a window appearing sends moves that
            // did not move).
            if (on && (Fl::event_state() & FL_SHIFT) && on_inspect && (ix != hover_x_ || iy != hover_y_)) {
                hover_x_ = ix;
                hover_y_ = iy;
                on_inspect(ix, iy);
            }
            return 1;
        }
        case FL_PUSH:
            if (Fl::focus() != this) take_focus();  // the keys are the view's again
            button_ = Fl::event_button();
            press_x_ = Fl::event_x();
            press_y_ = Fl::event_y();
            shift_at_press_ = Fl::event_state() & FL_SHIFT;
            dragging_ = false;
            pan_at_press_x_ = pan_x_;
            pan_at_press_y_ = pan_y_;
            return 1;
        case FL_DRAG: {
            const int dx = Fl::event_x() - press_x_, dy = Fl::event_y() - press_y_;
            if (!dragging_ && std::abs(dx) < kClickSlop && std::abs(dy) < kClickSlop) return 1;
            dragging_ = true;
            if (button_ == FL_RIGHT_MOUSE) {  // moves the picture, not the camera
                pan_x_ = pan_at_press_x_ + dx;
                pan_y_ = pan_at_press_y_ + dy;
                clamp_pan();
                redraw();
            } else if (on_camera_drag) {
                const bool pan = button_ == FL_MIDDLE_MOUSE || (button_ == FL_LEFT_MOUSE && shift_at_press_);
                on_camera_drag(pan ? Drag::Pan : Drag::Orbit, dx, dy, false);
            }
            int ix = -1, iy = -1;
            if (on_hover) to_image(Fl::event_x(), Fl::event_y(), ix, iy) ? on_hover(ix, iy) : on_hover(-1, -1);
            return 1;
        }
        case FL_RELEASE: {
            const int dx = Fl::event_x() - press_x_, dy = Fl::event_y() - press_y_;
            if (dragging_) {
                if (button_ != FL_RIGHT_MOUSE && on_camera_drag) {
                    const bool pan = button_ == FL_MIDDLE_MOUSE || (button_ == FL_LEFT_MOUSE && shift_at_press_);
                    on_camera_drag(pan ? Drag::Pan : Drag::Orbit, dx, dy, true);
                }
            } else if (button_ == FL_LEFT_MOUSE) {
                int ix = -1, iy = -1;
                if (to_image(press_x_, press_y_, ix, iy) && on_inspect) {
                    hover_x_ = ix;
                    hover_y_ = iy;
                    on_inspect(ix, iy);
                }
            }
            dragging_ = false;
            button_ = 0;
            return 1;
        }
        case FL_MOUSEWHEEL: {
            const int dy = Fl::event_dy();
            if (dy == 0 || !on_wheel) return 0;
            on_wheel(-dy, (Fl::event_state() & FL_CTRL) != 0);
            return 1;
        }
        case FL_KEYBOARD:
            return on_key && on_key(Fl::event_key()) ? 1 : 0;
        default:
            return Fl_Widget::handle(event);
    }
}

}  // namespace whitted::viewer
