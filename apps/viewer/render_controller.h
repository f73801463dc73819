#pragma once
// The viewer's render controller: loads a scene and renders it on background threads, and lets the
// UI thread look at progress and the image so far without ever blocking on the render.
// Display-free (no FLTK): the viewer polls it from a timer; the tests drive it directly.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "film/image.h"
#include "film/view_transform.h"
#include "integrator/render_mode.h"
#include "render/load_scene.h"
#include "render/renderer.h"
#include "session/session.h"

namespace whitted::viewer {

enum class RenderState {
    Idle,             // nothing started yet
    Loading,          // parsing, flattening, textures, BVH
    Rendering,        // tiles are being rendered; the image fills in
    Finished,         // the whole image is there
    Stopped,          // stop() was called; the image keeps the tiles finished before it
    Failed,           // the scene has errors (see RenderStatus::diagnostics)
    MissingTextures,  // the load failed only because textures were not found (RenderStatus::missing_textures)
};

const char* state_name(RenderState state);
// True while a job is loading or rendering.
inline bool is_busy(RenderState s) { return s == RenderState::Loading || s == RenderState::Rendering; }


struct RenderStatus {
    RenderState state = RenderState::Idle;
    std::uint64_t job = 0;        // increases with every start()
    std::string scene_path;       // as given to start()
    RenderJob settings;           // of the current job (the size, integrator and sampling; no callbacks)
    int tiles_done = 0, tiles_total = 0;  // over all passes
    int samples_done = 0, samples_total = 0;  // per pixel: of the passes finished, of the job
    int passes_done = 0, passes_total = 0;
    double elapsed_seconds = 0;   // since start(), frozen when the job ends
    std::vector<Diagnostic> diagnostics;       // of the last load (warnings too)
    std::vector<MissingTexture> missing_textures;
    LoadStats load_stats;         // objects and lights are known once the load succeeded
    bool scene_reused = false;    // the loaded scene of the previous job was used again (file unchanged)
    std::string message;          // the last error or warning, one line, for a status bar ("" if none)
    // The image now shown was rendered at 1/preview_divisor of the resolution (1 = full): a job
    // started with coarse_first shows 1/8, 1/4 and 1/2 resolution frames before the full one.
    int preview_divisor = 1;
    std::uint64_t frames = 0;     // coarse frames of this job shown so far
    CameraDesc file_camera;       // the loaded scene file's camera as written (LoadResult::camera)
    std::vector<std::string> texture_files;  // the files its textures were read from (LoadResult::texture_paths)
};

// The coarse frames' divisors (kPreviewDivisors) and their enlargement (enlarge_nearest) are the
// session's (session/session.h).

class RenderController {
public:
    RenderController() = default;
    ~RenderController();  // cancels any job and joins every thread
    RenderController(const RenderController&) = delete;
    RenderController& operator=(const RenderController&) = delete;

    // Loads `scene_path` with `load` and renders it with `settings`, on a background thread.
    // Returns at once; a job still running is cancelled first (without waiting for it).
    // If the file, its modification time and the load options are those of the last successful
    // load, that scene is rendered again without loading (pass force_reload to load anyway).
    // coarse_first (a camera that moves): 1/8, 1/4 and 1/2 resolution frames come first (one
    // sample per pixel, each shown enlarged), then the full image over the last of them, then its
    // sample passes; the previous image stays on screen until the new one's pixels replace it.
    // Returns false, doing nothing, when asked again for what the current job makes or made: the
    // same file, unchanged since it began, with the same load options and the same pixels
    // (same_pixels), the job still running or finished (not when stopped or failed).
    bool start(const std::string& scene_path, const LoadOptions& load, const RenderJob& settings,
               bool force_reload = false, bool coarse_first = false);
    // Renders a scene that is already loaded (no file involved).
    void start(std::shared_ptr<const Scene> scene, const RenderJob& settings);

    // Asks the current job to stop and returns at once. The state becomes Stopped immediately;
    // the image keeps the tiles finished so far. The job's threads end within a tile row.
    void stop();

    RenderStatus status() const;

    // Copies the image if it changed since `version` (0 = never seen); returns whether it did.
    bool copy_image_if_changed(Image& out, std::uint64_t& version) const;
    Image image() const;
    // The mean colours of the picture shown, unclamped (what .exr and .pfm keep): the current job's
    // tiles and coarse frames over the last job's picture.
    LinearImage linear_image() const;
    // One pixel of it (none off the picture).
    std::optional<glm::vec3> linear_at(int x, int y) const;

    // How the picture's linear values are shown: the view transform, after an exposure of 2^stops.
    // The picture is encoded again at once (no render); image() and Save image give what is shown.
    void set_display(ViewTransform view, float exposure_stops);

    // The scene and settings of the image being shown (the last job that began rendering): what
    // the pixel inspector looks at. Null scene before any job rendered.
    struct Shown {
        std::shared_ptr<const Scene> scene;
        RenderJob settings;  // without callbacks
        std::string scene_path;
    };
    Shown shown() const;

    // Blocks until the current job is no longer loading or rendering, or the timeout passes.
    // For tests and batch use; the UI never calls it. Returns true if the job ended.
    bool wait(std::chrono::milliseconds timeout) const;
    // Joins threads of jobs that have ended (cheap; called by start/stop and the UI timer).
    // Returns the number of job threads that are still running.
    int reap();
    // Waits (up to the timeout) until no job thread runs at all, including cancelled ones.
    bool wait_all_threads(std::chrono::milliseconds timeout);

    // Tests only: called on a render thread after each tile it finished has reached the image,
    // outside the lock, with the job's number; a test holds a job in the middle of its render here
    // (to show that start() and stop() never wait for it). Set before the first start().
    void set_after_tile_hook_for_tests(std::function<void(std::uint64_t job)> hook) { after_tile_ = std::move(hook); }

private:
    struct Job;
    void launch(std::shared_ptr<Job> job);
    void run(std::shared_ptr<Job> job);
    void cancel_current_locked();
    void begin_locked(std::shared_ptr<Job> job, const std::string& path, const RenderJob& settings);

    mutable std::mutex mutex_;
    mutable std::condition_variable changed_;
    std::shared_ptr<Job> current_;
    std::vector<std::shared_ptr<Job>> jobs_;  // every job whose thread has not been joined yet
    RenderStatus status_;
    std::chrono::steady_clock::time_point started_{};
    Image image_;
    LinearImage linear_;  // the picture's linear values; image_ is their encoding
    ViewTransform view_ = ViewTransform::Linear;
    float exposure_scale_ = 1.0f;
    Shown shown_;  // what image_ is a render of
    std::uint64_t image_version_ = 0;
    std::uint64_t next_job_ = 0;
    std::function<void(std::uint64_t)> after_tile_;

    // The last scene loaded successfully, reused while its file and options are unchanged.
    struct Cached {
        std::string path, key;
        LoadResult result;
    };
    Cached cache_;
};

// A key describing a file's identity and modification time, "" if it cannot be read.
std::string file_stamp(const std::string& path);

}  // namespace whitted::viewer
