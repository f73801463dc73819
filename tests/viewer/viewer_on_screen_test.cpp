// whitted-view on a real X server, checked on the screen: reloading a changed scene, Fit window,
// names drawn as written, the missing-texture dialog.
#ifdef WHITTED_VIEWER_PATH
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

// --watch: saving the scene reloads it and renders again; the window then shows the new scene.
TEST_F(ViewerOnScreen, AChangedSceneIsReloadedAndShown) {
    auto viewer = start_viewer({"--watch"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen1.png"), red_, first.image))
        << "the red sphere is not on the screen (see " << dir_ << "/screen1.png)";

    rewrite_scene(scene_, sphere_scene("0.1 0.1 0.9"));
    Ready again;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, again,
                               [&](const Ready& n) { return n.job > first.job && n.state == "finished"; }, 30s))
        << "the changed scene was not rendered again:\n" << viewer->output();
    EXPECT_FALSE(again.reused) << "the changed file must be loaded again";
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen2.png"), blue_, again.image))
        << "the blue sphere is not on the screen (see " << dir_ << "/screen2.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Without --watch a saved change is not picked up (until File > Reload, Ctrl+R).
TEST_F(ViewerOnScreen, WithoutWatchAChangedSceneIsNotReloaded) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();

    Ready before;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, before, [](const Ready&) { return true; }, 5s)) << viewer->output();
    rewrite_scene(scene_, sphere_scene("0.1 0.1 0.9"));
    // Three ticks of the viewer's watch timer: with --watch, the change would have been seen at
    // the first and its render reported by the third.
    Ready later;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, later,
                               [&](const Ready& n) { return n.watch_ticks >= before.watch_ticks + 3; }, 30s))
        << viewer->output();
    EXPECT_EQ(later.job, first.job) << "the scene was rendered again without --watch";
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen1.png"), red_, later.image))
        << "the red sphere is no longer on the screen (see " << dir_ << "/screen1.png)";

    // The change was real: reloading by hand shows it.
    const std::string window = xdotool(x_.display(), "search --name whitted-view");
    xdotool(x_.display(), "windowfocus --sync " + window + " key ctrl+r");
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, later,
                               [&](const Ready& n) { return n.job > first.job && n.state == "finished"; }, 30s))
        << viewer->output();
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen2.png"), blue_, later.image))
        << "the blue sphere is not on the screen after Reload (see " << dir_ << "/screen2.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Fit window: once a resize has settled the scene is rendered again (without loading it again)
// at the size of the new image area; resizes in quick succession give one render.
TEST_F(ViewerOnScreen, FitWindowRendersAgainAtTheNewSizeAfterAResize) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    auto viewer = start_viewer({"--fit", "--window-size", "640x480"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_EQ(first.window.w, 640);
    EXPECT_EQ(first.area.w, 640);
    EXPECT_LT(first.area.h, 480);
    EXPECT_EQ(first.image.w, first.area.w);
    EXPECT_EQ(first.image.h, first.area.h);
    const int chrome_h = first.window.h - first.area.h;  // menu, tool and status bars

    const std::string window = xdotool(x_.display(), "search --name whitted-view");
    xdotool(x_.display(), "windowsize " + window + " 600 400 windowsize " + window + " 700 500");
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r,
                               [&](const Ready& n) {
                                   return n.window.w == 700 && n.window.h == 500 && n.job > first.job &&
                                          n.state == "finished";
                               },
                               30s))
        << "no render at the new size:\n" << viewer->output();
    EXPECT_EQ(r.job, first.job + 1) << "one render for the resizes, after they settled";
    EXPECT_TRUE(r.reused) << "the unchanged scene is not loaded again";
    EXPECT_EQ(r.area.w, 700);
    EXPECT_EQ(r.area.h, 500 - chrome_h);
    const Image expected = cli_image(scene_, r.area.w, r.area.h, dir_ + "/fitted.png");
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen.png"), expected, r.image))
        << "the image at the new size is not on the screen (see " << dir_ << "/screen.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Names with '@' (the scene's, a texture's) show as written in the status bar and the panel.
