// Ctrl-C twice on a render that cannot finish first: the second interrupt alone must end it.
// (cli_test.cpp interrupts renders that do end soon after the first Ctrl-C, which would pass
// even if the second were ignored.)
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
// to the depth limit. At depth 28 a camera ray costs 2.7 million rays (measured: seconds of
// work), a tile row of 32 of them a minute or more.
// The renderer checks for a stop only between rows, so after the first Ctrl-C it keeps working
// far longer than any wait below (on each of its two threads).
const char* kEndlessScene = R"(camera [ eye 0 0 0 focus 0 0 -1 ]
mastersubgraph root [
  trans [ scale 4 4 4 object sphere [ diffuse 0 0 0 reflect .9 .9 .9 transparent .9 .9 .9 ior 1 ] ]
  trans [ scale 8 8 8 object sphere [ diffuse 0 0 0 reflect .9 .9 .9 transparent .9 .9 .9 ior 1 ] ]
]
)";

TEST(CliInterrupt, TheSecondCtrlCEndsARenderTheFirstCouldNotStopInTime) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = test::write_file(dir, "endless.sc", kEndlessScene);
    const std::string out = dir + "/endless.png";
    test::BackgroundProcess p({test::cli_path(), scene, "-o", out, "--width", "64", "--height", "64", "--max-depth",
                               "28", "--threads", "2", "-q"},
                              dir + "/log.txt");
    // The first Ctrl-C once the render is under way: the handler is there (before, SIGINT would
    // kill the process outright) and the render thread besides the main one has worked for 50 ms,
    // so it is inside a tile row, which it finishes before it stops (a Ctrl-C during the load
    // would stop the load, which ends at once, as would one before the workers' first row).
    ASSERT_TRUE(p.wait_until_it_catches(SIGINT, 30s)) << p.output();
    ASSERT_TRUE(p.wait_until_a_second_thread_ran(50ms, 60s)) << "the render did not start\n" << p.output();
    ASSERT_TRUE(p.signal_and_wait_delivered(SIGINT, 10s)) << p.output();
    // It asked the render to stop, which cannot happen before the current row is done.
    EXPECT_EQ(p.wait_exit(300ms), -1) << "the render ended after one Ctrl-C: the test needs a slower scene\n"
                                      << p.output();
    ASSERT_TRUE(p.signal_and_wait_delivered(SIGINT, 10s)) << p.output();
    const int code = p.wait_exit(10s);
    EXPECT_EQ(code, 130) << (code == -1 ? "still running 10 s after the second Ctrl-C\n" : "") << p.output();
    EXPECT_NE(p.output().find("whitted: interrupted twice, exiting now\n"), std::string::npos) << p.output();
    // Nothing written: neither the image nor a temporary file.
    for (const auto& e : fs::directory_iterator(dir)) {
        const std::string name = e.path().filename().string();
        EXPECT_TRUE(name == "endless.sc" || name == "log.txt") << "left behind: " << name;
    }
}

}  // namespace
}  // namespace whitted
