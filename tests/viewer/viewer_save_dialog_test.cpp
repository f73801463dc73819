// whitted-view's Save image as, on a real X server: the folder and name it suggests, typing into
// FLTK's chooser, the window going on while it is open, the image saved finished or said partial.
#ifdef WHITTED_VIEWER_PATH
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

// File > Save image as proposes the scene's folder and name; a name it cannot write is an error
// in the status bar and in the messages panel.
TEST_F(ViewerE2E, SaveImageAsStartsInTheScenesFolder) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    fs::create_directory(dir_ + "/scenes");
    const std::string scene = dir_ + "/scenes/room.sc", ready = dir_ + "/ready.txt";
    fs::copy_file(scene_, scene);
    // (HOME: the file chooser keeps a list of recent files there.)
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", "160", "--height", "120", "--threads", "2", "--ready-file",
                  ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready&) { return true; })) << viewer.output();
    ASSERT_EQ(r.state, "finished");
    const std::string window = xdotool(x.display(), "search --name whitted-view");

    // Opens the dialog with Ctrl+S and types into it.
    auto save_as = [&](const std::vector<std::string>& keys) {
        xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
        const std::string dialog = xdotool(x.display(), "search --sync --name 'Save image as'");
        xdotool(x.display(), "windowfocus --sync " + dialog);
        for (const std::string& k : keys) xdotool(x.display(), k);
    };
    save_as({"key Return"});
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (!fs::exists(dir_ + "/scenes/room.png") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(50ms);
    Image saved;
    ASSERT_EQ(read_image(dir_ + "/scenes/room.png", saved), "") << viewer.output();
    EXPECT_EQ(saved.width, 160);

    // The suggested name is selected without its folder: typing replaces it.
    save_as({"type x.gif", "key Return"});
    const std::string error =
        "error: cannot write '" + dir_ + "/scenes/x.gif': use .png, .bmp, .ppm, .jpg, .jpeg, .exr or .pfm";
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return !n.panel.empty(); }, 20s))
        << viewer.output();
    EXPECT_EQ(r.panel, std::vector<std::string>{error});

    // A name typed alone into the emptied field is in the folder shown, not the working directory
    // (FLTK 1.3.8 resolved it there and moved the cursor to the start, garbling the next keys).
    // (Shift+Home selects the whole field: Ctrl+A is the start of the line in FLTK.)
    save_as({"key End", "key shift+Home", "type y.png", "key Return"});
    const auto saved_y = [](const Ready& n) {
        return n.labels.count("message") && n.labels.at("message").find("y.png") != std::string::npos;
    };
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, saved_y, 20s))
        << viewer.output();
    EXPECT_EQ(drawn_text(r.labels["message"]), " saved " + dir_ + "/scenes/y.png");
    ASSERT_EQ(read_image(dir_ + "/scenes/y.png", saved), "") << viewer.output();
    EXPECT_EQ(saved.width, 160);

    // Saving over a file asks first; Escape keeps the file as it was.
    const auto written = fs::last_write_time(dir_ + "/scenes/room.png");
    save_as({"key Return"});
    const std::string ask = xdotool(x.display(), "search --sync --name '^Save$'");
    ASSERT_FALSE(ask.empty()) << viewer.output();
    xdotool(x.display(), "windowfocus --sync " + ask + " key Escape");
    const auto closed = std::chrono::steady_clock::now() + 10s;
    while (run_process({"/bin/sh", "-c", "DISPLAY=" + x.display() + " xdotool search --name '^Save'"}).exit_code == 0 &&
           std::chrono::steady_clock::now() < closed)
        std::this_thread::sleep_for(50ms);
    EXPECT_EQ(fs::last_write_time(dir_ + "/scenes/room.png"), written);
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

// A path typed from the root into the name field is taken as typed (FLTK's chooser moved to each
// folder as its '/' was typed and garbled the field; Enter then did nothing).
TEST_F(ViewerE2E, SaveImageAsTakesAnAbsolutePathTypedIntoTheName) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    fs::create_directory(dir_ + "/elsewhere");
    const std::string ready = dir_ + "/ready.txt", target = dir_ + "/elsewhere/out.png";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", "160", "--height", "120", "--threads", "2", "--ready-file",
                  ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer.output();
    const std::string window = xdotool(x.display(), "search --name whitted-view");
    xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
    const std::string dialog = xdotool(x.display(), "search --sync --name 'Save image as'");
    xdotool(x.display(), "windowfocus --sync " + dialog);
    xdotool(x.display(), "key End shift+Home");
    xdotool(x.display(), "type --delay 30 " + target);
    xdotool(x.display(), "key Return");
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) {
        return n.labels.count("message") && n.labels.at("message").find("saved") != std::string::npos;
    }, 20s)) << "nothing was saved:\n" << viewer.output();
    EXPECT_EQ(drawn_text(r.labels["message"]), " saved " + target);
    Image saved;
    ASSERT_EQ(read_image(target, saved), "") << viewer.output();
    EXPECT_EQ(saved.width, 160);
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

