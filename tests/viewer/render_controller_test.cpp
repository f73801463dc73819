// The viewer's render controller, without a display: start, progress, stop, restart, error states.
#if __has_include("render_controller.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "render_controller.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include <gtest/gtest.h>

#include "film/film.h"
#include "film/image_io.h"
#include "integrator/integrator.h"
#include "render/renderer.h"
#include "support/run_process.h"
#include "support/scene_builder.h"

namespace whitted::viewer {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

std::shared_ptr<const Scene> busy_scene(int n = 60) {
    test::SceneBuilder b;
    Material m;
    m.reflect = glm::vec3(0.5f);
    m.specular = glm::vec3(0.5f);
    m.shine = 20;
    for (int i = 0; i < n; ++i) {
        float x = float(i % 10) - 4.5f, y = float(i / 10 % 6) - 2.5f;
        b.add(ShapeKind(i % 4), test::translate_scale({x, y, -8.0f - float(i % 3)}, glm::vec3(0.9f)), m);
    }
    b.light(test::point_light({2, 5, 5}, {1, 1, 1}));
    b.light(test::point_light({-3, 2, 4}, {0.5f, 0.5f, 0.8f}));
    b.background({0.2f, 0.3f, 0.4f});
    return std::make_shared<const Scene>(b.build());
}

// A render that takes many seconds on one thread: large, and deep mirrors everywhere.
RenderJob heavy_settings() {
    RenderJob s;
    s.width = 1600;
    s.height = 1200;
    s.integrator.max_depth = 40;
    s.threads = 2;
    s.tile_size = 16;
    return s;
}

std::size_t lit_bytes(const Image& img) {
    std::size_t n = 0;
    for (auto v : img.rgb) n += v != 0;
    return n;
}

// The eye inside two nested spheres that both reflect and transmit 90% (ior 1): every ray
// splits in two at each sphere down to the depth limit; at depth 16 a camera ray costs about
// 8000 rays, a tile row of 16 a fraction of a second and the 1600 × 1200 image hours. For the
// tests it is a render that does not end until it is cancelled.
std::shared_ptr<const Scene> endless_scene() {
    test::SceneBuilder b;
    Material m;
    m.diffuse = glm::vec3(0.0f);
    m.reflect = m.transparent = glm::vec3(0.9f);
    m.ior = 1.0f;
    b.add(ShapeKind::Sphere, test::translate_scale({0, 0, 1}, glm::vec3(4)), m);
    b.add(ShapeKind::Sphere, test::translate_scale({0, 0, 1}, glm::vec3(8)), m);
    return std::make_shared<const Scene>(b.build());
}

// Waits for the first finished tile, for at most `timeout`.
bool wait_first_tile(const RenderController& c, std::chrono::milliseconds timeout) {
    for (const auto deadline = Clock::now() + timeout;; std::this_thread::sleep_for(2ms)) {
        if (c.status().tiles_done >= 1) return true;
        if (Clock::now() >= deadline) return false;
    }
}

const char* kBallScene = R"(camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]
)";

// Holds the render threads of one job, each at a finished tile once `after` tiles are in, until
// opened: a job that is certainly still in the middle of its render, whatever the machine's load.
class TileGate {
public:
    TileGate(std::uint64_t job, int after) : job_(job), after_(after) {}
    void at_tile(std::uint64_t job) {  // the controller's after-tile hook
        std::unique_lock lock(mutex_);
        if (job != job_ || ++tiles_ < after_) return;
        held_ = true;
        changed_.notify_all();
        changed_.wait(lock, [&] { return open_; });
    }
    bool wait_held(std::chrono::milliseconds timeout) {
        std::unique_lock lock(mutex_);
        return changed_.wait_for(lock, timeout, [&] { return held_; });
    }
    bool is_open() {
        std::lock_guard lock(mutex_);
        return open_;
    }
    void open() {
        std::lock_guard lock(mutex_);
        open_ = true;
        changed_.notify_all();
    }

private:
    std::mutex mutex_;
    std::condition_variable changed_;
    std::uint64_t job_;
    int after_, tiles_ = 0;
    bool held_ = false, open_ = false;
};

