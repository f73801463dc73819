#pragma once
// Numbered frames of an animation (--frames A..B, --fps F): which frames, at what scene time, and
// the file each one goes to.
#include <optional>
#include <string>
#include <string_view>

namespace whitted {

struct FrameRange {
    int first = 0, last = 0;  // inclusive
    int count() const { return last - first + 1; }
};

// The largest frame number: six digits, a day of frames at 10 frames a second.
constexpr int kMaxFrame = 999999;

// "A..B" with 0 <= A <= B <= kMaxFrame, or "N" for one frame; nothing else.
std::optional<FrameRange> parse_frame_range(std::string_view text);

// Frame n is the scene at time n / fps: frame 0 is the still image (--time 0).
float frame_time(int n, float fps);

// NAME.EXT → NAME.0007.EXT: the number padded to four digits (more when it needs them), so that
// the files sort in frame order; a name without an extension gets the number at its end.
std::string frame_path(const std::string& output, int n);

}  // namespace whitted
