// whitted-view end to end on a real X server (Xvfb): a real screen grab (xwd) compared with the
// command-line renderer's image of the same scene and size; errors on the screen; the tool bar's layout.
#ifdef WHITTED_VIEWER_PATH
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

TEST_F(ViewerE2E, TheWindowShowsTheSameImageAsTheCommandLineRenderer) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xwd", "convert"}));
    const std::string xwd = find_on_path("xwd"), convert = find_on_path("convert");

    const int W = 320, H = 240;
    auto cli = run_process({test::cli_path(), scene_, "-o", dir_ + "/cli.png", "--width", std::to_string(W),
                            "--height", std::to_string(H), "-q"});
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    Image expected;
    ASSERT_EQ(read_image(dir_ + "/cli.png", expected), "");

    // The viewer renders on start and says when the image is on screen.
    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", std::to_string(W), "--height", std::to_string(H),
                  "--threads", "2", "--ready-file", ready},
                 dir_ + "/viewer.log", {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    const auto deadline = std::chrono::steady_clock::now() + 120s;
    while (!fs::exists(ready) && std::chrono::steady_clock::now() < deadline) {
        ASSERT_EQ(viewer.wait_exit(0ms), -1) << "the viewer exited early:\n" << viewer.output();
        std::this_thread::sleep_for(50ms);
    }
    ASSERT_TRUE(fs::exists(ready)) << "the render did not finish in time:\n" << viewer.output();
    const Ready r = read_ready(ready);
    EXPECT_EQ(r.state, "finished");
    const int wx = r.window.x, ww = r.window.w, ix = r.image.x, iy = r.image.y;
    EXPECT_EQ(r.image.w, W);
    EXPECT_EQ(r.image.h, H);

    // A real screen grab of the whole X screen.
    auto grab = run_process({"/bin/sh", "-c",
                             "'" + xwd + "' -root -silent -display " + x.display() + " | '" + convert + "' xwd:- '" +
                                 dir_ + "/screen.png'"});
    ASSERT_EQ(grab.exit_code, 0) << grab.output;
    Image screen;
    ASSERT_EQ(read_image(dir_ + "/screen.png", screen), "");
    ASSERT_EQ(screen.width, 1280);

    auto [fx, fy] = find_subimage(screen, expected, {ix, iy});
    ASSERT_GE(fx, 0) << "the rendered image was not found on the screen (see " << dir_ << "/screen.png)";
    EXPECT_EQ(fx, ix) << "the viewer reported the image at another place";
    EXPECT_EQ(fy, iy);
    // The image lies inside the window.
    EXPECT_GE(fx, wx);
    EXPECT_LE(fx + W, wx + ww);

    // Ctrl-C / SIGTERM closes the window cleanly.
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

TEST_F(ViewerE2E, ScreenshotFlagSavesTheDisplayedPixels) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    auto cli = run_process({test::cli_path(), scene_, "-o", dir_ + "/cli.png", "--width", "200", "--height", "150",
                            "--mode", "normals", "-q"});
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", "200", "--height", "150", "--mode", "normals",
                  "--screenshot", dir_ + "/shot.png"},
                 dir_ + "/viewer.log", {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    ASSERT_EQ(viewer.wait_exit(120s), 0) << viewer.output();
    Image expected, shot;
    ASSERT_EQ(read_image(dir_ + "/cli.png", expected), "");
    ASSERT_EQ(read_image(dir_ + "/shot.png", shot), "");
    ASSERT_EQ(shot.width, 200);
    ASSERT_EQ(shot.height, 150);
    EXPECT_EQ(find_subimage(shot, expected, {0, 0}), std::make_pair(0, 0));
}

TEST_F(ViewerE2E, ASceneWithErrorsIsReportedNotACrash) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    std::ofstream(scene_) << "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n";
    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--exit-when-done", "--ready-file", ready}, dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    ASSERT_EQ(viewer.wait_exit(60s), 2) << viewer.output();
    const std::string output = viewer.output();
    EXPECT_NE(output.find(scene_ + ":2:"), std::string::npos) << output;

    // The window showed the error, as FILE:LINE:COL: error: ..., in the messages panel and the status bar.
    Ready r = read_ready(ready);
    EXPECT_EQ(r.state, "failed");
    ASSERT_EQ(r.panel.size(), 1u) << output;
    // In the window, the path is relative to the scene's folder; on stderr, as given.
    const std::string& error = r.panel[0];
    ASSERT_EQ(error.rfind("scene.sc:2:", 0), 0u) << error;
    // After "FILE:2:": the column's digits, then the message.
    const std::string rest = error.substr(std::string("scene.sc:2:").size());
    const std::size_t digits = rest.find_first_not_of("0123456789");
    EXPECT_GT(digits, 0u) << error;
    EXPECT_EQ(rest.substr(digits).rfind(": error: unknown object type 'blob'", 0), 0u) << error;
    EXPECT_NE(output.find(dir_ + "/" + error + "\n"), std::string::npos) << "the panel and stderr differ:\n" << output;
    EXPECT_EQ(drawn_text(r.labels["message"]), " " + error);
    EXPECT_EQ(drawn_text(r.labels["progress"]), " the scene has errors");
}

