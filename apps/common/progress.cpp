#include "progress.h"

#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdio>
#include <string>

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

std::string fit_to_width(const std::vector<std::string>& forms, int columns) {
    for (const std::string& f : forms)
        if (int(f.size()) < columns) return f;
    return columns > 1 && !forms.empty() ? forms.back().substr(0, std::size_t(columns - 1)) : "";
}

int terminal_columns(int fd) {
    struct winsize size {};
    return ioctl(fd, TIOCGWINSZ, &size) == 0 && size.ws_col > 0 ? size.ws_col : 80;
}

std::vector<std::string> progress_forms(double fraction, double elapsed, double eta) {
    char pct[16], el[32], et[32];
    std::snprintf(pct, sizeof pct, "%5.1f%%", 100 * fraction);
    std::snprintf(el, sizeof el, "%.1fs", elapsed);
    std::snprintf(et, sizeof et, "%.1fs", eta);
    return {
        std::string("rendering ") + pct + "  elapsed " + el + "  eta " + et,
        std::string(pct) + "  elapsed " + el + "  eta " + et,
        std::string(pct) + " eta " + et,
        pct,
    };
}

std::string progress_text(double fraction, double elapsed, double eta, int columns) {
    return fit_to_width(progress_forms(fraction, elapsed, eta), columns);
}

void ProgressLine::draw(int done) {
    double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    double fraction = total_ > 0 ? double(done) / total_ : 1.0;
    double eta = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
    std::fprintf(stderr, "\r\033[K%s", progress_text(fraction, elapsed, eta, terminal_columns(STDERR_FILENO)).c_str());
    std::fflush(stderr);
}

void ProgressLine::finish() {
    if (!enabled_) return;
    std::lock_guard lock(mutex_);
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace whitted::cli
