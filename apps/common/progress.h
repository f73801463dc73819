#pragma once
// One progress line on a terminal, rewritten in place a few times a second.
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>
#include <vector>

namespace whitted::cli {

// The first of `forms` (longest first) that leaves the last column of a terminal `columns` wide
// free, or the last one cut to fit: a line reaching the last column wraps on some terminals, and
// "\r" then rewrites only the wrapped part (every update a new line).
std::string fit_to_width(const std::vector<std::string>& forms, int columns);

// The width of the terminal on `fd`; 80 when it is not one or does not say.
int terminal_columns(int fd);

// The progress line's forms, longest first, down to the percentage alone.
std::vector<std::string> progress_forms(double fraction, double elapsed, double eta);

// The line for a terminal `columns` wide: the longest of progress_forms() that fits.
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
