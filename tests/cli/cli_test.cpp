// The `whitted` command as a user runs it: exit codes, output files, messages, Ctrl-C.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "film/linear_decode.h"
#include "film/view_transform.h"
#include "cli/cli_scenes.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::run_process;
using test::write_file;
using test::kSimpleScene;
using test::heavy_scene;


TEST(Cli, RendersNextToTheSceneByDefault) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "ball.sc", kSimpleScene);
    auto r = run_process({test::cli_path(), scene, "--width", "40", "--height", "30", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Image img;
    ASSERT_EQ(read_image(dir + "/ball.png", img), "");
    EXPECT_EQ(img.width, 40);
    EXPECT_EQ(img.height, 30);
    glm::u8vec3 centre = img.at(20, 15);
    EXPECT_GT(centre.x, 100);  // the red ball, lit
    EXPECT_EQ(centre.y, 0);
    EXPECT_EQ(img.at(0, 0), glm::u8vec3(0));  // black background
}

TEST(Cli, OutputFormatFollowsTheExtension) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "s.sc", kSimpleScene);
    for (std::string ext : {".bmp", ".ppm", ".jpg", ".png"}) {
        std::string out = dir + "/out" + ext;
        auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "16", "--height", "12", "-q"});
        ASSERT_EQ(r.exit_code, 0) << ext << r.output;
        Image img;
        ASSERT_EQ(read_image(out, img), "") << ext;
        EXPECT_EQ(img.width, 16);
    }
    std::ifstream ppm(dir + "/out.ppm", std::ios::binary);
    std::string magic(2, ' ');
    ppm.read(magic.data(), 2);
    EXPECT_EQ(magic, "P6");
}

TEST(Cli, BadUsageExitsOne) {
    EXPECT_EQ(run_process({test::cli_path(), "--width", "0"}).exit_code, 1);
    EXPECT_EQ(run_process({test::cli_path(), "--no-such-flag"}).exit_code, 1);
    EXPECT_EQ(run_process({test::cli_path(), "--mode", "fancy"}).exit_code, 1);
    EXPECT_EQ(run_process({test::cli_path(), "--aa", "0"}).exit_code, 1);
    EXPECT_EQ(run_process({test::cli_path(), "--aa", "17"}).exit_code, 1);
    EXPECT_EQ(run_process({test::cli_path(), "--aa-threshold", "1.5"}).exit_code, 1);
    EXPECT_EQ(run_process({test::cli_path(), "--aa-threshold", "nan"}).exit_code, 1);
    EXPECT_EQ(run_process({test::cli_path(), "x.sc", "-o", "out.gif"}).exit_code, 1);
    // A size the format cannot hold is refused before the render, not after it.
    auto huge = run_process({test::cli_path(), "-o", "/tmp/never.bmp", "--width", "32768", "--height", "32768"});
    EXPECT_EQ(huge.exit_code, 1);
    EXPECT_NE(huge.output.find("32768x32768 is too large for .bmp"), std::string::npos) << huge.output;
    // And memory: 32768 × 32768 pixels of 16 bytes of film and 3 of 8-bit image are 19 × 2^30
    // bytes, 19.0 GiB, over a 2G --max-memory.
    huge = run_process({test::cli_path(), "-o", "/tmp/never.png", "--width", "32768", "--height", "32768",
                        "--max-memory", "2G"});
    EXPECT_EQ(huge.exit_code, 1);
    EXPECT_NE(huge.output.find("image needs about 19.0 GiB of memory"), std::string::npos) << huge.output;
    auto help = run_process({test::cli_path(), "--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--max-depth INT:INT in [0 - 1000]=5"), std::string::npos) << help.output;
    EXPECT_NE(help.output.find("Exit codes: 0 done, 1 bad usage, 2 bad scene"), std::string::npos) << help.output;
}

TEST(Cli, RefusesToWriteTheImageOverTheSceneFile) {
    // `whitted scene.png` would put the image next to the scene with its extension changed to
    // .png: the scene itself.
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "oops.png", kSimpleScene);
    for (const std::vector<std::string>& args : {std::vector<std::string>{test::cli_path(), scene, "-q"},
                                                 std::vector<std::string>{test::cli_path(), scene, "-o", scene, "-q"}}) {
        auto r = run_process(args);
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find("is the scene file itself"), std::string::npos) << r.output;
        std::ifstream in(scene, std::ios::binary);
        EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), kSimpleScene);
    }
}

