#pragma once
// The pixel inspector's window: the report of the pixel last clicked (or hovered with Shift) on
// the image, as selectable, copyable text. Double-clicking a line that names FILE:LINE:COL, or
// the button under the text, opens $VISUAL / $EDITOR at that line. The report itself comes
// from inspect_action.h (display-free).
#include <functional>
#include <string>
#include <vector>

#include <FL/Fl_Double_Window.H>

#include "inspect_action.h"

class Fl_Button;
class Fl_Check_Button;
class Fl_Value_Slider;
class Fl_Text_Buffer;
class Fl_Box;

namespace whitted::viewer {

class ReportDisplay;

class InspectorWindow : public Fl_Double_Window {
public:
    InspectorWindow();
    ~InspectorWindow() override;

    // Shows the report (or why there is none).
    void show_result(const InspectResult& result);
    const std::string& text() const { return text_; }

    // Opens the editor at the location named on `line` of the report; a message when it cannot.
    void open_line(const std::string& line);

    // The ray tree's controls: its depth slider from 0 to `deepest` at `depth`, and whether it is drawn.
    void set_tree(int deepest, int depth, bool on);
    // The user changed them.
    std::function<void(bool on, int depth)> on_tree;

    void resize(int x, int y, int w, int h) override;

private:
    void open_loc(const SourceLoc& loc);
    void layout_buttons();

    ReportDisplay* display_ = nullptr;
    Fl_Text_Buffer* buffer_ = nullptr;
    Fl_Button *copy_ = nullptr, *open_ = nullptr;
    Fl_Box* hint_ = nullptr;
    Fl_Check_Button* tree_on_ = nullptr;
    Fl_Value_Slider* tree_depth_ = nullptr;
    std::vector<Fl_Box*> legend_;
    std::string text_, base_dir_, open_label_;
    SourceLoc object_loc_;
};

// Opens $VISUAL or $EDITOR at loc's line, or says why it cannot.
void open_in_editor(const SourceLoc& loc);

}  // namespace whitted::viewer
