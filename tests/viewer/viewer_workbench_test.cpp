// The workbench, on a real X server: the camera moved on the image, back home, into the
// file; the error loop; what is remembered between runs.
#ifdef WHITTED_VIEWER_PATH
#include <fstream>
#include <iterator>

#include "film/linear_decode.h"
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

TEST_F(ViewerWorkbench, ADragMovesTheCameraAndHomeRestoresTheFilesImageByteForByte) {
    std::ofstream(scene_) << kShapes;
    const Image file_image = cli_image(scene_, kW, kH, dir_ + "/file.png");
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen1.png"), file_image, first.image));
    EXPECT_EQ(first.camera.rfind("file camera [ eye 0 1 6 focus 0 0 0 ", 0), 0u) << first.camera;

    drag(first, 60);  // 15 degrees of orbit
    Ready moved;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, moved, [&](const Ready& n) {
        return n.job > first.job && n.state == "finished" && n.camera.rfind("moved ", 0) == 0;
    })) << viewer->output();
    EXPECT_TRUE(moved.reused) << "moving the camera must not load the scene again";
    const Image after_drag = crop(grab_screen(x_.display(), dir_ + "/screen2.png"), moved.image);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < after_drag.rgb.size(); ++i) differ += after_drag.rgb[i] != file_image.rgb[i];
    EXPECT_GT(differ, after_drag.rgb.size() / 20) << "the image did not change (see " << dir_ << "/screen2.png)";

    keys("Home");
    Ready home;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, home, [&](const Ready& n) {
        return n.job > moved.job && n.state == "finished" && n.camera.rfind("file ", 0) == 0;
    })) << viewer->output();
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen3.png"), file_image, home.image))
        << "Home must give the file's image byte for byte (see " << dir_ << "/screen3.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// The block is edited in place: the new eye is written where the old one was, the comment and
// line break inside the block stay, and the dialog shows that block as it will be written.
TEST_F(ViewerWorkbench, SaveCameraIntoSceneKeepsEveryOtherByteAndTheImageOnScreen) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    const std::string head = "# my scene\n";
    const std::string old_block = "camera [ eye 0 1 6   # from the door\n  focus 0 0 0 angle 40 ]";
    const std::string tail = std::string("   # the camera\n") + (std::strchr(kShapes, '\n') + 1);
    std::ofstream(scene_) << head + old_block + tail;
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    drag(first, -80);
    Ready moved;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, moved, [&](const Ready& n) {
        return n.job > first.job && n.state == "finished" && n.camera.rfind("moved ", 0) == 0;
    })) << viewer->output();
    const Image on_screen = crop(grab_screen(x_.display(), dir_ + "/moved.png"), moved.image);
    // An orbit about the focus point moves the eye only: "moved camera [ eye X Y Z focus 0 0 0 ...".
    const std::size_t eye_at = moved.camera.find(" eye ") + 5, focus_at = moved.camera.find(" focus ");
    ASSERT_LT(eye_at, focus_at) << moved.camera;
    const std::string new_eye = moved.camera.substr(eye_at, focus_at - eye_at);
    ASSERT_NE(moved.camera.find(" focus 0 0 0 "), std::string::npos) << moved.camera;

    keys("ctrl+shift+s");
    const std::string dialog = wait_for_window(x_.display(), "^Save camera into scene$", 30s);
    ASSERT_FALSE(dialog.empty()) << "no confirmation was asked:\n" << viewer->output();
    grab_screen(x_.display(), dir_ + "/dialog.png");
    const std::string asked = screen_text(dir_ + "/dialog.png", window_geometry(x_.display(), dialog), Lines::Block);
    EXPECT_TRUE(reads(asked, "# from the door")) << "the dialog does not show the block to be written:\n" << asked;
    xdotool(x_.display(), "windowfocus --sync " + dialog + " key Return");
    Ready saved;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, saved, [&](const Ready& n) {
        return n.job > moved.job && n.state == "finished" && n.camera.rfind("file ", 0) == 0;
    })) << viewer->output();

    // The file: the same bytes, but for the eye's numbers.
    std::ifstream in(scene_);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    EXPECT_EQ(text, head + "camera [ eye " + new_eye + "   # from the door\n  focus 0 0 0 angle 40 ]" + tail);
    // Loaded again: the window shows the image it showed before saving, and so does the renderer.
    EXPECT_FALSE(saved.reused);
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/saved.png"), on_screen, saved.image))
        << "see " << dir_ << "/moved.png and saved.png";
    EXPECT_EQ(cli_image(scene_, kW, kH, dir_ + "/saved_cli.png").rgb, on_screen.rgb);
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// F5 with nothing changed renders nothing: the picture stays, no new job, and the status bar says why.
TEST_F(ViewerWorkbench, RenderAgainWithNothingChangedKeepsThePicture) {
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    keys("F5");
    Ready again;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, again, [](const Ready& n) {
        const auto m = n.labels.find("message");
        return m != n.labels.end() && m->second.find("up to date") != std::string::npos;
    }, 20s)) << viewer->output();
    EXPECT_EQ(again.job, first.job);
    EXPECT_EQ(again.state, "finished");
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/again.png"), red_, again.image));
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