// `whitted out.png` (an image given as the scene, no -o): the image would be its own output, but
// the first thing to say is that it is no scene file; the image stays as it was.
TEST(Cli, AnImageGivenAsTheSceneIsNamedForWhatItIs) {
    std::string dir = test::make_temp_dir();
    const std::string image(std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
    std::string png = write_file(dir, "out.png", image);
    auto r = run_process({test::cli_path(), png, "-q"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(png + ":1:1: error: this is not a scene file (it looks like a PNG image)"), std::string::npos)
        << r.output;
    EXPECT_EQ(r.output.find("is the scene file itself"), std::string::npos) << r.output;
    std::ifstream in(png, std::ios::binary);
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>()), image);
}

// A scene with a lens rendered with one sample per pixel shows it sharp (the lens centre): says so.
TEST(Cli, OneSamplePerPixelOfASceneWithALensSaysSo) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "lens.sc",
                                   "camera [ eye 0 0 5 focus 0 0 0 aperture 0.3 ]\n"
                                   "light [ position 2 2 4 ]\n"
                                   "mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]\n");
    auto one = run_process({test::cli_path(), scene, "-o", dir + "/one.png", "--width", "16", "--height", "12", "-q"});
    EXPECT_EQ(one.exit_code, 0) << one.output;
    EXPECT_NE(one.output.find("whitted: note: this scene has depth of field: raise SPP to see it"), std::string::npos)
        << one.output;
    auto more = run_process(
        {test::cli_path(), scene, "-o", dir + "/more.png", "--width", "16", "--height", "12", "--spp", "4", "-q"});
    EXPECT_EQ(more.exit_code, 0) << more.output;
    EXPECT_EQ(more.output.find("raise SPP"), std::string::npos) << more.output;
}

TEST(Cli, ThousandsOfWarningsAreCountedNotAllPrinted) {
    std::string dir = test::make_temp_dir();
    std::string text = "mastersubgraph root [ trans [ object sphere [ ] ] ]\n";
    for (int i = 0; i < 1000; ++i) text += "[\n";  // a stray '[' is skipped with a warning
    std::string scene = write_file(dir, "brackets.sc", text);
    auto r = run_process({test::cli_path(), scene, "-o", dir + "/b.png", "--width", "8", "--height", "8", "-q"});
    EXPECT_EQ(r.exit_code, 0) << r.output.substr(0, 500);
    std::size_t shown = 0;
    for (std::size_t at = 0; (at = r.output.find(": warning: ", at)) != std::string::npos; ++at) ++shown;
    EXPECT_EQ(shown, 50u);
    EXPECT_NE(r.output.find("brackets.sc:2:1: warning: "), std::string::npos) << r.output.substr(0, 500);
    EXPECT_NE(r.output.find("whitted: 950 more warnings not shown"), std::string::npos) << r.output.substr(r.output.size() - 300);
}

TEST(Cli, AntiAliasingSmoothsTheBallsOutline) {
    // The red ball's outline, a circle of about 12 pixels' radius (seen from 1.5 away, 60° over
    // 40 pixels), crosses some 75 pixels: with --aa 4 they are partly red, where one ray per
    // pixel gives only all or nothing.
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "s.sc", "camera [ eye 0 0 1.5 focus 0 0 0 ]\n"
                                                "mastersubgraph root [ trans [ object sphere [ diffuse 0 0 0 ambient 1 0 0 ] ] ]\n");
    auto count_partial = [&](const char* aa) {
        std::string out = dir + "/aa" + aa + ".png";
        auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "40", "--height", "40", "--aa", aa, "-q"});
        EXPECT_EQ(r.exit_code, 0) << r.output;
        Image img;
        EXPECT_EQ(read_image(out, img), "");
        int partial = 0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) partial += img.at(x, y).x > 0 && img.at(x, y).x < 255;
        return partial;
    };
    EXPECT_EQ(count_partial("1"), 0) << "ambient 1 0 0 and no light: every ray sees red 255 or black";
    EXPECT_GT(count_partial("4"), 40);
}

TEST(Cli, BadSceneExitsTwoWithALocatedError) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "bad.sc", "camera [ eye 0 0 5 ]\nmastersubgraph root [\n  trans [ object blob [ ] ]\n]\n");
    auto r = run_process({test::cli_path(), scene, "-o", dir + "/bad.png", "-q"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find(scene + ":3:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("error:"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/bad.png"));
    // A scene file that cannot be read at all is an I/O failure, not a bad scene.
    auto missing = run_process({test::cli_path(), dir + "/missing.sc", "-q"});
    EXPECT_EQ(missing.exit_code, 3);
    EXPECT_NE(missing.output.find(dir + "/missing.sc: error: cannot read scene file: No such file"), std::string::npos)
        << missing.output;
    EXPECT_EQ(run_process({test::cli_path(), dir, "-o", dir + "/d.png", "-q"}).exit_code, 3);
}

