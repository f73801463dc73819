// The viewer's render controller, without a display: start, progress, stop, restart, error states.
#if __has_include("render_controller.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "render_controller.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include <gtest/gtest.h>

#include "film/image_io.h"
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
RenderSettings heavy_settings() {
    RenderSettings s;
    s.width = 1600;
    s.height = 1200;
    s.max_depth = 40;
    s.threads = 2;
    s.tile_size = 16;
    return s;
}

std::size_t lit_bytes(const Image& img) {
    std::size_t n = 0;
    for (auto v : img.rgb) n += v != 0;
    return n;
}

const char* kBallScene = R"(camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]
)";

TEST(RenderController, StartsIdle) {
    RenderController c;
    EXPECT_EQ(c.status().state, RenderState::Idle);
    Image img;
    std::uint64_t version = 0;
    EXPECT_FALSE(c.copy_image_if_changed(img, version));
}

TEST(RenderController, RendersProgressivelyToTheSameImageAsADirectRender) {
    auto scene = busy_scene();
    RenderSettings s;
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

    RenderOptions o;
    o.width = s.width;
    o.height = s.height;
    o.max_depth = s.max_depth;
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

TEST(RenderController, StopIsImmediateAndKeepsWhatWasRendered) {
    RenderController c;
    c.start(busy_scene(), heavy_settings());
    // Wait for a few tiles.
    const auto deadline = Clock::now() + 30s;
    while (c.status().tiles_done < 4 && Clock::now() < deadline) std::this_thread::sleep_for(2ms);
    ASSERT_GE(c.status().tiles_done, 4);

    const auto t0 = Clock::now();
    c.stop();
    const auto stop_took = Clock::now() - t0;
    EXPECT_LT(stop_took, 50ms) << "stop() must not wait for the render";
    RenderStatus st = c.status();
    EXPECT_EQ(st.state, RenderState::Stopped);
    EXPECT_LT(st.tiles_done, st.tiles_total);
    EXPECT_TRUE(c.wait_all_threads(500ms)) << "the render threads should end within a fraction of a second";

    // The finished tiles are kept, the rest is black, and nothing arrives after the stop.
    Image img = c.image();
    ASSERT_EQ(img.width, 1600);
    EXPECT_GT(lit_bytes(img), 0u);
    EXPECT_EQ(img.at(1599, 1199), glm::u8vec3(0));
    std::this_thread::sleep_for(100ms);
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
    RenderSettings s;
    s.width = 32;
    s.height = 24;
    c.start(busy_scene(4), s);
    ASSERT_TRUE(c.wait(30s));
    ASSERT_EQ(c.status().state, RenderState::Finished);
    c.stop();
    EXPECT_EQ(c.status().state, RenderState::Finished);
}

TEST(RenderController, RestartWhileRunningCancelsThePreviousJob) {
    RenderController c;
    auto scene = busy_scene();
    c.start(scene, heavy_settings());
    while (c.status().tiles_done < 1) std::this_thread::sleep_for(2ms);

    RenderSettings small;
    small.width = 64;
    small.height = 48;
    small.threads = 2;
    small.aa = 2;  // the settings of the new job, anti-aliasing included, reach its render
    small.aa_threshold = 0.05f;
    const auto t0 = Clock::now();
    c.start(scene, small);
    EXPECT_LT(Clock::now() - t0, 50ms) << "start() must not wait for the previous render";
    ASSERT_TRUE(c.wait(30s));
    RenderStatus st = c.status();
    EXPECT_EQ(st.job, 2u);
    EXPECT_EQ(st.state, RenderState::Finished);
    EXPECT_EQ(st.tiles_done, st.tiles_total);
    EXPECT_TRUE(c.wait_all_threads(500ms)) << "the first job's threads should have stopped";
    Image img = c.image();
    EXPECT_EQ(img.width, 64);
    EXPECT_EQ(img.height, 48);
    // The late tiles of the first job never reach the second job's image.
    RenderOptions o;
    o.width = 64;
    o.height = 48;
    o.aa = 2;
    o.aa_threshold = 0.05f;
    Image direct(64, 48);
    render(*scene, o, direct);
    EXPECT_EQ(img.rgb, direct.rgb);
}

TEST(RenderController, ManyQuickRestartsEndCleanly) {
    RenderController c;
    auto scene = busy_scene();
    for (int i = 0; i < 20; ++i) c.start(scene, heavy_settings());
    c.stop();
    EXPECT_TRUE(c.wait_all_threads(2s));
    EXPECT_EQ(c.status().job, 20u);
}

TEST(RenderController, DestructorDoesNotWaitForTheRender) {
    const auto t0 = Clock::now();
    {
        RenderController c;
        c.start(busy_scene(), heavy_settings());
        while (c.status().tiles_done < 1) std::this_thread::sleep_for(2ms);
    }
    EXPECT_LT(Clock::now() - t0, 10s);  // the full render would take far longer
}

TEST(RenderController, LoadsASceneFileAndReportsItsCounts) {
    std::string dir = test::make_temp_dir();
    std::string path = test::write_file(dir, "ball.sc", kBallScene);
    RenderController c;
    RenderSettings s;
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

    // Same file, same options: the loaded scene is used again; a changed file is loaded again.
    c.start(path, {}, s);
    ASSERT_TRUE(c.wait(30s));
    EXPECT_TRUE(c.status().scene_reused);
    c.start(path, {}, s, /*force_reload=*/true);
    ASSERT_TRUE(c.wait(30s));
    EXPECT_FALSE(c.status().scene_reused);
    std::this_thread::sleep_for(20ms);
    test::write_file(dir, "ball.sc", std::string(kBallScene) + "light [ position -2 2 5 color 1 1 1 ]\n");
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
    RenderSettings s;
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
    RenderSettings s;
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
    RenderSettings s;
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

}  // namespace
}  // namespace whitted::viewer
#endif