TEST_F(ViewerOnScreen, NamesWithAnAtSignShowAsWritten) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    scene_ = dir_ + "/a@b.sc";
    std::ofstream(scene_) << sphere_scene("1 1 1", "t@x.png");
    auto viewer = start_viewer({"--missing-textures", "checker"});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_EQ(drawn_text(r.labels["scene"]).rfind(" a@b.sc: 1 objects", 0), 0u) << r.labels["scene"];
    const std::string warning = "a@b.sc:4:";  // relative to the scene's folder
    const std::string texture = "warning: texture 't@x.png': not found (drawn as a checkerboard)";
    const std::string message = drawn_text(r.labels["message"]);
    EXPECT_EQ(message.rfind(" " + warning, 0), 0u) << r.labels["message"];
    EXPECT_NE(message.find(texture), std::string::npos) << r.labels["message"];
    ASSERT_FALSE(r.panel.empty());
    EXPECT_EQ(r.panel[0].rfind(warning, 0), 0u) << r.panel[0];
    EXPECT_NE(r.panel[0].find(texture), std::string::npos) << r.panel[0];

    // What the user reads on the screen: the names with their '@', in the status bar and the
    // messages panel (between the image area and the status bar).
    const std::string png = dir_ + "/screen.png";
    grab_screen(x_.display(), png);
    const std::string scene_field = screen_text(png, r.fields["scene"], Lines::One);
    EXPECT_TRUE(reads(scene_field, "a@b.sc: 1 objects")) << scene_field << " (see " << png << ")";
    const std::string message_field = screen_text(png, r.fields["message"], Lines::One);
    EXPECT_TRUE(reads(message_field, "a@b.sc:4:")) << message_field << " (see " << png << ")";
    EXPECT_TRUE(reads(message_field, "warning: texture 't@x.png'")) << message_field << " (see " << png << ")";
    const Box panel{r.window.x, r.area.y + r.area.h, r.window.w, r.fields["scene"].y - (r.area.y + r.area.h)};
    const std::string panel_text = screen_text(png, panel, Lines::Block);
    EXPECT_TRUE(reads(panel_text, "a@b.sc:4:")) << panel_text << " (see " << png << ")";
    EXPECT_TRUE(reads(panel_text, texture)) << panel_text << " (see " << png << ")";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// A texture that is not found: the viewer asks for its file in a dialog; Cancel draws it as the
// magenta/black checkerboard, with a warning naming it; the viewer then quits cleanly.
TEST_F(ViewerOnScreen, CancellingTheMissingTextureDialogDrawsACheckerboard) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    std::ofstream(scene_) << sphere_scene("1 1 1", "nowhere.png");
    auto viewer = start_viewer({"--mode", "raycast"});  // unlit: the texture's own colours

    // The dialog is mapped and drawn on the screen while the viewer waits for an answer.
    const std::string dialog = wait_for_window(x_.display(), "^Texture not found$", 60s);
    ASSERT_FALSE(dialog.empty()) << "no dialog was shown:\n" << viewer->output();
    const Box d = window_geometry(x_.display(), dialog);
    ASSERT_EQ(d.w, 640) << "the dialog's width, as made in ask_texture_dialog()";
    bool shown = false;
    for (auto deadline = std::chrono::steady_clock::now() + 10s;
         !shown && std::chrono::steady_clock::now() < deadline; std::this_thread::sleep_for(50ms))
        shown = shows_a_dialog(grab_screen(x_.display(), dir_ + "/dialog.png"), d);
    ASSERT_TRUE(shown) << "the dialog is not on the screen (see " << dir_ << "/dialog.png)";
    EXPECT_EQ(visible_windows(x_.display(), "^Texture not found$").size(), 1u);

    // A click on "Cancel (checkerboard)": 180×28 at (w - 340, h - 38) in the dialog.
    xdotool(x_.display(), "mousemove --window " + dialog + " " + std::to_string(d.w - 250) + " " +
                              std::to_string(d.h - 24) + " click 1");
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }, 60s))
        << "no render after Cancel:\n" << viewer->output();
    EXPECT_TRUE(visible_windows(x_.display(), "Texture").empty()) << "the dialog, or a file chooser, is open";

    // Inside the sphere (about 36 pixels across, in the middle) only the board's colours and
    // their blends at the squares' edges: both colours, and nothing off the line between them.
    const Image screen = grab_screen(x_.display(), dir_ + "/checker.png");
    ASSERT_EQ(r.image.w, kW);
    ASSERT_EQ(r.image.h, kH);
    int magenta = 0, black = 0, other = 0;
    const int cx = r.image.x + kW / 2, cy = r.image.y + kH / 2;
    for (int y = cy - 8; y < cy + 8; ++y)
        for (int x = cx - 8; x < cx + 8; ++x) {
            const glm::ivec3 c(screen.at(x, y));
            if (c.x >= 254 && c.y <= 1 && c.z >= 254) ++magenta;
            else if (c.x <= 1 && c.y <= 1 && c.z <= 1) ++black;
            else if (c.y > 1 || std::abs(c.x - c.z) > 1) ++other;
        }
    EXPECT_GT(magenta, 0) << "see " << dir_ << "/checker.png";
    EXPECT_GT(black, 0) << "see " << dir_ << "/checker.png";
    EXPECT_EQ(other, 0) << "see " << dir_ << "/checker.png";

    // The messages panel and the status bar name the texture.
    ASSERT_FALSE(r.panel.empty());
    EXPECT_EQ(r.panel[0].rfind("scene.sc:4:", 0), 0u) << r.panel[0];
    EXPECT_NE(r.panel[0].find("warning: texture 'nowhere.png': not found (drawn as a checkerboard)"),
              std::string::npos)
        << r.panel[0];
    EXPECT_EQ(drawn_text(r.labels["message"]).rfind(" warning: texture 'nowhere.png' drawn as a checkerboard", 0), 0u)
        << r.labels["message"];

    // File > Quit (Ctrl+Q) ends it with 0, leaving no process behind.
    const std::vector<std::string> main_window = visible_windows(x_.display(), "^whitted-view");
    ASSERT_EQ(main_window.size(), 1u);
    xdotool(x_.display(), "windowfocus --sync " + main_window[0] + " key ctrl+q");
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
    EXPECT_EQ(processes_left(), std::vector<pid_t>{});
}

}  // namespace
}  // namespace whitted
#endif