TEST(Cli, UnwritableOutputExitsThreeAndLeavesNoFile) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "s.sc", kSimpleScene);
    auto r = run_process({test::cli_path(), scene, "-o", dir + "/no/such/dir/out.png", "-q", "--width", "8", "--height", "8"});
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("cannot write"), std::string::npos) << r.output;
    // Nothing half-written lies about, temporary files included.
    for (auto& e : fs::directory_iterator(dir)) EXPECT_NE(e.path().extension(), ".png") << e.path();
}

TEST(Cli, AWriteThatFailsMidwayExitsThreeAndKeepsTheOldImage) {
    // A file-size limit of a few blocks (SIGXFSZ ignored, so writes past it fail with EFBIG) is a
    // disk that fills up in the middle of the image: the old image must stay as it was.
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "s.sc", kSimpleScene);
    for (std::string ext : {".png", ".bmp", ".jpg", ".ppm"}) {
        SCOPED_TRACE(ext);
        const std::string out = dir + "/out" + ext;
        const std::string before = "the previous image";
        write_file(dir, "out" + ext, before);
        auto r = run_process({"/bin/sh", "-c", "ulimit -f 2; trap '' XFSZ; exec \"$0\" \"$@\"", test::cli_path(),
                              scene, "-o", out, "--width", "200", "--height", "150", "-q"});
        EXPECT_EQ(r.exit_code, 3) << r.output;
        EXPECT_NE(r.output.find("cannot write"), std::string::npos) << r.output;
        std::ifstream in(out, std::ios::binary);
        std::string after((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        EXPECT_EQ(after, before);
    }
    for (auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
}

// A scene whose load takes a while: one sphere instanced 10⁶ times through six levels of ten.
std::string million_spheres() {
    std::string text = "camera [ eye 0 0 40 focus 0 0 0 ]\nlight [ position 5 5 40 color 1 1 1 ]\n"
                       "mastersubgraph l0 [ trans [ scale .1 .1 .1 object sphere [ ] ] ]\n";
    for (int level = 1; level <= 6; ++level) {
        // (std::string("l") += …: GCC 12 warns falsely about "l" + std::string, its bug 105329.)
        const std::string name = level == 6 ? std::string("root") : std::string("l") += std::to_string(level);
        const std::string child = std::string("l") += std::to_string(level - 1);
        text += "mastersubgraph " + name + " [\n";
        for (int i = 0; i < 10; ++i) {
            const double x = (i - 4.5) * std::pow(3.0, level - 1) * 0.3, y = level % 2 ? 0.1 * i : 0.0;
            text += "  trans [ translate " + std::to_string(x) + " " + std::to_string(y) + " 0 subgraph " + child + " ]\n";
        }
        text += "]\n";
    }
    return text;
}

TEST(Cli, StatsCountTheRaysAndTheThreadsUsed) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "s.sc", kSimpleScene);
    auto r = run_process({test::cli_path(), scene, "-o", dir + "/o.png", "--width", "100", "--height", "60",
                          "--threads", "3", "--aa", "2", "--stats", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("rays: camera 24000,"), std::string::npos) << r.output;  // 100 · 60 · 2²
    EXPECT_NE(r.output.find("(3 threads)"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("objects 1, lights 1"), std::string::npos) << r.output;
    for (const char* stage : {"parse ", "flatten ", "textures ", "meshes ", "build ", "render ", "Mrays/s"})
        EXPECT_NE(r.output.find(stage), std::string::npos) << stage << "\n" << r.output;
    // Each kind's rate through the acceleration structure, from the traversals timed: the camera
    // rays' is never 0 (some were timed), the scene has no mirror or glass (nothing timed, 0).
    const std::size_t rates = r.output.find("traversal Mrays/s per thread (1 in 32 timed): camera ");
    ASSERT_NE(rates, std::string::npos) << r.output;
    EXPECT_GT(std::stod(r.output.substr(rates + std::strlen("traversal Mrays/s per thread (1 in 32 timed): camera "))), 0.0);
    EXPECT_NE(r.output.find("reflected 0.00, refracted 0.00, shadow ", rates), std::string::npos) << r.output;
    // An 8×8 image is one tile: one thread is all that can work on it, and that is what is said.
    r = run_process({test::cli_path(), scene, "-o", dir + "/o.png", "--width", "8", "--height", "8", "--threads", "3",
                     "--stats", "-q"});
    EXPECT_NE(r.output.find("(1 threads)"), std::string::npos) << r.output;
}

TEST(Cli, ThreadCountChangesNoByte) {
    std::string dir = test::make_temp_dir();
    std::string scene = test::source_dir() + "/scenes/showcase.sc";
    std::string first;
    for (const char* threads : {"1", "2", "5"}) {
        std::string out = dir + "/t" + threads + ".ppm";
        auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "150", "--height", "110", "--threads",
                              threads, "--stats", "-q"});
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find(std::string("(") + threads + " threads)"), std::string::npos) << r.output;
        std::ifstream in(out, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (first.empty()) first = bytes;
        EXPECT_TRUE(bytes == first) << threads << " threads gave another image";
    }
}

