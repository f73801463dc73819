// whitted-view without a display: a clear error, and what needs no display (help, usage errors).
#ifdef WHITTED_VIEWER_PATH
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

TEST(ViewerNoDisplay, ExitsWithAClearErrorWhenDisplayIsUnset) {
    auto r = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH, "--width", "10", "--height", "10"});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("whitted-view: error: no display"), std::string::npos) << r.output;
}

TEST(ViewerNoDisplay, ExitsWithAClearErrorWhenDisplayIsWrong) {
    auto r = run_process({"/usr/bin/env", "DISPLAY=:4321", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("whitted-view: error: cannot open display ':4321'"), std::string::npos) << r.output;
}

TEST(ViewerNoDisplay, HelpAndBadUsageNeedNoDisplay) {
    auto help = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH, "--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--screenshot"), std::string::npos);
    EXPECT_EQ(run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH, "--mode", "fancy"}).exit_code, 1);
}

// --screenshot / --exit-when-done with no scene waited forever for a render
// that never came; now a usage error at once (before the display is needed).
TEST(ViewerNoDisplay, AutomatedRunsNeedAScene) {
    for (const char* flag : {"--exit-when-done", "--screenshot=x.png"}) {
        auto r = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(),
                              WHITTED_VIEWER_PATH, flag},
                             std::vector<test::TimedSignal>{{20000, SIGKILL}});
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find("--screenshot and --exit-when-done need a scene file"), std::string::npos) << r.output;
    }
    // Finding 11: the scene after a --texture-path is the scene, not a second folder (it got as far
    // as looking for a display).
    auto r = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(),
                          WHITTED_VIEWER_PATH, "--exit-when-done", "--texture-path", "/tmp", "scene.sc"});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("whitted-view: error: no display"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace whitted
#endif
