// whitted --frames A..B --fps F: numbered images, frame n the scene at time n / F (docs/animation.md),
// frames already written skipped.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::run_process;
using test::write_file;

std::string bytes_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::string scene_with(const char* transforms) {
    return std::string("camera [ eye 0 0 6 focus 0 0 0 ]\nlight [ position 2 2 5 color 1 1 1 ]\n"
                       "mastersubgraph root [ trans [ ") +
           transforms + " object cube [ diffuse 1 0 0 ] ] ]\n";
}

// The pixels alone (the files' text names the time they were made at).
std::vector<std::uint8_t> pixels_of(const std::string& path) {
    Image image;
    EXPECT_EQ(read_image(path, image), "") << path;
    return image.rgb;
}

std::vector<std::string> command(const std::string& scene, const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> argv = {test::cli_path(), scene, "-o", out, "--width", "32", "--height", "24", "-q"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    return argv;
}

TEST(CliFrames, EachFrameIsTheSceneAtItsTime) {
    const std::string dir = test::make_temp_dir();
    // Moving by (1, 0.5, 0) per unit of time, turning 80 degrees per unit: frames 0..2 at 4 fps
    // are the times 0, 0.25 and 0.5.
    const std::string scene = write_file(dir, "m.sc", scene_with("velocity 1 0.5 0 angularrate 0 1 1 80"));
    const auto r = run_process(command(scene, dir + "/f.png", {"--frames", "0..2", "--fps", "4"}));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* n : {"0000", "0001", "0002"})
        EXPECT_TRUE(fs::exists(dir + "/f." + std::string(n) + ".png")) << n;
    EXPECT_FALSE(fs::exists(dir + "/f.png"));
    EXPECT_FALSE(fs::exists(dir + "/f.0003.png"));
    const char* times[] = {"0", "0.25", "0.5"};
    for (int n = 0; n < 3; ++n) {
        SCOPED_TRACE(n);
        const std::string single = dir + "/t" + std::to_string(n) + ".png";
        ASSERT_EQ(run_process(command(scene, single, {"--time", times[n]})).exit_code, 0);
        EXPECT_EQ(bytes_of(dir + "/f.000" + std::to_string(n) + ".png"), bytes_of(single));
    }
    // Frame 2 (t = 0.5) is the file written with the motion's closed form (§9.4), and not frame 0.
    const std::string moved = write_file(dir, "moved.sc", scene_with("translate 0.5 0.25 0 rotate 0 1 1 40"));
    ASSERT_EQ(run_process(command(moved, dir + "/moved.png", {})).exit_code, 0);
    EXPECT_EQ(pixels_of(dir + "/f.0002.png"), pixels_of(dir + "/moved.png"));
    EXPECT_NE(pixels_of(dir + "/f.0002.png"), pixels_of(dir + "/f.0000.png"));
}

// With --frames, --shutter T0,T1 is relative to each frame's time: frame n is the image of
// --time n/fps with the same shutter, and a moving object's frames are blurred.
TEST(CliFrames, ShutterIsRelativeToEachFramesTime) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "m.sc", scene_with("velocity 2 0 0"));
    const std::vector<std::string> blur = {"--shutter", "-0.1,0.1", "--spp", "16"};
    auto with = [&](std::vector<std::string> extra) {
        extra.insert(extra.end(), blur.begin(), blur.end());
        return extra;
    };
    ASSERT_EQ(run_process(command(scene, dir + "/f.png", with({"--frames", "1..2", "--fps", "4"}))).exit_code, 0);
    for (int n : {1, 2}) {
        SCOPED_TRACE(n);
        const std::string single = dir + "/t" + std::to_string(n) + ".png";
        ASSERT_EQ(run_process(command(scene, single, with({"--time", n == 1 ? "0.25" : "0.5"}))).exit_code, 0);
        EXPECT_EQ(pixels_of(dir + "/f.000" + std::to_string(n) + ".png"), pixels_of(single));
    }
    // Not the frame at its instant: the shutter blurs it.
    ASSERT_EQ(run_process(command(scene, dir + "/still.png", {"--time", "0.5", "--spp", "16"})).exit_code, 0);
    EXPECT_NE(pixels_of(dir + "/f.0002.png"), pixels_of(dir + "/still.png"));
}

