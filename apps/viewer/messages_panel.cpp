#include "messages_panel.h"

#include <ostream>

#include <FL/Fl_Text_Buffer.H>

#include "messages_view.h"
#include "render_controller.h"
#include "viewer_util.h"

namespace whitted::viewer {

MessagesPanel::MessagesPanel(std::function<void(const std::string& line)> open_line) {
    view_ = new MessagesView(0, 0, 100, kMessagesH);
    view_->on_open_line = std::move(open_line);
    text_ = new Fl_Text_Buffer();
    styles_ = new Fl_Text_Buffer();
    view_->buffer(text_);
    view_->textfont(FL_COURIER);
    view_->textsize(13);
    view_->wrap_mode(Fl_Text_Display::WRAP_AT_BOUNDS, 0);
    static const Fl_Text_Display::Style_Table_Entry styles[] = {
        {FL_FOREGROUND_COLOR, FL_COURIER, 13, 0}, {FL_RED, FL_COURIER, 13, 0}, {FL_DARK_YELLOW, FL_COURIER, 13, 0}};
    view_->highlight_data(styles_, styles, 3, 'A', nullptr, nullptr);
}

// The widget belongs to the window, which deletes it after this (its members go first).
MessagesPanel::~MessagesPanel() {
    view_->buffer(nullptr);  // (it does not look at the style buffer once it has no text)
    delete text_;
    delete styles_;
}

MessagesPanel::Change MessagesPanel::update(const RenderStatus& st, const std::string& own,
                                            const std::function<std::string(const std::string&)>& relative) {
    auto styled = [](const std::string& line, Fl_Color c) {
        return std::string(1, c == FL_RED ? 'B' : c == FL_DARK_YELLOW ? 'C' : 'A') + line;
    };
    // Keep the previous load's messages while a new load runs, until it has its own.
    if (st.state != RenderState::Loading && st.job != job_) {
        job_ = st.job;
        diagnostic_lines_.clear();
        for (const auto& d : st.diagnostics)
            for (const std::string& line : split_lines(relative(d.str())))
                diagnostic_lines_.push_back(styled(line, d.severity == Severity::Error ? FL_RED : FL_DARK_YELLOW));
        // A failure without a diagnostic still has its message in the status bar.
        if (st.diagnostics.empty() && message_color(st.message) != FL_FOREGROUND_COLOR)
            diagnostic_lines_.push_back(styled(relative(st.message), message_color(st.message)));
    }
    // The viewer's own errors and warnings go last.
    std::vector<std::string> lines = diagnostic_lines_;
    const bool has_own = message_color(own) != FL_FOREGROUND_COLOR;
    if (has_own)
        for (const std::string& line : split_lines(own)) lines.push_back(styled(line, message_color(own)));
    if (lines == lines_) return Change::Same;
    const bool was_shown = !lines_.empty();
    lines_ = lines;
    std::string text, style;
    for (const std::string& line : lines) {
        text += line.substr(1) + "\n";
        style += std::string(line.size() - 1, line[0]) + "A";
    }
    text_->text(text.c_str());
    styles_->text(style.c_str());
    if (has_own) view_->scroll(view_->count_lines(0, text_->length(), true), 0);
    return was_shown != !lines_.empty() ? Change::Shown : Change::Text;
}

void MessagesPanel::place(int x, int y, int w, int h) {
    view_->resize(x, y, w, h);
    view_->show();
}

void MessagesPanel::hide() { view_->hide(); }

void MessagesPanel::describe(std::ostream& out) const {
    for (const std::string& line : lines_) out << "panel " << line.substr(1) << "\n";  // after its style
}

}  // namespace whitted::viewer
