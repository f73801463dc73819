#include "inspector_window.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <FL/Fl.H>
#include <FL/Fl_Box.H>
#include <FL/Fl_Button.H>
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
constexpr int kW = 760, kH = 520, kPad = 8, kButtonH = 28;
}

InspectorWindow::InspectorWindow() : Fl_Double_Window(kW, kH, "Pixel inspector") {
    buffer_ = new Fl_Text_Buffer();
    display_ = new ReportDisplay(kPad, kPad, kW - 2 * kPad, kH - 3 * kPad - kButtonH, *this);
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
    if (open_) layout_buttons();
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
