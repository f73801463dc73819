#include "status_bar.h"

#include <algorithm>
#include <ostream>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/fl_draw.H>

#include "status_text.h"
#include "viewer_util.h"

namespace whitted::viewer {
namespace {

// A field of the status bar: its label (as given to FLTK, "@@" for '@') drawn as written, cut with
// an ellipsis when the field is narrower than it (its tooltip has it all).
class StatusField : public Fl_Box {
public:
    StatusField() : Fl_Box(0, 0, 10, kStatusH) {}
    void draw() override {
        draw_box();
        std::string text;
        for (const char* p = label() ? label() : ""; *p; ++p) {
            if (*p == '@' && p[1] == '@') ++p;
            text += *p;
        }
        // Where Fl_Widget::draw_label() puts a label aligned left inside.
        const int X = x() + Fl::box_dx(box()) + 3, W = w() - Fl::box_dw(box()) - 6;
        fl_font(labelfont(), labelsize());
        fl_color(active_r() ? labelcolor() : fl_inactive(labelcolor()));
        fl_push_clip(X, y(), std::max(0, W), h());
        fl_draw(fit_width(text, W).c_str(), X, y() + Fl::box_dy(box()), W, h() - Fl::box_dh(box()), align(), nullptr, 0);
        fl_pop_clip();
    }
};

}  // namespace

StatusBar::StatusBar() {
    scene_ = new StatusField();
    progress_ = new StatusField();
    message_ = new StatusField();
    pixel_ = new StatusField();
    for (Fl_Box* b : {scene_, progress_, message_, pixel_}) {
        b->box(FL_THIN_DOWN_BOX);
        b->align(FL_ALIGN_LEFT | FL_ALIGN_INSIDE | FL_ALIGN_CLIP);
        b->labelsize(13);
    }
    scene_->copy_label(" no scene: File > Open");
}

void StatusBar::update(const std::string& scene, const RenderStatus& st, const std::string& message) {
    const std::string stats = load_summary(st), progress = progress_text(st);
    // Sets a field's text (first line; " " keeps it off the border), colour and tooltip (all of it).
    auto set = [](Fl_Box* b, const std::string& text, const std::string& tip_text, Fl_Color c) {
        const std::string label = escape_label(" " + split_lines(text).front()), tip = escape_label(tip_text);
        if (label == (b->label() ? b->label() : "") && tip == (b->tooltip() ? b->tooltip() : "") &&
            c == b->labelcolor())
            return false;
        b->copy_label(label.c_str());
        b->copy_tooltip(tip.empty() ? nullptr : tip.c_str());
        b->labelcolor(c);
        return true;
    };
    bool changed = scene.empty() ? set(scene_, "no scene: File > Open", "", FL_FOREGROUND_COLOR)
                                 : set(scene_, base_name(scene) + stats, scene + stats, FL_FOREGROUND_COLOR);
    changed |= set(progress_, progress, progress, FL_FOREGROUND_COLOR);
    changed |= set(message_, message, message, message_color(message));
    changed |= set(pixel_, pixel_text_, pixel_text_, FL_FOREGROUND_COLOR);
    if (changed) relayout();
}

void StatusBar::set_pixel(const std::string& text) {
    if (text == pixel_text_) return;
    pixel_text_ = text;
    pixel_->copy_label((" " + text).c_str());
    relayout();
}

void StatusBar::layout(int y, int window_w) {
    y_ = y;
    window_w_ = window_w;
    relayout();
}

void StatusBar::relayout() {
    auto needs = [](const Fl_Box* b) {
        int tw = 0, th = 0;
        b->measure_label(tw, th);
        return tw + 10;  // the box's border and the label's margins
    };
    // The pixel readout (while the pointer is on the image) takes the right end.
    const int rw = pixel_text_.empty() ? 0 : std::min(needs(pixel_), window_w_ / 3);
    if (rw) pixel_->show();
    else pixel_->hide();
    const int W = window_w_ - rw, y = y_;
    pixel_->resize(W, y, rw, kStatusH);
    const int sw = std::min(needs(scene_), W / 3);
    // The progress text may take the message's room only while there is no message.
    const int pw = std::max(0, std::min(needs(progress_), W - sw - std::min(needs(message_), W / 3)));
    scene_->resize(0, y, sw, kStatusH);
    progress_->resize(sw, y, pw, kStatusH);
    message_->resize(sw + pw, y, W - sw - pw, kStatusH);
    for (Fl_Box* b : {scene_, progress_, message_, pixel_}) b->redraw();
}

void StatusBar::describe(std::ostream& out, int wx, int wy) const {
    const std::pair<const char*, const Fl_Box*> fields[] = {{"scene", scene_}, {"progress", progress_}, {"message", message_}};
    for (const auto& [name, b] : fields) {
        int tw = 0, th = 0;
        b->measure_label(tw, th);
        out << "field " << name << " " << wx + b->x() << " " << wy + b->y() << " " << b->w() << " " << b->h()
            << " needs " << tw << " label " << (b->label() ? b->label() : "") << "\n";
    }
}

}  // namespace whitted::viewer