// The window goes on showing the render while the Save dialog is open: the
// ready file, written from the window's own timer when the render ends, appears with the dialog
// still open. (GTK's chooser ran an event loop of its own, in which no timer of ours fired.)
TEST_F(ViewerE2E, TheWindowKeepsUpdatingWhileTheSaveDialogIsOpen) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    const std::string ready = dir_ + "/ready.txt", scene = dir_ + "/showcase.sc";
    fs::copy_file(std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc", scene);
    // Long enough (16 samples a pixel of the showcase) for the dialog to open well before the end.
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", "320", "--height", "240", "--spp", "16", "--threads", "2",
                  "--ready-file", ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    const std::string window = xdotool(x.display(), "search --sync --name whitted-view");
    ASSERT_FALSE(window.empty()) << viewer.output();
    xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
    const std::string dialog = xdotool(x.display(), "search --sync --name 'Save image as'");
    ASSERT_FALSE(dialog.empty()) << viewer.output();
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "finished"; }, 120s))
        << "the render's end was not seen while the dialog was open:\n" << viewer.output();
    EXPECT_FALSE(xdotool(x.display(), "search --name 'Save image as'").empty());  // still open

    // Saved now, it is the finished image, as whitted renders it, and no word of it being partial.
    xdotool(x.display(), "windowfocus --sync " + dialog + " key Return");
    const std::string png = dir_ + "/showcase.png";
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) {
        return n.labels.count("message") && n.labels.at("message").find("saved") != std::string::npos;
    }, 20s))
        << viewer.output();
    EXPECT_EQ(drawn_text(r.labels["message"]), " saved " + png);
    Image saved, expected;
    ASSERT_EQ(read_image(png, saved), "") << viewer.output();
    auto cli = run_process({test::cli_path(), scene, "-o", dir_ + "/cli.png", "--width", "320", "--height", "240",
                            "--spp", "16", "-q"});
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    ASSERT_EQ(read_image(dir_ + "/cli.png", expected), "");
    EXPECT_TRUE(saved.rgb == expected.rgb) << "see " << png << " and " << dir_ << "/cli.png";

    // Quitting with the dialog open saves nothing (its name field still holds a name).
    xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
    const std::string again = xdotool(x.display(), "search --sync --name 'Save image as'");
    xdotool(x.display(), "windowfocus --sync " + again + " type later.png");
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
    EXPECT_FALSE(fs::exists(dir_ + "/later.png"));
}

// Saved while a render runs, the image is the one on screen then, and the message says it is
// partial.
TEST_F(ViewerE2E, SavingWhileRenderingSaysTheImageIsPartial) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    const std::string ready = dir_ + "/ready.txt", scene = dir_ + "/showcase.sc", png = dir_ + "/showcase.png";
    fs::copy_file(std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc", scene);
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", "160", "--height", "120", "--threads", "2", "--ready-file",
                  ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer.output();
    // A render of minutes: 4096 samples a pixel (Render > Samples per pixel, then F5), stopped by
    // the quit at the end.
    const std::string window = xdotool(x.display(), "search --name whitted-view");
    xdotool(x.display(), "windowfocus --sync " + window + " key alt+r p");
    xdotool(x.display(), "search --sync --name '^Samples per pixel$'");
    xdotool(x.display(), "key End shift+Home");
    xdotool(x.display(), "type 4096");
    xdotool(x.display(), "key Return");
    xdotool(x.display(), "windowfocus --sync " + window + " key F5");
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) {
        return n.labels.count("progress") && n.labels.at("progress").find("of 4096 samples") != std::string::npos;
    }, 30s)) << viewer.output();

    xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
    const std::string dialog = xdotool(x.display(), "search --sync --name 'Save image as'");
    xdotool(x.display(), "windowfocus --sync " + dialog + " key Return");
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) {
        return n.labels.count("message") && n.labels.at("message").find("saved") != std::string::npos;
    }, 20s))
        << viewer.output();
    EXPECT_EQ(drawn_text(r.labels["message"]), " saved " + png + " while still rendering: the image is partial");
    Image saved;
    ASSERT_EQ(read_image(png, saved), "") << viewer.output();
    EXPECT_EQ(saved.width, 160);
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

}  // namespace
}  // namespace whitted
#endif
