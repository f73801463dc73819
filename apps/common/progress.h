#pragma once
// One progress line on a terminal, rewritten in place a few times a second.
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace whitted::cli {

// The line for a terminal `columns` wide: the longest of several forms that leaves the last
// column free, down to the percentage alone.
std::string progress_text(double fraction, double elapsed, double eta, int columns);

class ProgressLine {
public:
    ProgressLine(int total_tiles, bool enabled);
    void tile_done();  // thread-safe
    void finish();     // clears the line

private:
    void draw(int done);
    int total_;
    bool enabled_;
    std::atomic<int> done_{0};
    std::mutex mutex_;
    std::chrono::steady_clock::time_point start_, last_draw_;
};

}  // namespace whitted::cli