// Opens the gate when the test ends however it ends, before the controller joins the threads.
struct GateOpener {
    TileGate& gate;
    ~GateOpener() { gate.open(); }
};

// Calls f() while the gate holds a job; a watchdog opens the gate if f() has not returned after
// a minute, so that a call that waits for the held job fails the test instead of hanging it.
// Returns whether f() returned with the gate still shut: without waiting for the held job.
bool returns_while_held(TileGate& gate, const std::function<void()>& f) {
    std::mutex m;
    std::condition_variable cv;
    bool returned = false;
    std::thread watchdog([&] {
        std::unique_lock lock(m);
        if (!cv.wait_for(lock, 60s, [&] { return returned; })) gate.open();
    });
    f();
    const bool without_waiting = !gate.is_open();
    {
        std::lock_guard lock(m);
        returned = true;
    }
    cv.notify_all();
    watchdog.join();
    return without_waiting;
}

TEST(RenderController, StartsIdle) {
    RenderController c;
    EXPECT_EQ(c.status().state, RenderState::Idle);
    Image img;
    std::uint64_t version = 0;
    EXPECT_FALSE(c.copy_image_if_changed(img, version));
}

TEST(RenderController, RendersProgressivelyToTheSameImageAsADirectRender) {
    auto scene = busy_scene();
    RenderJob s;
    s.width = 320;
    s.height = 240;
    s.tile_size = 16;
    s.threads = 2;
    RenderController c;
    c.start(scene, s);
    RenderStatus st = c.status();
    EXPECT_EQ(st.job, 1u);
    EXPECT_EQ(st.settings.width, 320);

    // Progress is visible while it runs: tiles_done only grows, and the image version moves on.
    int last_done = 0, observations = 0;
    Image shown;
    std::uint64_t version = 0;
    const auto deadline = Clock::now() + 60s;
    while (is_busy((st = c.status()).state) && Clock::now() < deadline) {
        EXPECT_GE(st.tiles_done, last_done);
        last_done = st.tiles_done;
        if (c.copy_image_if_changed(shown, version)) ++observations;
        std::this_thread::sleep_for(1ms);
    }
    ASSERT_EQ(st.state, RenderState::Finished);
    EXPECT_EQ(st.tiles_total, 20 * 15);
    EXPECT_EQ(st.tiles_done, st.tiles_total);
    EXPECT_GT(st.elapsed_seconds, 0.0);
    EXPECT_GE(observations, 1);

    RenderJob o;
    o.width = s.width;
    o.height = s.height;
    o.integrator.max_depth = s.integrator.max_depth;
    o.threads = 1;
    Image direct(s.width, s.height);
    render(*scene, o, direct);
    EXPECT_TRUE(c.copy_image_if_changed(shown, version) || version != 0);
    EXPECT_EQ(shown.width, 320);
    EXPECT_EQ(shown.rgb, direct.rgb);
    EXPECT_EQ(c.image().rgb, direct.rgb);
    // Nothing changes after the end.
    EXPECT_FALSE(c.copy_image_if_changed(shown, version));
    EXPECT_TRUE(c.wait_all_threads(1s));
}

