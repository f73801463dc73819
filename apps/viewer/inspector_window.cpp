#include "inspector_window.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/Fl_Button.H>
#include <FL/Fl_Check_Button.H>
#include <FL/Fl_Value_Slider.H>
#include <FL/Fl_Text_Buffer.H>
#include <FL/Fl_Text_Display.H>
#include <FL/fl_ask.H>
#include <FL/fl_draw.H>

#include "inspect/report_text.h"
#include "viewer_util.h"

namespace whitted::viewer {

// The report's text: selectable, Ctrl+C copies; a double click on a line opens its location.
class ReportDisplay : public Fl_Text_Display {
public:
    ReportDisplay(int x, int y, int w, int h, InspectorWindow& owner) : Fl_Text_Display(x, y, w, h), owner_(owner) {}
    int handle(int event) override {
        if (event == FL_PUSH && Fl::event_button() == FL_LEFT_MOUSE && Fl::event_clicks() > 0 && buffer()) {
            const int pos = xy_to_position(Fl::event_x(), Fl::event_y());
            char* line = buffer()->line_text(pos);
            const std::string text = line ? line : "";
            std::free(line);
            owner_.open_line(text);
            return 1;
        }
        return Fl_Text_Display::handle(event);
    }

private:
    InspectorWindow& owner_;
};

namespace {
// The report on top; under it the ray tree's row (draw it, its depth, the colours), then the buttons.
constexpr int kW = 760, kH = 560, kPad = 8, kButtonH = 28;
// The colours of ray_overlay.h, named.
constexpr struct {
    const char* label;
    unsigned char r, g, b;
} kLegend[] = {{"reflected", 60, 140, 255}, {"refracted", 255, 150, 30}, {"shadow: lit", 40, 220, 40},
               {"blocked", 230, 30, 30},     {"through glass", 230, 230, 60}, {"TIR", 255, 230, 0}};
}  // namespace

InspectorWindow::InspectorWindow() : Fl_Double_Window(kW, kH, "Pixel inspector") {
    buffer_ = new Fl_Text_Buffer();
    display_ = new ReportDisplay(kPad, kPad, kW - 2 * kPad, kH - 4 * kPad - 2 * kButtonH, *this);
    display_->buffer(buffer_);
    display_->textfont(FL_COURIER);
    display_->textsize(13);
    copy_ = new Fl_Button(kPad, kH - kPad - kButtonH, 90, kButtonH, "&Copy");
    copy_->callback([](Fl_Widget*, void* v) {
        const std::string& t = static_cast<InspectorWindow*>(v)->text_;
        Fl::copy(t.c_str(), int(t.size()), 1);  // the clipboard (Ctrl+V elsewhere)
        Fl::copy(t.c_str(), int(t.size()), 0);  // and the selection (middle click)
    }, this);
    open_ = new Fl_Button(kPad + 98, kH - kPad - kButtonH, 330, kButtonH, "Open the object's line");
    open_->callback([](Fl_Widget*, void* v) {
        auto* w = static_cast<InspectorWindow*>(v);
        w->open_loc(w->object_loc_);
    }, this);
    hint_ = new Fl_Box(kPad + 436, kH - kPad - kButtonH, kW - 444 - kPad, kButtonH,
                       "Click a pixel; Shift+hover follows the mouse");
    hint_->align(FL_ALIGN_INSIDE | FL_ALIGN_LEFT | FL_ALIGN_CLIP);
    hint_->labelsize(12);
    tree_on_ = new Fl_Check_Button(0, 0, 130, kButtonH, "Draw ray tree");
    tree_on_->value(1);
    tree_on_->tooltip("Draw the inspected sample's rays over the image, projected with the render's camera");
    tree_depth_ = new Fl_Value_Slider(0, 0, 160, kButtonH - 6, "Depth");
    tree_depth_->type(FL_HOR_NICE_SLIDER);
    tree_depth_->align(FL_ALIGN_LEFT);
    tree_depth_->step(1);
    tree_depth_->bounds(0, 0);
    tree_depth_->tooltip("The bounces drawn: 0 is the camera ray's hit and its shadow rays (also View > Ray tree depth)");
    auto changed = [](Fl_Widget*, void* v) {
        auto* w = static_cast<InspectorWindow*>(v);
        if (w->on_tree) w->on_tree(w->tree_on_->value() != 0, int(w->tree_depth_->value()));
    };
    tree_on_->callback(changed, this);
    tree_depth_->callback(changed, this);
    for (const auto& l : kLegend) {
        auto* b = new Fl_Box(0, 0, 60, kButtonH, l.label);
        b->labelsize(12);
        b->labelcolor(fl_rgb_color(l.r, l.g, l.b));
        b->box(FL_FLAT_BOX);
        b->color(fl_rgb_color(48, 48, 48));  // the image area's grey: the colours as drawn over a picture
        legend_.push_back(b);
    }
    end();
    resizable(display_);
    show_result(inspect_message("Click a pixel of the image (or hover over it with Shift held) to see what made it."));
}

InspectorWindow::~InspectorWindow() {
    display_->buffer(nullptr);
    delete buffer_;
}

void InspectorWindow::show_result(const InspectResult& r) {
    text_ = r.ok ? r.text : r.message + "\n";
    base_dir_ = r.base_dir;
    buffer_->text(text_.c_str());
    object_loc_ = r.ok && r.report.hit ? r.report.hit->object.loc : SourceLoc{};
    if (object_loc_.line > 0) {
        open_label_ = "Open " + display_loc(object_loc_, base_dir_) + " in the editor";
        open_->activate();
    } else {
        open_label_ = "Open the object's line";
        open_->deactivate();
    }
    layout_buttons();
    redraw();
}

void InspectorWindow::resize(int X, int Y, int W, int H) {
    Fl_Double_Window::resize(X, Y, W, H);
    if (tree_on_) layout_buttons();
}

// The bottom row: Copy, then the Open button as wide as its label (a long path loses its start to
// an ellipsis; the tooltip has it all), then the hint in what is left.
void InspectorWindow::layout_buttons() {
    const int y = h() - kPad - kButtonH, open_x = kPad + 98, margins = 24;
    const int max_w = std::max(160, w() - open_x - kPad - 160);  // the hint keeps some room
    fl_font(open_->labelfont(), open_->labelsize());
    std::string label = open_label_;
    if (object_loc_.line > 0 && fl_width(label.c_str()) + margins > max_w) {
        const std::string head = "Open ", tail = " in the editor";
        const double room = max_w - margins - fl_width((head + tail).c_str());
        label = head + fit_width(display_loc(object_loc_, base_dir_), room, /*keep_end=*/true) + tail;
    }
    open_->copy_label(escape_label(label).c_str());
    open_->copy_tooltip(label == open_label_ ? nullptr : escape_label(open_label_).c_str());
    const int open_w = std::min(max_w, int(fl_width(label.c_str())) + margins);
    open_->resize(open_x, y, open_w, kButtonH);
    copy_->resize(kPad, y, 90, kButtonH);
    const int hint_x = open_x + open_w + 8;
    hint_->resize(hint_x, y, std::max(0, w() - kPad - hint_x), kButtonH);
    // The ray tree's row, above: the check box, the slider (its label to its left), the legend.
    const int ty = y - kPad - kButtonH;
    tree_on_->resize(kPad, ty, 130, kButtonH);
    tree_depth_->resize(kPad + 130 + 48, ty + 3, 130, kButtonH - 6);
    int lx = kPad + 130 + 48 + 130 + 12;
    for (Fl_Box* b : legend_) {  // each as wide as its name; those that no longer fit are hidden
        fl_font(b->labelfont(), b->labelsize());
        const int bw = int(fl_width(b->label())) + 10;
        b->resize(lx, ty + 3, bw, kButtonH - 6);
        if (lx + bw <= w() - kPad) b->show();
        else b->hide();
        lx += bw + 2;
    }
}

void InspectorWindow::set_tree(int deepest, int depth, bool on) {
    tree_depth_->bounds(0, std::max(0, deepest));
    tree_depth_->value(std::clamp(depth, 0, std::max(0, deepest)));
    tree_on_->value(on);
    tree_depth_->redraw();
}

void InspectorWindow::open_line(const std::string& line) {
    if (const auto loc = location_in_line(line, base_dir_)) open_loc(*loc);
}

void InspectorWindow::open_loc(const SourceLoc& loc) { open_in_editor(loc); }

void open_in_editor(const SourceLoc& loc) {
    const std::string editor = chosen_editor(std::getenv("VISUAL"), std::getenv("EDITOR"));
    if (editor.empty()) {
        fl_message("Set $VISUAL or $EDITOR to open %s:%d in your editor.", loc.file.c_str(), loc.line);
        return;
    }
    if (!launch_detached(editor_command(editor, loc))) fl_alert("Could not start the editor '%s'.", editor.c_str());
}

}  // namespace whitted::viewer
