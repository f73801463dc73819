#pragma once
// The viewer's once-a-second timer: with --watch (File ▸ Reload on change), a scene whose file or
// texture files changed on disk is loaded and rendered again. It also counts its ticks, so that a
// test can tell when the file was (or would have been) checked.
#include <functional>
#include <string>
#include <vector>

namespace whitted::viewer {

// The scene file's stamp (file_stamp), then those of the given texture files.
std::string scene_stamp(const std::string& scene, const std::vector<std::string>& texture_files);

class WatchTimer {
public:
    // `stamp`: the current stamp of what is watched ("" = nothing to watch); `reload`: it changed;
    // `ticked`: after every tick.
    WatchTimer(bool enabled, std::function<std::string()> stamp, std::function<void()> reload,
               std::function<void()> ticked);
    ~WatchTimer();
    WatchTimer(const WatchTimer&) = delete;
    WatchTimer& operator=(const WatchTimer&) = delete;

    bool enabled() const { return enabled_; }
    void set_enabled(bool on);  // from now on (what is on disk now is not a change)
    // A render is starting from what is on disk now: a change is a change from this.
    void rearm();
    int ticks() const { return ticks_; }
    void stop();

private:
    static void tick_cb(void* self);
    void tick();

    bool enabled_;
    std::function<std::string()> stamp_;
    std::function<void()> reload_, ticked_;
    std::string watched_;
    int ticks_ = 0;
};

}  // namespace whitted::viewer
