// [inspector] whitted-view's pixel inspector on a real X server: a click on the image, the report,
// the editor opened at the object's line.
#ifdef WHITTED_VIEWER_PATH
#include "viewer/viewer_e2e_fixtures.h"
#include "inspect/inspect_scene.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

// [inspector] A click on a pixel of the image opens the inspector with that pixel's report; its
// button opens $EDITOR at the line of the object's `object` keyword (the editor here a script that
// writes down how it was called).
TEST_F(ViewerE2E, ClickingAPixelInspectsItAndOpensTheEditorAtTheObjectsLine) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    const std::string scene = dir_ + "/pillars.sc", ready = dir_ + "/ready.txt", called = dir_ + "/editor-args.txt";
    std::ofstream(scene) << test::kInspectScene;
    const std::string editor = dir_ + "/editor.sh";
    std::ofstream(editor) << "#!/bin/sh\necho \"$@\" > '" << called << ".tmp' && mv '" << called << ".tmp' '" << called
                          << "'\n";
    fs::permissions(editor, fs::perms::owner_all);
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", std::to_string(test::kInspectWidth), "--height",
                  std::to_string(test::kInspectHeight), "--threads", "2", "--ready-file", ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"VISUAL", ""}, {"EDITOR", editor},
                  {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer.output();
    ASSERT_EQ(r.image.w, test::kInspectWidth);

    // The right pillar, projected; clicked at its pixel's centre (root-window coordinates).
    const glm::ivec2 px = test::project(test::kRightPillarFront);
    xdotool(x.display(), "mousemove --sync " + std::to_string(r.image.x + px.x) + " " + std::to_string(r.image.y + px.y) +
                             " click 1");
    const std::string inspector = xdotool(x.display(), "search --sync --name 'Pixel inspector'");
    ASSERT_FALSE(inspector.empty());
    const Box w = window_geometry(x.display(), inspector);
    // Its button "Open FILE:LINE:COL in the editor", left of the bottom row (inspector_window.cpp).
    xdotool(x.display(), "mousemove --window " + inspector + " 200 " + std::to_string(w.h - 8 - 14) + " click 1");
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (!fs::exists(called) && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(50ms);
    std::ifstream in(called);
    std::string args;
    std::getline(in, args);
    // Appended piece by piece: GCC 12's -Wrestrict misfires on the one-expression form.
    std::string want = "+";
    want += std::to_string(test::find_in_scene("object cylinder").line);
    want += ' ';
    want += scene;
    EXPECT_EQ(args, want) << viewer.output();
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

}  // namespace
}  // namespace whitted
#endif