// The error of ASceneWithErrorsIsReportedNotACrash as the user reads it on the screen.
TEST_F(ViewerE2E, ASceneWithErrorsShowsTheErrorOnTheScreen) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xwd", "convert", "tesseract"}));
    std::ofstream(scene_) << "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n";
    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--ready-file", ready}, dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "failed"; }, 60s))
        << viewer.output();
    const std::string png = dir_ + "/screen.png";
    grab_screen(x.display(), png);
    // In the status bar: the error (after the scene's folder, which OCR need not spell) and the
    // state; in the messages panel: the error.
    const std::string message = screen_text(png, r.fields["message"], Lines::One);
    EXPECT_TRUE(reads(message, "scene.sc:2:")) << message << " (see " << png << ")";
    EXPECT_TRUE(reads(message, "error: unknown object type 'blob'")) << message << " (see " << png << ")";
    const std::string progress = screen_text(png, r.fields["progress"], Lines::One);
    EXPECT_TRUE(reads(progress, "the scene has errors")) << progress << " (see " << png << ")";
    const Box panel{r.window.x, r.area.y + r.area.h, r.window.w, r.fields["scene"].y - (r.area.y + r.area.h)};
    const std::string panel_text = screen_text(png, panel, Lines::Block);
    EXPECT_TRUE(reads(panel_text, "scene.sc:2:")) << panel_text << " (see " << png << ")";
    EXPECT_TRUE(reads(panel_text, "error: unknown object type 'blob'")) << panel_text << " (see " << png << ")";
    viewer.signal(SIGTERM);
    EXPECT_NE(viewer.wait_exit(10s), -1) << viewer.output();
}

TEST_F(ViewerE2E, TheToolBarKeepsItsLayoutWhenTheWindowIsResized) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool", "xwd", "convert"}));

    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", "160", "--height", "120", "--threads", "2", "--ready-file",
                  ready},
                 dir_ + "/viewer.log", {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready made;
    ASSERT_TRUE(wait_for_ready(viewer, ready, made, [](const Ready&) { return true; })) << viewer.output();
    ASSERT_EQ(made.window.w, 1000);  // the default size, wide enough for every tool
    ASSERT_EQ(made.tools.size(), 10u);  // render, stop, width, height, fit, depth, mode, AA, SPP, threads
    for (const auto& [name, b] : made.tools) {
        EXPECT_TRUE(b.shown) << name;
        EXPECT_EQ(b.h, 24) << name;
    }
    const Image made_screen = grab_screen(x.display(), dir_ + "/made.png");
    const std::string window = xdotool(x.display(), "search --name whitted-view");
    ASSERT_FALSE(window.empty());

    for (auto [W, H] : {std::pair{600, 400}, std::pair{1270, 950}}) {
        SCOPED_TRACE(std::to_string(W) + "x" + std::to_string(H));
        fs::remove(ready);
        xdotool(x.display(), "windowsize " + window + " " + std::to_string(W) + " " + std::to_string(H));
        Ready r;
        ASSERT_TRUE(wait_for_ready(viewer, ready, r, [&](const Ready& n) { return n.window.w == W && n.window.h == H; },
                                   20s))
            << "no ready file for the new size:\n" << viewer.output();
        EXPECT_EQ(r.job, made.job) << "without Fit window a resize renders nothing";

        // Every tool keeps the size and place it was made with, relative to the window; those
        // that would stick out are hidden, and no two that are shown overlap.
        ASSERT_EQ(r.tools.size(), made.tools.size());
        int shown_right = 0;
        for (std::size_t i = 0; i < r.tools.size(); ++i) {
            const auto& [name, b] = r.tools[i];
            const Box& m = made.tools[i].second;
            EXPECT_EQ(b.x - r.window.x, m.x - made.window.x) << name;
            EXPECT_EQ(b.y - r.window.y, m.y - made.window.y) << name;
            EXPECT_EQ(b.w, m.w) << name;
            EXPECT_EQ(b.h, m.h) << name;
            if (!b.shown) {
                EXPECT_GT(b.right(), r.window.right() - 10) << name << " is hidden though it fits";
                continue;
            }
            EXPECT_LE(b.right(), r.window.right()) << name;
            EXPECT_TRUE(r.tools[i > 0 ? i - 1 : 0].second.shown) << name << " is shown after a hidden one";
            for (std::size_t j = 0; j < i; ++j)
                EXPECT_FALSE(overlap(b, r.tools[j].second)) << name << " overlaps " << r.tools[j].first;
            shown_right = std::max(shown_right, b.right() - r.window.x);
        }
        EXPECT_TRUE(r.tools[0].second.shown && r.tools[1].second.shown) << "Render and Stop always fit";

        // The tool bar looks as it did at the start, as far as it is shown.
        const Image screen = grab_screen(x.display(), dir_ + "/resized.png");
        const int top = made.tools[0].second.y - made.window.y - 2, rows = made.tools[0].second.h + 4;
        int differ = 0;
        for (int yy = top; yy < top + rows; ++yy)
            for (int xx = 0; xx < shown_right; ++xx)
                differ += made_screen.at(made.window.x + xx, made.window.y + yy) !=
                          screen.at(r.window.x + xx, r.window.y + yy);
        EXPECT_EQ(differ, 0) << "the tool bar changed (see " << dir_ << "/made.png and resized.png)";

        // The status bar's fields fill its row left to right; the progress text fits its field.
        const Box &scene = r.fields["scene"], &progress = r.fields["progress"], &message = r.fields["message"];
        EXPECT_EQ(scene.x, r.window.x);
        EXPECT_EQ(progress.x, scene.right());
        EXPECT_EQ(message.x, progress.right());
        EXPECT_EQ(message.right(), r.window.right());
        EXPECT_EQ(scene.y + scene.h, r.window.y + r.window.h);
        EXPECT_GE(progress.w, r.needs["progress"]);
    }
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

}  // namespace
}  // namespace whitted
#endif
