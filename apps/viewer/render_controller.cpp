#include "render_controller.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>

#include "render/renderer.h"

namespace whitted::viewer {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Everything in the load options that changes what a load produces.
std::string options_key(const LoadOptions& o) {
    std::ostringstream k;
    k << o.lenient << '|' << o.time << '|' << int(o.textures.missing) << '|' << int(o.cs1230_stage) << '|'
      << o.textures.limits.mip_levels;  // a filter that reads mip-maps needs them built
    for (const auto& d : o.textures.search_dirs) k << "|d:" << d;
    for (const auto& [name, file] : o.textures.overrides) k << "|o:" << name << '=' << file << '@' << file_stamp(file);
    for (const auto& name : o.textures.checker_names) k << "|c:" << name;
    return k.str();
}

// The line a status bar shows for a load: the last error, else the last warning.
std::string summary(const std::vector<Diagnostic>& diags) {
    const Diagnostic* pick = nullptr;
    for (const auto& d : diags)
        if (d.severity == Severity::Error) pick = &d;
    if (!pick && !diags.empty()) pick = &diags.back();
    return pick ? pick->str() : "";
}

}  // namespace

const char* state_name(RenderState s) {
    switch (s) {
        case RenderState::Idle: return "idle";
        case RenderState::Loading: return "loading";
        case RenderState::Rendering: return "rendering";
        case RenderState::Finished: return "finished";
        case RenderState::Stopped: return "stopped";
        case RenderState::Failed: return "failed";
        case RenderState::MissingTextures: return "missing textures";
    }
    return "?";
}

std::string file_stamp(const std::string& path) {
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) return "";
    std::ostringstream k;
    k << st.st_dev << ':' << st.st_ino << ':' << st.st_size << ':' << st.st_mtim.tv_sec << '.' << st.st_mtim.tv_nsec;
    return k.str();
}

struct RenderController::Job {
    std::uint64_t id = 0;
    std::string path;  // "" when the scene was given
    LoadOptions load;
    std::string key;  // the file's stamp and the load options when the job started
    bool force_reload = false;
    bool coarse_first = false;
    std::shared_ptr<const Scene> scene;
    RenderJob settings;
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
    std::thread thread;
};

RenderController::~RenderController() {
    std::vector<std::shared_ptr<Job>> jobs;
    {
        std::lock_guard lock(mutex_);
        for (auto& j : jobs_) j->cancel = true;
        jobs.swap(jobs_);
        current_.reset();
    }
    for (auto& j : jobs)
        if (j->thread.joinable()) j->thread.join();
}

void RenderController::cancel_current_locked() {
    if (!current_) return;
    current_->cancel = true;
    if (is_busy(status_.state)) {
        status_.state = RenderState::Stopped;
        status_.elapsed_seconds = seconds_since(started_);
    }
}

// The settings as the controller renders them: sizes, depth and samples within their ranges, no
// callbacks (the controller's own, per job).
static RenderJob sanitized(const RenderJob& settings) {
    RenderJob s = settings;
    s.width = std::max(1, settings.width);
    s.height = std::max(1, settings.height);
    s.integrator.max_depth = std::max(0, settings.integrator.max_depth);
    s.sampling.aa = std::clamp(settings.sampling.aa, 1, Sampler::kMaxAa);
    s.sampling.spp = std::clamp(settings.sampling.spp, 1, Sampler::kMaxSpp);
    s.sampling.aa_threshold =
        settings.sampling.aa_threshold > 0.0f ? std::min(settings.sampling.aa_threshold, 1.0f) : 0.0f;  // NaN: 0
    s.cancel = nullptr;
    s.on_tile = nullptr;
    s.threads = std::max(0, settings.threads);
    s.tile_size = std::max(1, settings.tile_size);
    return s;
}

void RenderController::begin_locked(std::shared_ptr<Job> job, const std::string& path, const RenderJob& settings) {
    cancel_current_locked();
    job->id = ++next_job_;
    job->settings = sanitized(settings);
    current_ = job;
    status_ = RenderStatus{};
    status_.state = RenderState::Loading;
    status_.job = job->id;
    status_.scene_path = path;
    status_.settings = job->settings;
    started_ = Clock::now();
    changed_.notify_all();
}