// Samples arrive in passes (one per cell over the whole image, then doubling); the passes add up
// to exactly the image of one render of all the samples (the CLI's).
TEST(RenderController, SamplePassesAddUpToTheImageOfOneRender) {
    EXPECT_EQ(sample_passes({1, 1, 0.0f}), (std::vector<int>{1}));
    EXPECT_EQ(sample_passes({1, 16, 0.0f}), (std::vector<int>{1, 2, 4, 8, 16}));
    EXPECT_EQ(sample_passes({2, 5, 0.0f}), (std::vector<int>{4, 8, 16, 20}));
    EXPECT_EQ(sample_passes({3, 1, 0.2f}), (std::vector<int>{9}));  // adaptive: one pass

    test::SceneBuilder b;
    Material m;
    m.diffuse = glm::vec3(0.8f, 0.4f, 0.2f);
    m.reflect = glm::vec3(0.3f);
    m.gloss = 40;
    b.add(ShapeKind::Sphere, test::translate_scale({0, 0, -3}, glm::vec3(1.5f)), m);
    b.add(ShapeKind::Cube, test::translate_scale({0, -1.5f, -3}, {8, 0.2f, 8}), Material{});
    Light soft = test::point_light({2, 3, 0}, glm::vec3(0.8f));
    soft.radius = 0.7f;
    auto scene = std::make_shared<const Scene>(b.light(soft).build());
    RenderJob s;
    s.width = 64;
    s.height = 48;
    s.sampling.spp = 8;
    s.threads = 2;
    RenderController c;
    c.start(scene, s);
    ASSERT_TRUE(c.wait(60s));
    const RenderStatus st = c.status();
    ASSERT_EQ(st.state, RenderState::Finished);
    EXPECT_EQ(st.passes_total, 4);
    EXPECT_EQ(st.passes_done, 4);
    EXPECT_EQ(st.samples_done, 8);
    EXPECT_EQ(st.samples_total, 8);
    EXPECT_EQ(st.tiles_done, st.tiles_total);
    Image direct(64, 48);
    s.threads = 1;
    render(*scene, s, direct);
    EXPECT_EQ(c.image().rgb, direct.rgb);
}

// Save image as .exr or .pfm keeps the film's values unclamped, as whitted -o does: a path-traced
// light brighter than 1 gives values above 1, the same floats as a direct render's film.
TEST(RenderController, KeepsTheFilmsLinearValuesForExrAndPfm) {
    test::SceneBuilder b;
    Material m;
    m.diffuse = glm::vec3(0.9f, 0.5f, 0.2f);
    b.add(ShapeKind::Sphere, test::translate_scale({0, 0, -3}, glm::vec3(1.5f)), m);
    auto scene = std::make_shared<const Scene>(b.light(test::point_light({2, 3, 0}, glm::vec3(6.0f))).build());
    RenderJob s;
    s.width = 40;
    s.height = 30;
    s.integrator = {RenderMode::Path, 4};
    s.sampling.spp = 4;
    s.threads = 2;
    RenderController c;
    c.start(scene, s);
    ASSERT_TRUE(c.wait(60s));
    ASSERT_EQ(c.status().state, RenderState::Finished);
    const LinearImage linear = c.linear_image();
    ASSERT_EQ(linear.width, 40);
    ASSERT_EQ(linear.height, 30);
    float brightest = 0.0f;
    for (const glm::vec3& v : linear.rgb) brightest = std::max({brightest, v.x, v.y, v.z});
    EXPECT_GT(brightest, 1.5f) << "clamped like the 8-bit image";
    s.threads = 1;
    Film film(40, 30);
    const auto integrator = make_integrator(*scene, s.camera_for(*scene), s.integrator);
    render(*integrator, s, film);
    EXPECT_EQ(linear.rgb, film.to_linear().rgb);
}

TEST(RenderController, StopKeepsThePassesDone) {
    RenderJob s;
    s.width = 120;
    s.height = 90;
    s.sampling.spp = 4096;  // far more passes than finish before the stop
    s.threads = 2;
    RenderController c;
    c.start(busy_scene(), s);
    const auto deadline = Clock::now() + 60s;
    while (c.status().passes_done < 2 && Clock::now() < deadline) std::this_thread::sleep_for(2ms);
    ASSERT_GE(c.status().passes_done, 2);
    c.stop();
    ASSERT_TRUE(c.wait_all_threads(10s));
    const RenderStatus st = c.status();
    EXPECT_EQ(st.state, RenderState::Stopped);
    EXPECT_GE(st.samples_done, 2);
    EXPECT_LT(st.samples_done, 4096);
    // Every pixel has the samples of the passes done: the whole image is there, none left black.
    const Image img = c.image();
    std::size_t black = 0;
    for (std::size_t p = 0; p < img.rgb.size(); p += 3) black += !img.rgb[p] && !img.rgb[p + 1] && !img.rgb[p + 2];
    EXPECT_LT(black, img.rgb.size() / 3 / 10) << "the busy scene fills the image";
}

