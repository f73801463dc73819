// whitted-view's render settings, on a real X server: they come from the one table of settings
// (session/render_settings.h), so choosing a mode in the window gives that mode's defaults as
// `whitted --mode` does, and only what the user chose in the window is remembered.
#ifdef WHITTED_VIEWER_PATH
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

std::string text_of(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// Mode path chosen in the tool bar: 64 samples per pixel and 64 bounces (the user set neither),
// rendered in refining passes; whitted's `--mode path` has the same defaults.
TEST_F(ViewerWorkbench, ChoosingPathInTheWindowGivesThePathTracersDefaults) {
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_EQ(r.settings["mode"], "whitted");
    ASSERT_EQ(r.settings["spp"], "1");
    ASSERT_EQ(r.settings["depth"], "5");
    Box mode;
    for (const auto& [id, box] : r.tools)
        if (id == "mode") mode = box;
    // The choice's pop-up opens on the current item (whitted, the first); path is the last of five.
    xdotool(x_.display(), "mousemove --sync " + std::to_string(mode.right() - 10) + " " +
                              std::to_string(mode.y + mode.h / 2) + " click 1");
    std::this_thread::sleep_for(500ms);
    keys("Down Down Down Down Return");
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) {
        return n.settings.count("mode") && n.settings.at("mode") == "path" && n.state == "finished";
    }, 60s)) << "mode " << r.settings["mode"] << ":\n" << viewer->output();
    EXPECT_EQ(r.settings["spp"], "64");
    EXPECT_EQ(r.settings["depth"], "64");
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// The remembered settings are the user's choices in the window: a run with one-off options on the
// command line (here --width, --height, --threads and --max-depth) leaves them as they were.
TEST_F(ViewerWorkbench, AOneOffCommandLineOptionIsNotRemembered) {
    const std::string prefs = dir_ + "/.fltk/whitted/whitted-view.prefs";
    fs::create_directories(dir_ + "/.fltk/whitted");
    const std::string before =
        "; FLTK preferences file format 1.0\n; vendor: whitted\n; application: whitted-view\n\n[.]\n\n"
        "[./settings]\n\nwidth:321\nheight:241\ndepth:7\naa:2\nspp:4\nmode:0\nfit:0\n";
    std::ofstream(prefs) << before;
    auto viewer = start_viewer({"--max-depth", "3"});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_EQ(r.settings["depth"], "3") << "the command line's settings are the ones used";
    keys("ctrl+q");
    ASSERT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
    const std::string after = text_of(prefs);
    for (const char* kept : {"width:321", "height:241", "depth:7", "aa:2", "spp:4"})
        EXPECT_NE(after.find(kept), std::string::npos) << kept << " was not kept:\n" << after;
    EXPECT_EQ(after.find("depth:3"), std::string::npos) << after;
}

}  // namespace
}  // namespace whitted
#endif