bool RenderController::start(const std::string& scene_path, const LoadOptions& load, const RenderJob& settings,
                             bool force_reload, bool coarse_first) {
    reap();
    auto job = std::make_shared<Job>();
    job->path = scene_path;
    job->load = load;
    job->key = file_stamp(scene_path) + "#" + options_key(load);
    job->force_reload = force_reload;
    job->coarse_first = coarse_first;
    std::lock_guard lock(mutex_);
    // Asked again for what is being made or was made: the same file, unchanged, the same pixels.
    if (!force_reload && !coarse_first && current_ && !current_->path.empty() && current_->path == scene_path &&
        current_->key == job->key && !job->key.starts_with("#") &&
        (is_busy(status_.state) || status_.state == RenderState::Finished) &&
        same_pixels(current_->settings, sanitized(settings)))
        return false;
    begin_locked(job, scene_path, settings);
    launch(job);
    return true;
}

void RenderController::start(std::shared_ptr<const Scene> scene, const RenderJob& settings) {
    reap();
    auto job = std::make_shared<Job>();
    job->scene = std::move(scene);
    std::lock_guard lock(mutex_);
    begin_locked(job, "", settings);
    launch(job);
}

void RenderController::launch(std::shared_ptr<Job> job) {
    // Called with the mutex held: the thread's first lock waits until start() has returned.
    jobs_.push_back(job);
    job->thread = std::thread([this, job] { run(job); });
}

void RenderController::stop() {
    {
        std::lock_guard lock(mutex_);
        cancel_current_locked();
        changed_.notify_all();
    }
    reap();
}

void RenderController::run(std::shared_ptr<Job> job) {
    auto is_current = [&] { return current_ == job && !job->cancel.load(); };  // call with the mutex held
    auto finish = [&] {
        job->finished = true;
        changed_.notify_all();
    };

    // 1. The scene: given, cached, or loaded now.
    std::shared_ptr<const Scene> scene = job->scene;
    if (!scene) {
        const std::string& key = job->key;
        LoadResult loaded;
        bool reused = false;
        {
            std::lock_guard lock(mutex_);
            if (!job->force_reload && cache_.result.ok() && cache_.path == job->path && cache_.key == key) {
                loaded = cache_.result;
                reused = true;
            }
        }
        if (!reused) {
            LoadOptions load = job->load;
            load.cancel = &job->cancel;  // a job stopped or replaced while loading gives up early
            loaded = load_scene(job->path, load);
        }

        std::lock_guard lock(mutex_);
        if (!reused && loaded.ok()) cache_ = Cached{job->path, key, loaded};
        if (!is_current()) return finish();
        status_.diagnostics = loaded.diagnostics;
        status_.missing_textures = loaded.missing_textures;
        status_.load_stats = loaded.stats;
        status_.scene_reused = reused;
        status_.file_camera = loaded.camera;
        status_.texture_files = loaded.texture_paths;
        status_.message = summary(loaded.diagnostics);
        if (!loaded.ok()) {
            status_.state = loaded.missing_textures.empty() ? RenderState::Failed : RenderState::MissingTextures;
            if (status_.message.empty()) status_.message = "error: the scene could not be loaded";
            status_.elapsed_seconds = seconds_since(started_);
            return finish();
        }
        scene = loaded.scene;
    }

    // 2. The render: a session's coarse frames (a moving camera) and passes; each finished tile is
    // copied to the shared image as it comes, over the picture already there.
    RenderJob settings = job->settings;
    settings.cancel = &job->cancel;
    Session session(scene, settings);
    const RenderJob& s = session.job();
    {
        std::lock_guard lock(mutex_);
        if (!is_current()) return finish();
        status_.state = RenderState::Rendering;
        status_.tiles_total = s.tile_count() * int(session.pass_ends().size());
        status_.samples_total = session.pass_ends().back();
        status_.passes_total = int(session.pass_ends().size());
        // The last picture stays on screen until the new one's tiles (or coarse frames) replace it.
        if (image_.width != s.width || image_.height != s.height) {
            image_ = Image(s.width, s.height);
            linear_ = LinearImage{s.width, s.height,
                                  std::vector<glm::vec3>(std::size_t(s.width) * std::size_t(s.height)), {}};
            ++image_version_;
        }
        shown_ = Shown{scene, s, job->path};
        shown_.settings.cancel = nullptr;
        shown_.settings.on_tile = nullptr;
        changed_.notify_all();
    }
    if (job->coarse_first)
        for (int div : kPreviewDivisors) {
            LinearImage big;
            if (!session.render_preview(div, big)) break;
            std::lock_guard lock(mutex_);
            if (!is_current()) return finish();
            linear_ = std::move(big);
            encode_region(linear_, image_, PixelRegion{0, 0, s.width, s.height}, view_, exposure_scale_);
            ++image_version_;
            ++status_.frames;
            status_.preview_divisor = div;
            changed_.notify_all();
        }
    const auto on_tile = [&](const Tile& t, const Film& film) {
        // Runs on the render thread that finished the tile, so reading its film pixels is race-free.
        {
            std::lock_guard lock(mutex_);
            if (!is_current()) return;
            film.write_to(linear_, t);
            encode_region(linear_, image_, t, view_, exposure_scale_);
            ++status_.tiles_done;
            if (status_.tiles_done == s.tile_count()) status_.preview_divisor = 1;  // the first full pass is in
            ++image_version_;
        }
        if (after_tile_) after_tile_(job->id);
    };
    bool cancelled = false;
    while (!session.done() && !cancelled) {
        cancelled = session.render_pass(on_tile).render.cancelled;
        std::lock_guard lock(mutex_);
        if (!cancelled && is_current()) {
            status_.samples_done = session.samples_done();
            status_.passes_done = session.passes_done();
        }
    }

    std::lock_guard lock(mutex_);
    if (is_current()) {
        status_.state = cancelled ? RenderState::Stopped : RenderState::Finished;
        status_.elapsed_seconds = seconds_since(started_);
    }
    finish();
}


