#include "messages_view.h"

#include <cstdlib>

#include <FL/Fl.H>
#include <FL/Fl_Text_Buffer.H>

namespace whitted::viewer {

int MessagesView::handle(int event) {
    if (event == FL_PUSH && Fl::event_button() == FL_LEFT_MOUSE && Fl::event_clicks() > 0 && on_open_line &&
        buffer() && buffer()->length() > 0) {
        const int pos = xy_to_position(Fl::event_x(), Fl::event_y(), CURSOR_POS);
        char* text = buffer()->line_text(pos);  // the buffer's line: a wrapped message is still one
        const std::string line = text ? text : "";
        std::free(text);
        on_open_line(line);
        return 1;
    }
    return Fl_Text_Display::handle(event);
}

}  // namespace whitted::viewer