TEST_F(ViewerWorkbench, ABrokenSceneKeepsTheLastImageDimmedUnderTheErrorUntilFixed) {
    auto viewer = start_viewer({"--watch"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_TRUE(shows(grab_screen(x_.display(), dir_ + "/red.png"), red_, first.image));

    rewrite_scene(scene_, "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n");
    Ready broken;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, broken,
                               [&](const Ready& n) { return n.job > first.job && n.state == "failed"; }, 30s))
        << viewer->output();
    EXPECT_TRUE(broken.dimmed);
    ASSERT_FALSE(broken.panel.empty());
    EXPECT_EQ(broken.panel[0].rfind("scene.sc:2:", 0), 0u) << broken.panel[0];
    const Image screen = grab_screen(x_.display(), dir_ + "/broken.png");
    // Below the banner (two lines of text at the top), the red image at 2/5 of its brightness.
    ASSERT_EQ(broken.image.w, kW);
    int wrong = 0;
    for (int y = kH - 40; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const glm::ivec3 want = glm::ivec3(red_.at(x, y)) * 2 / 5;
            wrong += glm::ivec3(screen.at(broken.image.x + x, broken.image.y + y)) != want;
        }
    EXPECT_EQ(wrong, 0) << "see " << dir_ << "/broken.png";
    EXPECT_EQ(glm::ivec3(screen.at(broken.area.x + 2, broken.area.y + 2)), glm::ivec3(70, 20, 20))
        << "no error banner at the top of the image area (see " << dir_ << "/broken.png)";

    rewrite_scene(scene_, sphere_scene("0.1 0.1 0.9"));
    Ready fixed;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, fixed,
                               [&](const Ready& n) { return n.job > broken.job && n.state == "finished"; }, 30s))
        << viewer->output();
    EXPECT_FALSE(fixed.dimmed);
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/blue.png"), blue_, fixed.image));
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

TEST_F(ViewerWorkbench, RecentFilesAndTheWindowSizeSurviveARestart) {
    // HOME is the test's folder (Child): the preferences start empty and stay there.
    {
        auto viewer = start_viewer({});
        Ready r;
        ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
            << viewer->output();
        EXPECT_EQ(r.window.w, 1000);  // the default, nothing remembered yet
        const std::string window = xdotool(x_.display(), "search --name whitted-view");
        xdotool(x_.display(), "windowsize " + window + " 720 520");
        ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.window.w == 720; }, 20s))
            << viewer->output();
        keys("ctrl+q");
        ASSERT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
    }
    EXPECT_TRUE(fs::exists(dir_ + "/.fltk/whitted/whitted-view.prefs"));
    fs::remove(ready_);
    const std::string first_scene = scene_;
    scene_ = dir_ + "/blue.sc";
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_EQ(r.window.w, 720);
    EXPECT_EQ(r.window.h, 520);
    EXPECT_EQ(r.recent, (std::vector<std::string>{scene_, first_scene}));
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// File > Open recent > (an entry) opens that scene (it used to take the entry's index for the
// window and crash).
TEST_F(ViewerWorkbench, OpenRecentOpensTheChosenScene) {
    const std::string red_scene = scene_;
    scene_ = dir_ + "/blue.sc";
    {
        auto viewer = start_viewer({});
        Ready r;
        ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
            << viewer->output();
        viewer->signal(SIGTERM);
        ASSERT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
    }
    fs::remove(ready_);
    scene_ = red_scene;
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_EQ(first.recent, (std::vector<std::string>{red_scene, dir_ + "/blue.sc"}));
    // The File menu, its second item (Open recent), that submenu's second entry: blue.sc.
    keys("--delay 250 alt+f Down Down Right Down Return");
    Ready opened;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, opened,
                               [&](const Ready& n) { return n.job > first.job && n.state == "finished"; }, 30s))
        << "no new render after choosing the recent scene:\n" << viewer->output();
    EXPECT_EQ(opened.recent.front(), dir_ + "/blue.sc");
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/opened.png"), blue_, opened.image))
        << "see " << dir_ << "/opened.png";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Zoom with '+' (2x, nearest neighbour: each image pixel a 2 x 2 block) and exposure with ']'