TEST(RenderController, StopIsImmediateAndKeepsWhatWasRendered) {
    TileGate gate(1, 4);  // the job held in its render once four tiles are in
    RenderController c;
    c.set_after_tile_hook_for_tests([&gate](std::uint64_t job) { gate.at_tile(job); });
    GateOpener opener{gate};
    c.start(busy_scene(), heavy_settings());
    ASSERT_TRUE(gate.wait_held(60s));

    EXPECT_TRUE(returns_while_held(gate, [&] { c.stop(); })) << "stop() waited for the render";
    RenderStatus st = c.status();
    EXPECT_EQ(st.state, RenderState::Stopped);
    EXPECT_GE(st.tiles_done, 4);
    EXPECT_LT(st.tiles_done, st.tiles_total);
    const Image img = c.image();
    gate.open();
    EXPECT_TRUE(c.wait_all_threads(30s)) << "the render threads should end within a tile row of the gate opening";

    // The finished tiles are kept, the rest is black, and nothing arrives after the stop: the held
    // threads went on after it, with a tile done and maybe more rows.
    ASSERT_EQ(img.width, 1600);
    EXPECT_GT(lit_bytes(img), 0u);
    EXPECT_EQ(img.at(1599, 1199), glm::u8vec3(0));
    EXPECT_EQ(c.status().tiles_done, st.tiles_done);
    EXPECT_EQ(c.image().rgb, img.rgb);
    const double frozen = c.status().elapsed_seconds;
    std::this_thread::sleep_for(50ms);
    EXPECT_EQ(c.status().elapsed_seconds, frozen) << "elapsed time stops with the render";
}

TEST(RenderController, StopWhenIdleOrFinishedChangesNothing) {
    RenderController c;
    c.stop();
    EXPECT_EQ(c.status().state, RenderState::Idle);
    RenderJob s;
    s.width = 32;
    s.height = 24;
    c.start(busy_scene(4), s);
    ASSERT_TRUE(c.wait(30s));
    ASSERT_EQ(c.status().state, RenderState::Finished);
    c.stop();
    EXPECT_EQ(c.status().state, RenderState::Finished);
}

TEST(RenderController, RestartWhileRunningCancelsThePreviousJob) {
    TileGate gate(1, 1);  // the first job held in its render at its first tile
    RenderController c;
    c.set_after_tile_hook_for_tests([&gate](std::uint64_t job) { gate.at_tile(job); });
    GateOpener opener{gate};
    auto scene = busy_scene();
    c.start(scene, heavy_settings());
    ASSERT_TRUE(gate.wait_held(60s));

    RenderJob small;
    small.width = 64;
    small.height = 48;
    small.threads = 2;
    small.sampling.aa = 2;  // the settings of the new job, anti-aliasing included, reach its render
    small.sampling.aa_threshold = 0.05f;
    EXPECT_TRUE(returns_while_held(gate, [&] { c.start(scene, small); }))
        << "start() waited for the previous render";
    ASSERT_TRUE(c.wait(30s)) << "the new job finishes while the old one is held";
    RenderStatus st = c.status();
    EXPECT_EQ(st.job, 2u);
    EXPECT_EQ(st.state, RenderState::Finished);
    EXPECT_EQ(st.tiles_done, st.tiles_total);
    EXPECT_GE(c.reap(), 1) << "the first job is still held";
    // The first job goes on after the second finished: its late tiles never reach the image.
    gate.open();
    EXPECT_TRUE(c.wait_all_threads(30s)) << "the first job's threads should have stopped";
    EXPECT_EQ(c.status().tiles_done, st.tiles_done);
    Image img = c.image();
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
    RenderJob o;
    o.width = 64;
    o.height = 48;
    o.sampling.aa = 2;
    o.sampling.aa_threshold = 0.05f;
    Image direct(64, 48);
    render(*scene, o, direct);
    EXPECT_EQ(img.rgb, direct.rgb);
}

