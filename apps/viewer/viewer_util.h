#pragma once
// Small text helpers the viewer window's files share (UI thread only).
#include <filesystem>
#include <string>
#include <vector>

#include <FL/Enumerations.H>

namespace whitted::viewer {

constexpr int kMenuH = 25, kToolH = 34, kStatusH = 24, kMessagesH = 110;
// In RenderMode's order.
constexpr const char* kModes[] = {"whitted", "raycast", "normals", "depth", "path"};

inline std::string base_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

// FLTK draws "@name" in a label or tooltip as a symbol; "@@" is a literal '@'. For names (scenes,
// textures, paths) that must show as written.
inline std::string escape_label(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '@') out += '@';
        out += c;
    }
    return out;
}

// Errors and warnings are coloured in the status bar and also listed in the messages panel.
inline Fl_Color message_color(const std::string& msg) {
    if (msg.find("error:") != std::string::npos) return FL_RED;
    if (msg.find("warning:") != std::string::npos) return FL_DARK_YELLOW;
    return FL_FOREGROUND_COLOR;
}

// A diagnostic's text may run over several lines (e.g. the paths a texture was looked for at).
inline std::vector<std::string> split_lines(const std::string& text) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (std::size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
        lines.push_back(text.substr(start, nl - start));
    lines.push_back(text.substr(start));
    return lines;
}

}  // namespace whitted::viewer