// (one stop: the radiance doubled, then clamped), about the centre of the area.
TEST_F(ViewerWorkbench, ZoomShowsPixelsAsBlocksAndExposureDoublesTheRadiance) {
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    keys("plus");
    Ready zoomed;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, zoomed, [](const Ready& n) { return n.image.w == 2 * kW; }, 20s))
        << viewer->output();
    ASSERT_EQ(zoomed.image.h, 2 * kH);
    const Image screen = grab_screen(x_.display(), dir_ + "/zoomed.png");
    int wrong = 0;
    for (int y = 0; y < 2 * kH; ++y)
        for (int x = 0; x < 2 * kW; ++x)
            wrong += screen.at(zoomed.image.x + x, zoomed.image.y + y) != red_.at(x / 2, y / 2);
    EXPECT_EQ(wrong, 0) << "see " << dir_ << "/zoomed.png";

    keys("1 bracketright");
    Ready exposed;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, exposed,
                               [](const Ready& n) { return n.image.w == kW && n.exposure == 1.0; }, 20s))
        << viewer->output();
    const Image bright = grab_screen(x_.display(), dir_ + "/exposed.png");
    // The exposure doubles the radiance, not the bytes: each pixel is the conversion of twice the
    // value whitted writes to a .pfm.
    const auto cli = run_process({test::cli_path(), scene_, "-o", dir_ + "/red.pfm", "--width", std::to_string(kW),
                                  "--height", std::to_string(kH), "-q"});
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    std::ifstream pfm(dir_ + "/red.pfm", std::ios::binary);
    const std::string pfm_bytes((std::istreambuf_iterator<char>(pfm)), std::istreambuf_iterator<char>());
    LinearImage radiance;
    ASSERT_EQ(decode_linear_image(pfm_bytes, ImageLimits{}, radiance), "");
    wrong = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const glm::vec3 v = radiance.rgb[std::size_t(y) * kW + std::size_t(x)] * 2.0f;
            const glm::ivec3 want(to_byte(v.x), to_byte(v.y), to_byte(v.z));
            wrong += glm::ivec3(bright.at(exposed.image.x + x, exposed.image.y + y)) != want;
        }
    EXPECT_EQ(wrong, 0) << "see " << dir_ << "/exposed.png";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// --watch also reloads when a texture file of the scene changes (not only the scene file).
TEST_F(ViewerWorkbench, WatchReloadsWhenATextureChanges) {
    Image tex(4, 4);
    std::fill(tex.rgb.begin(), tex.rgb.end(), std::uint8_t(200));
    ASSERT_EQ(write_image(tex, dir_ + "/tex.png"), "");
    std::ofstream(scene_, std::ios::trunc) << sphere_scene("1 1 1", "tex.png");
    auto viewer = start_viewer({"--watch"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    const auto before = fs::last_write_time(dir_ + "/tex.png");
    std::fill(tex.rgb.begin(), tex.rgb.end(), std::uint8_t(40));
    ASSERT_EQ(write_image(tex, dir_ + "/tex.png"), "");
    fs::last_write_time(dir_ + "/tex.png", before + 2s);
    Ready again;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, again,
                               [&](const Ready& n) { return n.job > first.job && n.state == "finished"; }, 30s))
        << "the changed texture was not loaded again:\n" << viewer->output();
    EXPECT_FALSE(again.reused);
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

TEST_F(ViewerWorkbench, F1OpensTheKeyboardShortcutsWindow) {
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    keys("F1");
    EXPECT_FALSE(wait_for_window(x_.display(), "^Keyboard shortcuts$", 20s).empty()) << viewer->output();
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// A double-click on an error in the messages panel opens the editor at the error's line;
// the editor here is a script that writes down how it was called.
TEST_F(ViewerWorkbench, DoubleClickingAnErrorOpensTheEditorAtItsLine) {
    std::ofstream(scene_, std::ios::trunc) << "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n";
    const std::string editor = dir_ + "/editor.sh", called = dir_ + "/editor-called";
    std::ofstream(editor) << "#!/bin/sh\necho \"$@\" > '" << called << ".tmp' && mv '" << called << ".tmp' '" << called
                          << "'\n";
    fs::permissions(editor, fs::perms::owner_all);
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", std::to_string(kW), "--height", std::to_string(kH), "--threads",
                  "2", "--ready-file", ready_},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x_.display()}, {"HOME", dir_}, {"VISUAL", ""}, {"EDITOR", editor},
                  {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready_, r, [](const Ready& n) { return n.state == "failed" && !n.panel.empty(); }))
        << viewer.output();
    ASSERT_EQ(r.panel[0].rfind("scene.sc:2:", 0), 0u) << r.panel[0];
    // The panel lies under the image area, across the window: its first line, double-clicked.
    xdotool(x_.display(), "mousemove --sync " + std::to_string(r.area.x + 40) + " " +
                              std::to_string(r.area.y + r.area.h + 10) + " click --repeat 2 --delay 80 1");
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (!fs::exists(called) && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(50ms);
    std::ifstream in(called);
    std::string args;
    std::getline(in, args);
    std::string want = "+2 ";  // (piece by piece: GCC 12's -Wrestrict misfires on the one-expression form)
    want += scene_;
    EXPECT_EQ(args, want) << viewer.output();
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

}  // namespace
}  // namespace whitted
#endif
