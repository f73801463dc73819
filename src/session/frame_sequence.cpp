#include "session/frame_sequence.h"

#include <charconv>
#include <cstdio>
#include <filesystem>

namespace whitted {
namespace {

std::optional<int> frame_number(std::string_view text) {
    int n = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, n);
    if (text.empty() || ec != std::errc() || ptr != end || n < 0 || n > kMaxFrame) return std::nullopt;
    return n;
}

}  // namespace

std::optional<FrameRange> parse_frame_range(std::string_view text) {
    const std::size_t dots = text.find("..");
    if (dots == std::string_view::npos) {
        const auto n = frame_number(text);
        if (!n) return std::nullopt;
        return FrameRange{*n, *n};
    }
    const auto first = frame_number(text.substr(0, dots));
    const auto last = frame_number(text.substr(dots + 2));
    if (!first || !last || *last < *first) return std::nullopt;
    return FrameRange{*first, *last};
}

// In double, then rounded once: frame n's time is the float nearest n / fps.
float frame_time(int n, float fps) { return float(double(n) / double(fps)); }

std::string frame_path(const std::string& output, int n) {
    const std::filesystem::path path(output);
    char number[16];
    std::snprintf(number, sizeof number, ".%04d", n);
    // stem + number + extension, in the same folder ("out.png" → "out.0001.png").
    const std::string ext = path.extension().string();
    return output.substr(0, output.size() - ext.size()) + number + ext;
}

}  // namespace whitted