TEST(RenderController, ManyQuickRestartsEndCleanly) {
    RenderController c;
    auto scene = busy_scene();
    for (int i = 0; i < 20; ++i) c.start(scene, heavy_settings());
    c.stop();
    // Generous: a loaded machine can hold a thread off the CPU for seconds; one that never ends fails.
    EXPECT_TRUE(c.wait_all_threads(30s));
    EXPECT_EQ(c.status().job, 20u);
}

TEST(RenderController, DestructorDoesNotWaitForTheRender) {
    RenderJob s = heavy_settings();
    s.integrator.max_depth = 16;
    auto c = std::make_unique<RenderController>();
    c->start(endless_scene(), s);
    ASSERT_TRUE(wait_first_tile(*c, 60s));
    // The destructor on another thread, so that one that waits for the render fails the test
    // instead of hanging it.
    std::atomic<bool> done{false};
    std::thread destroy([&] {
        c.reset();
        done = true;
    });
    const auto deadline = Clock::now() + 10s;  // a tile row takes well under a second
    while (!done && Clock::now() < deadline) std::this_thread::sleep_for(2ms);
    if (!done) {
        ADD_FAILURE() << "the destructor still waits 10 s later: it waits for the render, which does not end";
        std::fflush(nullptr);
        std::_Exit(1);  // the render thread cannot be stopped from here
    }
    destroy.join();
}

TEST(RenderController, LoadsASceneFileAndReportsItsCounts) {
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "ball.sc", kBallScene);
    RenderController c;
    RenderJob s;
    s.width = 40;
    s.height = 30;
    c.start(path, {}, s);
    ASSERT_TRUE(c.wait(30s));
    RenderStatus st = c.status();
    ASSERT_EQ(st.state, RenderState::Finished) << st.message;
    EXPECT_EQ(st.scene_path, path);
    EXPECT_EQ(st.load_stats.objects, 1u);
    EXPECT_EQ(st.load_stats.lights, 1u);
    EXPECT_FALSE(st.scene_reused);
    Image img = c.image();
    EXPECT_GT(img.at(20, 15).x, 100);  // the red ball

    // Same file, same options, other render settings: the loaded scene is used again; a changed
    // file is loaded again.
    s.sampling.aa = 2;
    ASSERT_TRUE(c.start(path, {}, s));
    ASSERT_TRUE(c.wait(30s));
    EXPECT_TRUE(c.status().scene_reused);
    c.start(path, {}, s, /*force_reload=*/true);
    ASSERT_TRUE(c.wait(30s));
    EXPECT_FALSE(c.status().scene_reused);
    // A changed file with a later modification time, whatever the file system's resolution.
    const auto before = std::filesystem::last_write_time(path);
    test::write_file(dir, "ball.sc", std::string(kBallScene) + "light [ position -2 2 5 color 1 1 1 ]\n");
    std::filesystem::last_write_time(path, before + 2s);
    c.start(path, {}, s);
    ASSERT_TRUE(c.wait(30s));
    EXPECT_FALSE(c.status().scene_reused);
    EXPECT_EQ(c.status().load_stats.lights, 2u);
}

TEST(RenderController, ANewSceneTimeLoadsAgainAndTheDialectIsReported) {
    // A Brown/Tufts file whose ball moves right with t (scene-format.md §9.4).
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "moving.sc",
                                        "camera [ eye 0 0 5 focus 0 0 0 ]\nlight [ number 0 position 2 2 5 ]\n"
                                        "trans [ velocity 1 0 0 object sphere [ diffuse 1 0 0 ] ]\n");
    RenderController c;
    RenderJob s;
    s.width = 40;
    s.height = 30;
    LoadOptions at0;
    c.start(path, at0, s);
    ASSERT_TRUE(c.wait(30s));
    ASSERT_EQ(c.status().state, RenderState::Finished) << c.status().message;
    EXPECT_EQ(c.status().load_stats.dialect, Dialect::BrownTufts);
    EXPECT_GT(c.image().at(20, 15).x, 100);  // the ball in the middle
    LoadOptions at1 = at0;
    at1.time = 1;  // the ball moves one unit right: out of the middle pixel (radius 0.5)
    c.start(path, at1, s);
    ASSERT_TRUE(c.wait(30s));
    EXPECT_FALSE(c.status().scene_reused);
    EXPECT_EQ(c.image().at(20, 15), glm::u8vec3(0));
}