// --seed: other sample values (an independent render, to measure noise against), the same for the
// same seed.
TEST(Cli, ASeedGivesOtherSamplesAndTheSameSeedTheSameBytes) {
    std::string dir = test::make_temp_dir();
    std::string scene = test::source_dir() + "/scenes/features/cornell_box.sc";
    auto bytes_of = [&](const char* seed) {
        std::string out = dir + "/s" + seed + ".pfm";
        auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "32", "--height", "24", "--mode", "path",
                              "--spp", "4", "--seed", seed, "-q"});
        EXPECT_EQ(r.exit_code, 0) << r.output;
        std::ifstream in(out, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    const std::string zero = bytes_of("0"), one = bytes_of("1");
    ASSERT_FALSE(zero.empty());
    EXPECT_NE(zero, one) << "--seed 1 gave the samples of seed 0";
    EXPECT_EQ(bytes_of("1"), one);
}

// --view: path mode's PNG is its radiance through the sRGB curve (and says so in an sRGB chunk);
// the lab's modes stay linear; a view given wins over the mode's.
TEST(Cli, PathModeImagesAreSrgbEncodedAndTheLabsLinear) {
    std::string dir = test::make_temp_dir();
    std::string scene = test::source_dir() + "/scenes/features/cornell_box.sc";
    auto render_to = [&](const std::string& out, std::vector<std::string> extra) {
        std::vector<std::string> args = {test::cli_path(), scene, "-o", out, "--width", "32", "--height", "24",
                                         "--spp", "4", "-q"};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto r = run_process(args);
        EXPECT_EQ(r.exit_code, 0) << r.output;
    };
    render_to(dir + "/p.pfm", {"--mode", "path"});
    render_to(dir + "/p.png", {"--mode", "path"});
    render_to(dir + "/f.png", {"--mode", "path", "--view", "filmic"});
    render_to(dir + "/w.pfm", {});
    render_to(dir + "/w.png", {});
    std::ifstream pfm_file(dir + "/p.pfm", std::ios::binary);
    const std::string pfm_bytes((std::istreambuf_iterator<char>(pfm_file)), std::istreambuf_iterator<char>());
    LinearImage radiance;
    ASSERT_EQ(decode_linear_image(pfm_bytes, ImageLimits{}, radiance), "");
    Image srgb, filmic;
    ASSERT_EQ(read_image(dir + "/p.png", srgb), "");
    ASSERT_EQ(read_image(dir + "/f.png", filmic), "");
    int above_one = 0;
    for (std::size_t i = 0; i < radiance.rgb.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            const float v = radiance.rgb[i][c];
            above_one += v > 1.0f;
            ASSERT_EQ(srgb.rgb[3 * i + std::size_t(c)], view_byte(ViewTransform::Srgb, v)) << i;
            ASSERT_EQ(filmic.rgb[3 * i + std::size_t(c)], view_byte(ViewTransform::Filmic, v)) << i;
        }
    EXPECT_GT(above_one, 0) << "the light is brighter than white";
    const auto file = [](const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    };
    EXPECT_NE(file(dir + "/p.png").find("sRGB"), std::string::npos);
    EXPECT_EQ(file(dir + "/w.png").find("sRGB"), std::string::npos);
    // Whitted mode: the linear values clamped, byte for byte (scene-format.md §7).
    std::ifstream wpfm(dir + "/w.pfm", std::ios::binary);
    const std::string w_bytes((std::istreambuf_iterator<char>(wpfm)), std::istreambuf_iterator<char>());
    LinearImage whitted_linear;
    ASSERT_EQ(decode_linear_image(w_bytes, ImageLimits{}, whitted_linear), "");
    Image lab;
    ASSERT_EQ(read_image(dir + "/w.png", lab), "");
    for (std::size_t i = 0; i < whitted_linear.rgb.size(); ++i)
        for (int c = 0; c < 3; ++c) ASSERT_EQ(lab.rgb[3 * i + std::size_t(c)], to_byte(whitted_linear.rgb[i][c]));
}

