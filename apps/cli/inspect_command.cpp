#include "inspect_command.h"

#include <charconv>
#include <filesystem>
#include <iostream>

#include "inspect/report_text.h"
#include "render_options.h"

namespace whitted::cli {
namespace {

// A whole decimal integer (optional '-'), nothing around it.
bool whole_int(std::string_view s, int& out) {
    if (s.empty()) return false;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
    return ec == std::errc() && end == s.data() + s.size();
}

}  // namespace

std::optional<PixelArg> parse_pixel_arg(const std::string& text, int width, int height, std::string& error) {
    const std::size_t comma = text.find(',');
    PixelArg p;
    if (comma == std::string::npos || !whole_int(std::string_view(text).substr(0, comma), p.x) ||
        !whole_int(std::string_view(text).substr(comma + 1), p.y)) {
        error = "--inspect takes a pixel as X,Y (column, row; row 0 at the top), e.g. --inspect 320,240; got '" +
                text + "'";
        return std::nullopt;
    }
    if (p.x < 0 || p.x >= width || p.y < 0 || p.y >= height) {
        error = "--inspect " + text + " is outside the " + std::to_string(width) + "x" + std::to_string(height) +
                " image (columns 0-" + std::to_string(width - 1) + ", rows 0-" + std::to_string(height - 1) + ")";
        return std::nullopt;
    }
    return p;
}

int print_inspection(const Scene& scene, const RenderJob& job, const PixelArg& p, const std::string& scene_path) {
    const std::string base = std::filesystem::path(scene_path).parent_path().string();
    const PixelReport report = inspect_pixel(scene, job, p.x, p.y, job.cancel);
    if (report.cancelled) return kExitInterrupted;  // the caller says why
    std::cout << report_text(report, base.empty() ? "." : base);
    std::cout.flush();
    return std::cout ? kExitOk : kExitIo;
}

}  // namespace whitted::cli