TEST(RenderController, ASceneWithErrorsEndsInTheFailedStateWithItsMessages) {
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "bad.sc", "camera [ eye 0 0 5 focus 0 0 0 ]\nlight [ position 1 2 ]\n"
                                                 "mastersubgraph root [ trans [ object blob [ ] ] ]\n");
    RenderController c;
    RenderJob s;
    s.width = 16;
    s.height = 16;
    c.start(path, {}, s);
    ASSERT_TRUE(c.wait(30s));
    RenderStatus st = c.status();
    EXPECT_EQ(st.state, RenderState::Failed);
    ASSERT_FALSE(st.diagnostics.empty());
    EXPECT_TRUE(has_errors(st.diagnostics));
    // "file:line:col: error: ..." with the file as given.
    EXPECT_EQ(st.diagnostics[0].str().rfind(path + ":", 0), 0u) << st.diagnostics[0].str();
    EXPECT_NE(st.message.find("error:"), std::string::npos) << st.message;
    EXPECT_EQ(st.tiles_total, 0);
    EXPECT_TRUE(c.wait_all_threads(1s));

    // A missing file fails the same way, and the controller can start again after a failure.
    c.start(dir + "/nope.sc", {}, s);
    ASSERT_TRUE(c.wait(30s));
    EXPECT_EQ(c.status().state, RenderState::Failed);
    EXPECT_FALSE(c.status().message.empty());
    test::write_file(dir, "bad.sc", kBallScene);
    c.start(path, {}, s);
    ASSERT_TRUE(c.wait(30s));
    EXPECT_EQ(c.status().state, RenderState::Finished);
    EXPECT_TRUE(c.status().diagnostics.empty());
    EXPECT_EQ(c.status().message, "");
}

TEST(RenderController, AMissingTextureIsReportedThenCheckeredOrOverridden) {
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "tex.sc", R"(camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [
  trans [ object cube [ diffuse 1 1 1 texture nowhere/wood.bmp 1 1 ] ]
]
)");
    RenderController c;
    RenderJob s;
    s.width = 40;
    s.height = 30;
    c.start(path, {}, s);
    ASSERT_TRUE(c.wait(30s));
    RenderStatus st = c.status();
    ASSERT_EQ(st.state, RenderState::MissingTextures) << st.message;
    ASSERT_EQ(st.missing_textures.size(), 1u);
    EXPECT_EQ(st.missing_textures[0].name, "nowhere/wood.bmp");
    EXPECT_EQ(st.missing_textures[0].loc.line, 4);
    EXPECT_FALSE(st.missing_textures[0].tried.empty());

    // Cancel in the viewer: the checkerboard, with a warning.
    LoadOptions checker;
    checker.textures.missing = MissingTexturePolicy::Checker;
    c.start(path, checker, s);
    ASSERT_TRUE(c.wait(30s));
    st = c.status();
    EXPECT_EQ(st.state, RenderState::Finished) << st.message;
    EXPECT_NE(st.message.find("warning:"), std::string::npos) << st.message;

    // A file picked by the user, for the name as written.
    Image tex(4, 4);
    for (auto& v : tex.rgb) v = 200;
    ASSERT_EQ(write_image(tex, dir + "/picked.png"), "");
    LoadOptions picked;
    picked.textures.overrides["nowhere/wood.bmp"] = dir + "/picked.png";
    c.start(path, picked, s);
    ASSERT_TRUE(c.wait(30s));
    st = c.status();
    EXPECT_EQ(st.state, RenderState::Finished) << st.message;
    EXPECT_TRUE(st.missing_textures.empty());
    EXPECT_EQ(st.message, "");
}

