// whitted-view's rough edges a first-time user met, on a real X server: each test failed before
// its fix (Shift+hover, keys typed into the tool bar, a first load that fails, windows and texts
// cut short).
#ifdef WHITTED_VIEWER_PATH
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

// Holding Shift while the mouse moves over the image inspects the pixels under it (the inspector
// window appears). It used to recurse (the new window's events inspected again) until the stack ran out.
TEST_F(ViewerWorkbench, ShiftHoverOverTheImageInspectsWithoutCrashing) {
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    const int cx = r.image.x + r.image.w / 2, cy = r.image.y + r.image.h / 2;
    auto at = [&](int dx, int dy) { return std::to_string(cx + dx) + " " + std::to_string(cy + dy); };
    xdotool(x_.display(), "mousemove " + at(0, 0) + " keydown shift mousemove " + at(3, 0) + " sleep 0.2 mousemove " +
                              at(6, 2) + " sleep 0.2 mousemove " + at(9, 4) + " sleep 0.5 keyup shift");
    EXPECT_FALSE(wait_for_window(x_.display(), "^Pixel inspector$", 20s).empty()) << viewer->output();
    std::this_thread::sleep_for(500ms);
    ASSERT_EQ(viewer->wait_exit(0ms), -1) << "the viewer died:\n" << viewer->output();
    EXPECT_EQ(visible_windows(x_.display(), "^Pixel inspector$").size(), 1u);
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// After a tool-bar field was clicked, the view's keys still reach the view: a key that is no
// part of a number (+) zooms, and a click on the image takes the keys back (1 is then 1:1, not
// a digit of the anti-aliasing).
TEST_F(ViewerWorkbench, ViewKeysAfterAToolBarFieldGoToTheView) {
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_EQ(r.settings["aa"], "1");
    Box aa;
    for (const auto& [id, box] : r.tools)
        if (id == "aa") aa = box;
    // The field's text, left of the spinner's arrows.
    const std::string field = std::to_string(aa.right() - 22) + " " + std::to_string(aa.y + aa.h / 2);
    const std::string image = std::to_string(r.image.x + r.image.w / 2) + " " + std::to_string(r.image.y + r.image.h / 2);

    xdotool(x_.display(), "mousemove --sync " + field + " click 1");
    keys("End shift+Home 2 plus");
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) {
        return n.image.w == 2 * kW && n.settings.count("aa") && n.settings.at("aa") == "2" && n.state == "finished";
    }, 20s)) << "AA " << r.settings["aa"] << ", image " << r.image.w << " wide:\n" << viewer->output();

    xdotool(x_.display(), "mousemove --sync " + field + " click 1");
    xdotool(x_.display(), "mousemove --sync " + image + " click 1");
    keys("1");
    EXPECT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.image.w == kW; }, 20s))
        << "1 did not show the image 1:1 (AA " << r.settings["aa"] << "):\n" << viewer->output();
    std::this_thread::sleep_for(1s);  // a setting typed would render again after 0.4 s
    r = read_ready(ready_);
    EXPECT_EQ(r.settings["aa"], "2");
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// A first load that fails has no image to keep: the banner does not promise one. A file that does
// not exist is not added to File > Open recent.
TEST_F(ViewerWorkbench, AFirstFailedLoadKeepsNoImageAndAMissingFileIsNotRemembered) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    scene_ = dir_ + "/nowhere.sc";
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "failed"; }))
        << viewer->output();
    ASSERT_FALSE(r.banner.empty());
    EXPECT_EQ(r.banner[0], "The scene could not be loaded:");
    EXPECT_FALSE(r.dimmed);
    EXPECT_TRUE(r.recent.empty()) << r.recent.front();
    const std::string png = dir_ + "/screen.png";
    grab_screen(x_.display(), png);
    const std::string title = screen_text(png, Box{r.area.x, r.area.y, r.area.w, 26}, Lines::One);
    EXPECT_TRUE(reads(title, "The scene could not be loaded:")) << title << " (see " << png << ")";
    EXPECT_FALSE(reads(title, "last good image")) << title << " (see " << png << ")";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Help > Keyboard shortcuts: every key and action whole, the window on the screen.