TEST(Cli, ProgressLineOnlyOnATerminal) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "s.sc", kSimpleScene);
    const std::vector<std::string> args = {test::cli_path(), scene, "-o", dir + "/o.png", "--width", "64", "--height", "64"};
    // On a terminal: the line is drawn in place (carriage return, erase line) and erased before
    // the final message.
    auto tty = test::run_in_terminal(args);
    ASSERT_EQ(tty.exit_code, 0) << tty.output;
    EXPECT_NE(tty.output.find("\r\033[Krendering "), std::string::npos) << tty.output;
    EXPECT_NE(tty.output.find("%  elapsed "), std::string::npos) << tty.output;
    EXPECT_NE(tty.output.find(" eta "), std::string::npos) << tty.output;
    EXPECT_NE(tty.output.find("\r\033[Kwrote "), std::string::npos) << tty.output;
    // Into a pipe, or with --quiet on a terminal: no progress at all.
    auto piped = run_process(args);
    ASSERT_EQ(piped.exit_code, 0) << piped.output;
    EXPECT_EQ(piped.output.find("rendering"), std::string::npos) << piped.output;
    std::vector<std::string> quiet = args;
    quiet.push_back("--quiet");
    auto tty_quiet = test::run_in_terminal(quiet);
    ASSERT_EQ(tty_quiet.exit_code, 0) << tty_quiet.output;
    EXPECT_EQ(tty_quiet.output.find("rendering"), std::string::npos) << tty_quiet.output;
}

// Ctrl-C during the load: nothing is rendered or written. The signal comes as the load starts (a
// hidden test option): a signal timed against the load's length raced it on a fast machine.
TEST(Cli, InterruptWhileLoadingWritesNothing) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "big.sc", million_spheres());
    std::string out = dir + "/big.png";
    auto r = run_process({test::cli_path(), scene, "-o", out, "-q", "--stats", "--test-interrupt-at-load"});
    EXPECT_EQ(r.exit_code, 130) << r.output;
    EXPECT_NE(r.output.find("interrupted while loading"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("render "), std::string::npos) << "nothing rendered: " << r.output;
    EXPECT_FALSE(fs::exists(out));
    EXPECT_FALSE(fs::exists(dir + "/big.partial.png"));
}

TEST(Cli, ASecondInterruptExitsAtOnceAndLeavesNoPartialFile) {
    // A 48 MB image: the first Ctrl-C stops the render within a row, then the PPM takes a while
    // to write; the second lands somewhere in the render's end or the write.
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "heavy.sc", heavy_scene());
    for (int gap : {0, 30, 80, 160, 320}) {
        SCOPED_TRACE(gap);
        std::string out = dir + "/big" + std::to_string(gap) + ".ppm";
        auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "4000", "--height", "4000",
                               "--max-depth", "1", "-q"},
                             std::vector<int>{300, 300 + gap});
        EXPECT_EQ(r.exit_code, 130) << r.output;
        EXPECT_FALSE(fs::exists(out)) << "an interrupted render writes NAME.partial.EXT";
        if (fs::exists(partial_image_path(out))) {  // the second Ctrl-C came after the image was complete
            Image img;
            EXPECT_EQ(read_image(partial_image_path(out), img), "");
            EXPECT_EQ(img.width, 4000);
        }
        for (auto& e : fs::directory_iterator(dir))
            EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
    }
}

TEST(Cli, InterruptWritesThePartialImageAndExitsNonZero) {
    std::string dir = test::make_temp_dir();
    std::string scene = write_file(dir, "heavy.sc", heavy_scene());
    std::string out = dir + "/heavy.png";
    auto start = std::chrono::steady_clock::now();
    auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "3000", "--height", "3000", "--max-depth",
                          "12", "-q"},
                         1500);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 130) << r.output;
    EXPECT_NE(r.output.find("interrupted"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("to " + dir + "/heavy.partial.png (" + out + " was not written)"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(out));
    Image img;
    ASSERT_EQ(read_image(dir + "/heavy.partial.png", img), "") << "a valid image of what was done";
    EXPECT_EQ(img.width, 3000);
    EXPECT_EQ(img.at(2999, 2999), glm::u8vec3(0)) << "the unrendered part is black";
    // The whole render takes seconds (depth 1: tiles of milliseconds, so that some are done when the
    // interrupt comes: a render with none done writes nothing); stopping and writing the 9-megapixel PNG
    // take well under a second in Release (under the sanitizers, a few).
    EXPECT_LT(seconds - 1.5, 10.0) << "seconds from the interrupt to the exit";
}

}  // namespace
}  // namespace whitted