TEST(RenderController, StateNamesAreReadable) {
    EXPECT_STREQ(state_name(RenderState::MissingTextures), "missing textures");
    EXPECT_TRUE(is_busy(RenderState::Loading));
    EXPECT_FALSE(is_busy(RenderState::Stopped));
}

// A moving camera: coarse frames first (1/8, 1/4, 1/2, each the same camera at that size, shown
// enlarged), then the full image, which is exactly that of a render without them.
TEST(RenderController, CoarseFramesComeFirstThenTheSameFullImage) {
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "ball.sc", kBallScene);
    RenderJob s;
    s.width = 80;
    s.height = 60;
    s.threads = 2;
    RenderController plain;
    plain.start(path, {}, s);
    ASSERT_TRUE(plain.wait(30s));
    ASSERT_EQ(plain.status().state, RenderState::Finished);
    EXPECT_EQ(plain.status().frames, 0u);
    EXPECT_EQ(plain.status().file_camera.eye, glm::vec3(0, 0, 5)) << "the file's camera as written";

    RenderController c;
    c.start(path, {}, s, false, /*coarse_first=*/true);
    // The 1/8 frame is the 10 x 8 render of the same camera, each pixel an 8 x 8 block.
    RenderJob eighth = s;
    eighth.width = 10;
    eighth.height = 8;
    Image small(eighth.width, eighth.height);
    render(*load_scene(path).scene, eighth, small);
    bool saw_eighth = false;
    for (auto deadline = Clock::now() + 30s; Clock::now() < deadline && !saw_eighth;) {
        const RenderStatus st = c.status();
        if (st.frames >= 1 && st.preview_divisor == 8) {
            const Image shown = c.image();
            if (c.status().frames == 1) {  // still that frame
                saw_eighth = true;
                EXPECT_EQ(shown.rgb, enlarge_nearest(small, 80, 60).rgb);
            }
        }
        if (!is_busy(st.state)) break;
        std::this_thread::sleep_for(100us);
    }
    ASSERT_TRUE(c.wait(30s));
    const RenderStatus st = c.status();
    ASSERT_EQ(st.state, RenderState::Finished);
    EXPECT_EQ(st.frames, 3u);
    EXPECT_EQ(st.preview_divisor, 1);
    EXPECT_EQ(c.image().rgb, plain.image().rgb);
    (void)saw_eighth;  // a fast machine may pass it between two looks; the count above still holds
}

TEST(RenderController, AskingAgainForTheSameImageDoesNothing) {
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "ball.sc", kBallScene);
    RenderController c;
    RenderJob s;
    s.width = 40;
    s.height = 30;
    ASSERT_TRUE(c.start(path, {}, s));
    ASSERT_TRUE(c.wait(30s));
    const std::uint64_t job = c.status().job;
    EXPECT_FALSE(c.start(path, {}, s)) << "nothing changed: no new job";
    EXPECT_EQ(c.status().job, job);
    EXPECT_EQ(c.status().state, RenderState::Finished);
    s.threads = 1;  // how it is made, not what: the same pixels
    s.tile_size = 7;
    EXPECT_FALSE(c.start(path, {}, s));
    // Anything that changes the pixels renders again.
    RenderJob deeper = s;
    deeper.integrator.max_depth = 2;
    EXPECT_TRUE(c.start(path, {}, deeper));
    ASSERT_TRUE(c.wait(30s));
    RenderJob moved = deeper;
    moved.camera = Camera{};
    EXPECT_TRUE(c.start(path, {}, moved));
    ASSERT_TRUE(c.wait(30s));
    LoadOptions later;
    later.time = 1;
    EXPECT_TRUE(c.start(path, later, moved));
    ASSERT_TRUE(c.wait(30s));
    EXPECT_TRUE(c.start(path, later, moved, /*force_reload=*/true)) << "Reload always reads the file";
    ASSERT_TRUE(c.wait(30s));
    // A stopped job is rendered again when asked.
    c.stop();
    EXPECT_EQ(c.status().state, RenderState::Finished) << "stop after the end changes nothing";
    const auto before = std::filesystem::last_write_time(path);
    std::filesystem::last_write_time(path, before + 2s);  // the file touched: rendered again
    EXPECT_TRUE(c.start(path, later, moved));
    c.stop();
    EXPECT_TRUE(c.start(path, later, moved));
    ASSERT_TRUE(c.wait(30s));
}

