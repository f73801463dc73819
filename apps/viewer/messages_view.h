#pragma once
// The messages panel: the scene's errors and warnings as selectable, wrapped text; a double-click on
// a message that names a FILE:LINE:COL asks for that line to be opened in the editor.
#include <functional>
#include <string>

#include <FL/Fl_Text_Display.H>

namespace whitted::viewer {

class MessagesView : public Fl_Text_Display {
public:
    using Fl_Text_Display::Fl_Text_Display;

    // Called with the whole message line (as shown, unwrapped) under a double-click.
    std::function<void(const std::string& line)> on_open_line;

    int handle(int event) override;
};

}  // namespace whitted::viewer
