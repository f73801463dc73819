#include "watch_timer.h"

#include <FL/Fl.H>

#include "render_controller.h"

namespace whitted::viewer {

std::string scene_stamp(const std::string& scene, const std::vector<std::string>& texture_files) {
    std::string stamp = file_stamp(scene);
    for (const std::string& t : texture_files) {
        stamp += '|';
        stamp += file_stamp(t);
    }
    return stamp;
}

WatchTimer::WatchTimer(bool enabled, std::function<std::string()> stamp, std::function<void()> reload,
                       std::function<void()> ticked)
    : enabled_(enabled), stamp_(std::move(stamp)), reload_(std::move(reload)), ticked_(std::move(ticked)) {
    Fl::add_timeout(1.0, tick_cb, this);
}

WatchTimer::~WatchTimer() { stop(); }

void WatchTimer::stop() { Fl::remove_timeout(tick_cb, this); }

void WatchTimer::set_enabled(bool on) {
    enabled_ = on;
    rearm();
}

void WatchTimer::rearm() { watched_ = stamp_(); }

void WatchTimer::tick_cb(void* self) { static_cast<WatchTimer*>(self)->tick(); }

void WatchTimer::tick() {
    if (enabled_) {
        const std::string stamp = stamp_();
        if (!stamp.empty() && stamp != watched_) {
            watched_ = stamp;
            reload_();
        }
    }
    ++ticks_;
    ticked_();
    Fl::repeat_timeout(1.0, tick_cb, this);
}

}  // namespace whitted::viewer
