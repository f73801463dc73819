#include "progress.h"

#include <cstdio>

namespace whitted::cli {

using Clock = std::chrono::steady_clock;

ProgressLine::ProgressLine(int total_tiles, bool enabled)
    : total_(total_tiles), enabled_(enabled), start_(Clock::now()), last_draw_(start_) {}

void ProgressLine::tile_done() {
    int done = ++done_;
    if (!enabled_) return;
    // Never make a worker wait for the terminal (another thread is drawing: skip this update),
    // except for the last tile, whose line is always drawn.
    std::unique_lock lock(mutex_, std::defer_lock);
    if (done >= total_) lock.lock();
    else if (!lock.try_lock()) return;
    auto now = Clock::now();
    if (now - last_draw_ < std::chrono::milliseconds(200) && done < total_) return;
    last_draw_ = now;
    draw(done);
}

void ProgressLine::draw(int done) {
    double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    double fraction = total_ > 0 ? double(done) / total_ : 1.0;
    double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
    std::fprintf(stderr, "\r\033[Krendering %5.1f%%  elapsed %.1fs  eta %.1fs", 100 * fraction, elapsed, eta);
    std::fflush(stderr);
}

void ProgressLine::finish() {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace whitted::cli