TEST(RenderController, ARenderAgainKeepsTheOldPictureUntilItsTilesAreReplaced) {
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "ball.sc", kBallScene);
    RenderController c;
    TileGate gate(2, 1);  // holds the second job after its first tile
    GateOpener opener{gate};
    c.set_after_tile_hook_for_tests([&](std::uint64_t job) { gate.at_tile(job); });
    RenderJob s;
    s.width = 64;
    s.height = 64;
    s.tile_size = 8;
    s.threads = 1;
    ASSERT_TRUE(c.start(path, {}, s));
    ASSERT_TRUE(c.wait(30s));
    const Image first = c.image();
    ASSERT_GT(lit_bytes(first), 50u);  // the red ball, about 10 pixels across
    RenderJob spp4 = s;
    spp4.sampling.spp = 4;
    ASSERT_TRUE(c.start(path, {}, spp4));
    ASSERT_TRUE(gate.wait_held(60s));
    // One tile of the new job is in (the top left, 8 x 8, black background); the ball in the
    // middle is still the last picture's, not a blank.
    const Image during = c.image();
    EXPECT_EQ(c.status().tiles_done, 1);
    EXPECT_EQ(during.at(32, 32), first.at(32, 32));
    EXPECT_GT(during.at(32, 32).x, 100);
    EXPECT_EQ(during.rgb, first.rgb) << "its first tile is background in both";
    gate.open();
    ASSERT_TRUE(c.wait(30s));
}

// The exposure scales the picture's radiance before the view transform, so a light brighter than
// white (here a glowing ball of 4) comes back below white; changing either renders nothing again.
TEST(RenderController, ExposureAndViewActOnTheRadianceNotOnTheBytes) {
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, test::translate_scale({0, 0, -5}, glm::vec3(2)), test::emitter(glm::vec3(4)));
    RenderController c;
    RenderJob s;
    s.width = 16;
    s.height = 16;
    s.integrator.mode = RenderMode::Path;
    c.start(std::make_shared<const Scene>(b.build()), s);
    ASSERT_TRUE(c.wait(30s));
    ASSERT_EQ(c.status().state, RenderState::Finished);
    EXPECT_FLOAT_EQ(c.linear_image().rgb[8 * 16 + 8].x, 4.0f);
    EXPECT_EQ(c.image().at(8, 8).x, 255);
    const std::uint64_t job = c.status().job;
    c.set_display(ViewTransform::Linear, -3.0f);  // 4 / 8
    EXPECT_EQ(c.image().at(8, 8).x, 128);
    c.set_display(ViewTransform::Srgb, -3.0f);
    EXPECT_EQ(c.image().at(8, 8).x, 188);  // the sRGB curve at 0.5
    EXPECT_FALSE(c.image().at(0, 0).x) << "the background stays black";
    c.set_display(ViewTransform::Linear, 0.0f);
    EXPECT_EQ(c.image().at(8, 8).x, 255);
    EXPECT_EQ(c.status().job, job) << "no render again";
}

TEST(RenderController, EnlargingRepeatsEachPixelNearestNeighbour) {
    Image small(2, 1);
    small.rgb = {10, 20, 30, 40, 50, 60};
    const Image big = enlarge_nearest(small, 5, 2);
    // Columns 0-2 come from pixel 0 (x * 2 / 5 = 0, 0, 0, 1, 1), both rows.
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 5; ++x) EXPECT_EQ(big.at(x, y), x < 3 ? glm::u8vec3(10, 20, 30) : glm::u8vec3(40, 50, 60));
}

}  // namespace
}  // namespace whitted::viewer
#endif
