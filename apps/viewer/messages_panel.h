#pragma once
// The messages panel under the image: the last load's errors and warnings, then the viewer's own
// (e.g. a failed save), as selectable wrapped text (copy with Ctrl+C), errors red and warnings
// yellow. Shown only while it has lines.
#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

class Fl_Text_Buffer;

namespace whitted::viewer {

class MessagesView;
struct RenderStatus;

class MessagesPanel {
public:
    // Makes its widget in the current group (the window's); `open_line` gets a double-clicked line.
    explicit MessagesPanel(std::function<void(const std::string& line)> open_line);
    ~MessagesPanel();
    MessagesPanel(const MessagesPanel&) = delete;
    MessagesPanel& operator=(const MessagesPanel&) = delete;

    enum class Change { Same, Text, Shown };  // Shown: it appeared or went (the window lays out again)
    // The messages of `st` (kept while a new load runs, until it has its own), then `own` if it is
    // an error or a warning; `relative` shortens the paths in a message.
    Change update(const RenderStatus& st, const std::string& own,
                  const std::function<std::string(const std::string&)>& relative);
    bool has_lines() const { return !lines_.empty(); }

    void place(int x, int y, int w, int h);  // and shows it
    void hide();
    // For the ready file: a line "panel TEXT" per line.
    void describe(std::ostream& out) const;

private:
    MessagesView* view_ = nullptr;
    Fl_Text_Buffer *text_ = nullptr, *styles_ = nullptr;
    std::uint64_t job_ = ~0ull;  // whose diagnostics are shown
    // Each line kept with its style letter first: the load's, and all shown now.
    std::vector<std::string> diagnostic_lines_, lines_;
};

}  // namespace whitted::viewer