TEST_F(ViewerWorkbench, TheShortcutsWindowShowsEveryKeyAndActionWhole) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    keys("F1");
    const std::string id = wait_for_window(x_.display(), "^Keyboard shortcuts$", 20s);
    ASSERT_FALSE(id.empty()) << viewer->output();
    std::this_thread::sleep_for(300ms);
    const Box w = window_geometry(x_.display(), id);
    EXPECT_GE(w.x, 0);
    EXPECT_GE(w.y, 0);
    EXPECT_LE(w.right(), 1280);
    EXPECT_LE(w.y + w.h, 1024);
    const std::string png = dir_ + "/shortcuts.png";
    grab_screen(x_.display(), png);
    const std::string text = screen_text(png, w, Lines::Block);
    for (const char* whole : {"Middle drag, Shift+Left drag", "Double-click a message", "Left click, Shift+hover",
                              "Move the picture in its area (does not change the camera)",
                              "Dolly: move the camera towards / away from the focus point",
                              "Open a scene (or drop a scene file on the window)"})
        EXPECT_TRUE(reads(text, whole)) << whole << " is not shown whole:\n" << text << "(see " << png << ")";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// The inspector's button names the object's line however long the scene's name: its label stays on
// the button (its start cut to an ellipsis if the window is too narrow), clear of the hint beside it.
TEST_F(ViewerWorkbench, TheInspectorsOpenButtonHoldsItsLabel) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    scene_ = dir_ + "/my-first-scene-with-a-long-name.sc";
    std::ofstream(scene_) << sphere_scene("0.9 0.1 0.1");
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    xdotool(x_.display(), "mousemove --sync " + std::to_string(r.image.x + r.image.w / 2) + " " +
                              std::to_string(r.image.y + r.image.h / 2) + " click 1");
    const std::string id = wait_for_window(x_.display(), "^Pixel inspector$", 20s);
    ASSERT_FALSE(id.empty()) << viewer->output();
    std::this_thread::sleep_for(500ms);
    const Box w = window_geometry(x_.display(), id);
    const std::string png = dir_ + "/inspector.png";
    grab_screen(x_.display(), png);
    const std::string row = screen_text(png, Box{w.x, w.y + w.h - 40, w.w, 40}, Lines::One);
    // Whole, or (a window too narrow for it) its start given up to an ellipsis: never over the hint.
    EXPECT_TRUE(reads(row, "Open ")) << row << " (see " << png << ")";
    EXPECT_TRUE(reads(row, "long-name.sc:4:")) << row << " (see " << png << ")";
    EXPECT_TRUE(reads(row, "in the editor")) << row << " (see " << png << ")";
    EXPECT_TRUE(reads(row, "Click a pixel")) << row << " (see " << png << ")";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// A status bar text longer than its field ends in an ellipsis on the screen (its tooltip has it all).
TEST_F(ViewerOnScreen, AStatusTextCutShortEndsInAnEllipsis) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    std::ofstream(scene_) << "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n";
    auto viewer = start_viewer({"--window-size", "520x400"});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "failed"; }))
        << viewer->output();
    const Box& message = r.fields["message"];
    ASSERT_LT(message.w, r.needs["message"]) << "the message fits: nothing to cut";
    const std::string png = dir_ + "/screen.png";
    grab_screen(x_.display(), png);
    std::string text = screen_text(png, message, Lines::One);
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    const bool ellipsis = text.size() >= 3 && (text.compare(text.size() - 3, 3, "\u2026") == 0 ||
                                               text.compare(text.size() - 3, 3, "...") == 0);
    EXPECT_TRUE(ellipsis) << "'" << text << "' (see " << png << ")";
    EXPECT_TRUE(reads(text, "scene.sc:2:")) << text;
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// A scene with a disc light rendered with one sample per pixel shows hard shadows (the light's
// centre): the status bar says so, and says nothing once the samples show them.
TEST_F(ViewerOnScreen, OneSamplePerPixelOfSoftShadowsIsToldInTheStatusBar) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    std::ofstream(scene_) << "camera [ eye 0 0 5 focus 0 0 0 angle 40 ]\n"
                             "light [ position 3 4 5 radius 0.5 ]\n"
                             "mastersubgraph root [ trans [ object sphere [ diffuse 0.9 0.1 0.1 ] ] ]\n";
    {
        auto viewer = start_viewer({});
        Ready r;
        ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
            << viewer->output();
        EXPECT_EQ(drawn_text(r.labels["message"]).rfind(" this scene has soft shadows: raise SPP to see them", 0), 0u)
            << r.labels["message"];
        const std::string png = dir_ + "/screen.png";
        grab_screen(x_.display(), png);
        const std::string text = screen_text(png, r.fields["message"], Lines::One);
        EXPECT_TRUE(reads(text, "this scene has soft shadows: raise SPP")) << text << " (see " << png << ")";
        viewer->signal(SIGTERM);
        EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
    }
    fs::remove(ready_);
    auto viewer = start_viewer({"--spp", "4"});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_EQ(r.labels["message"].find("raise SPP"), std::string::npos) << r.labels["message"];
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

}  // namespace
}  // namespace whitted
#endif