std::optional<glm::vec3> RenderController::linear_at(int x, int y) const {
    std::lock_guard lock(mutex_);
    if (x < 0 || y < 0 || x >= linear_.width || y >= linear_.height) return std::nullopt;
    return linear_.rgb[std::size_t(y) * std::size_t(linear_.width) + std::size_t(x)];
}

void RenderController::set_display(ViewTransform view, float exposure_stops) {
    std::lock_guard lock(mutex_);
    const float scale = std::exp2(std::clamp(exposure_stops, -20.0f, 20.0f));
    if (view == view_ && scale == exposure_scale_) return;
    view_ = view;
    exposure_scale_ = scale;
    if (linear_.width == image_.width && linear_.height == image_.height)
        encode_region(linear_, image_, PixelRegion{0, 0, image_.width, image_.height}, view_, exposure_scale_);
    ++image_version_;
    changed_.notify_all();
}

RenderStatus RenderController::status() const {
    std::lock_guard lock(mutex_);
    RenderStatus s = status_;
    if (is_busy(s.state)) s.elapsed_seconds = seconds_since(started_);
    return s;
}

bool RenderController::copy_image_if_changed(Image& out, std::uint64_t& version) const {
    std::lock_guard lock(mutex_);
    if (version == image_version_) return false;
    out = image_;
    version = image_version_;
    return true;
}

Image RenderController::image() const {
    std::lock_guard lock(mutex_);
    return image_;
}

LinearImage RenderController::linear_image() const {
    std::lock_guard lock(mutex_);
    return linear_;
}

RenderController::Shown RenderController::shown() const {
    std::lock_guard lock(mutex_);
    return shown_;
}

bool RenderController::wait(std::chrono::milliseconds timeout) const {
    std::unique_lock lock(mutex_);
    return changed_.wait_for(lock, timeout, [&] { return !is_busy(status_.state); });
}

int RenderController::reap() {
    std::vector<std::shared_ptr<Job>> done;
    int running = 0;
    {
        std::lock_guard lock(mutex_);
        auto it = std::partition(jobs_.begin(), jobs_.end(), [](const auto& j) { return !j->finished.load(); });
        done.assign(std::make_move_iterator(it), std::make_move_iterator(jobs_.end()));
        jobs_.erase(it, jobs_.end());
        running = int(jobs_.size());
    }
    for (auto& j : done)
        if (j->thread.joinable()) j->thread.join();  // it has finished: returns at once
    return running;
}

bool RenderController::wait_all_threads(std::chrono::milliseconds timeout) {
    const auto deadline = Clock::now() + timeout;
    while (reap() > 0) {
        if (Clock::now() >= deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return true;
}

}  // namespace whitted::viewer