TEST(CliFrames, FramesThatExistAreSkipped) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "m.sc", scene_with("velocity 1 0 0"));
    // Frame 11 is there already (an interrupted run's): left as it is, and said so.
    write_file(dir, "seq.0011.png", "not touched");
    const auto r = run_process(command(scene, dir + "/seq.png", {"--frames", "10..12"}));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(bytes_of(dir + "/seq.0011.png"), "not touched");
    EXPECT_NE(r.output.find("frame 11: " + dir + "/seq.0011.png exists, skipped"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(dir + "/seq.0010.png"));
    EXPECT_TRUE(fs::exists(dir + "/seq.0012.png"));
    // Run again: nothing left to render, nothing rewritten.
    const auto before = fs::last_write_time(dir + "/seq.0010.png");
    const auto again = run_process(command(scene, dir + "/seq.png", {"--frames", "10..12"}));
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_EQ(fs::last_write_time(dir + "/seq.0010.png"), before);
    EXPECT_NE(again.output.find("frame 12: "), std::string::npos) << again.output;
}

// A sequence stopped by --timeout keeps the frames it finished and no part of the one it was in;
// the same command run again renders only what is missing.
TEST(CliFrames, AnInterruptedSequenceGoesOnWhereItStopped) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "m.sc", scene_with("velocity 0.01 0 0"));
    const auto r = run_process(command(scene, dir + "/s.png", {"--frames", "0..999999", "--timeout", "0.5"}));
    ASSERT_EQ(r.exit_code, 4) << r.output;  // a million frames do not fit in half a second
    EXPECT_NE(r.output.find("not written (run the same command again to go on)"), std::string::npos) << r.output;
    auto frame = [&](int n) {
        char name[32];
        std::snprintf(name, sizeof name, "/s.%04d.png", n);
        return dir + name;
    };
    int written = 0;
    while (fs::exists(frame(written))) ++written;
    // Only finished frames, numbered from the first, each a whole image; no other frame file.
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.path().extension() == ".png";
    EXPECT_EQ(files, std::size_t(written));
    for (int n = 0; n < written; ++n) {
        Image image;
        EXPECT_EQ(read_image(frame(n), image), "") << frame(n);
    }
    const std::string last = std::to_string(written + 1);
    const auto again = run_process(command(scene, dir + "/s.png", {"--frames", "0.." + last}));
    ASSERT_EQ(again.exit_code, 0) << again.output;
    std::size_t skipped = 0;
    for (std::size_t at = 0; (at = again.output.find("exists, skipped", at)) != std::string::npos; ++at) ++skipped;
    EXPECT_EQ(skipped, std::size_t(written));
    EXPECT_TRUE(fs::exists(frame(written)));
    EXPECT_TRUE(fs::exists(frame(written + 1)));
}

TEST(CliFrames, NumbersBeyondFourDigitsAndLinearOutput) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "s.sc", scene_with(""));
    const auto r = run_process(command(scene, dir + "/big.exr", {"--frames", "12345"}));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(fs::exists(dir + "/big.12345.exr"));
}

TEST(CliFrames, WhatDoesNotGoWithFramesIsRefused) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "s.sc", scene_with("velocity 1 0 0"));
    const std::string out = dir + "/x.png";
    const struct {
        std::vector<std::string> args;
        const char* message;
    } cases[] = {
        {{"--frames", "3..1"}, "is not a range of frame numbers"},
        {{"--frames", "1..x"}, "is not a range of frame numbers"},
        {{"--frames", "-1..2"}, "is not a range of frame numbers"},
        {{"--fps", "30"}, "--fps is the frame rate of --frames"},
        {{"--frames", "0..1", "--time", "2"}, "each frame's time is its number / --fps"},
        {{"--frames", "0..1", "--checkpoint", dir + "/c.ckpt"}, "--frames keeps no checkpoint"},
        {{"--frames", "0..1", "--inspect", "1,1"}, "--inspect looks at one image"},
        {{"--frames", "0..1", "--fps", "0"}, "--fps"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.args[0] + " " + c.args[1]);
        const auto r = run_process(command(scene, out, c.args));
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
    }
    EXPECT_FALSE(fs::exists(dir + "/x.0000.png"));  // a refusal renders nothing
}

}  // namespace
}  // namespace whitted
