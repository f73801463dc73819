#pragma once
// Small text helpers the viewer window's files share (UI thread only).
#include <filesystem>
#include <string>
#include <vector>

#include <FL/Enumerations.H>
#include <FL/fl_draw.H>

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

// `text` within `max_w` pixels in the current font (fl_font): whole if it fits, else cut at a
// character boundary with an ellipsis where its end (or, keep_end, its start) was.
inline std::string fit_width(const std::string& text, double max_w, bool keep_end = false) {
    static const std::string ellipsis = "\xE2\x80\xA6";
    if (fl_width(text.c_str()) <= max_w) return text;
    auto boundary = [&](std::size_t i) { return i >= text.size() || (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80; };
    std::string best = ellipsis;
    if (keep_end) {
        for (std::size_t from = text.size(); from-- > 0;) {
            if (!boundary(from)) continue;
            const std::string t = ellipsis + text.substr(from);
            if (fl_width(t.c_str()) > max_w) break;
            best = t;
        }
    } else {
        for (std::size_t n = 1; n <= text.size(); ++n) {
            if (!boundary(n)) continue;
            const std::string t = text.substr(0, n) + ellipsis;
            if (fl_width(t.c_str()) > max_w) break;
            best = t;
        }
    }
    return best;
}

}  // namespace whitted::viewer
