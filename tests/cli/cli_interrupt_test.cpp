// The first Ctrl-C, SIGTERM or --timeout stops every phase within a moment:
// the renderer looks at the flag between packets of samples, and a camera sample's rays are bounded
// (kMaxSecondaryRays), so neither a deep ray tree nor a pixel of a million samples holds it up.
// Process-level: the renders below run for minutes if the signal is not seen; each must end within
// seconds of it.
#include <signal.h>

#include <chrono>
#include <filesystem>

#include <gtest/gtest.h>

#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;

// The eye inside two nested spheres that both reflect and transmit 90% (ior 1: the transmitted
// ray goes straight on): every ray inside the outer sphere hits a sphere and splits in two, down
// to the depth limit. At depth 38 a camera ray was 2^39 rays (132 s for the scene; the renderer
// looked at the flag only between rows of a tile).
const char* kEndlessScene = R"(camera [ eye 0 0 0 focus 0 0 -1 ]
mastersubgraph root [
  trans [ scale 4 4 4 object sphere [ diffuse 0 0 0 reflect .9 .9 .9 transparent .9 .9 .9 ior 1 ] ]
  trans [ scale 8 8 8 object sphere [ diffuse 0 0 0 reflect .9 .9 .9 transparent .9 .9 .9 ior 1 ] ]
]
)";

// Nothing in the folder but the scene and the log.
void expect_nothing_written(const std::string& dir, const std::string& scene_name) {
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        EXPECT_TRUE(name == scene_name || name == "log.txt") << "left behind: " << name;
    }
}

TEST(CliInterrupt, TheFirstCtrlCStopsADeepRayTree) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "endless.sc", kEndlessScene);
    test::BackgroundProcess p({test::cli_path(), scene, "-o", dir + "/endless.png", "--width", "64", "--height", "64",
                               "--max-depth", "38", "--threads", "2", "-q"},
                              dir + "/log.txt");
    ASSERT_TRUE(p.wait_until_it_catches(SIGINT, 30s)) << p.output();
    ASSERT_TRUE(p.wait_until_a_second_thread_ran(50ms, 60s)) << "the render did not start\n" << p.output();
    ASSERT_TRUE(p.signal_and_wait_delivered(SIGINT, 10s)) << p.output();
    const int code = p.wait_exit(10s);
    EXPECT_EQ(code, 130) << (code == -1 ? "still running 10 s after the first Ctrl-C\n" : "") << p.output();
}

// One pixel of 16.7 million samples ran 95 s under --timeout 3; and a render stopped before any
// tile was done wrote an image of nothing (a 715-megapixel one, for minutes). Now it stops at once
// and writes nothing, saying so.
TEST(CliInterrupt, APixelOfMillionsOfSamplesStopsAndNothingRenderedIsNotWritten) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "s.sc", kEndlessScene);
    // Two tiles of 32 pixels (a thread each), each pixel 256 × 65536 samples, each sample a tree of
    // 2^38 rays: not one tile of the first pass (256 samples a pixel) ends.
    test::BackgroundProcess p({test::cli_path(), scene, "-o", dir + "/o.png", "--width", "64", "--height", "1",
                               "--aa", "16", "--spp", "65536", "--max-depth", "38", "--threads", "2", "-q"},
                              dir + "/log.txt");
    ASSERT_TRUE(p.wait_until_it_catches(SIGTERM, 30s)) << p.output();
    ASSERT_TRUE(p.wait_until_a_second_thread_ran(50ms, 60s)) << "the render did not start\n" << p.output();
    ASSERT_TRUE(p.signal_and_wait_delivered(SIGTERM, 10s)) << p.output();
    const int code = p.wait_exit(10s);
    EXPECT_EQ(code, 130) << (code == -1 ? "still running 10 s after SIGTERM\n" : "") << p.output();
    EXPECT_NE(p.output().find("whitted: interrupted: no tile was rendered: nothing written"), std::string::npos)
        << p.output();
    expect_nothing_written(dir, "s.sc");
}

}  // namespace
}  // namespace whitted
