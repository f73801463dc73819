// The `whitted` command as a user runs it: exit codes, output files, messages, Ctrl-C.
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::run_process;
using test::write_file;

const char* kSimpleScene = R"(camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]
)";

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
    EXPECT_EQ(run_process({test::cli_path(), "x.sc", "-o", "out.gif"}).exit_code, 1);
    auto help = run_process({test::cli_path(), "--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--max-depth"), std::string::npos);
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
    EXPECT_EQ(run_process({test::cli_path(), dir + "/missing.sc", "-q"}).exit_code, 2);
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

TEST(Cli, InterruptWritesThePartialImageAndExitsNonZero) {
    std::string dir = test::make_temp_dir();
    // Many mirrors and a big image: seconds of work, so the interrupt lands mid-render.
    std::string text = "camera [ eye 0 0 12 focus 0 0 0 ]\nlight [ position 3 3 10 color 1 1 1 ]\nmastersubgraph root [\n";
    for (int i = 0; i < 400; ++i)
        text += "trans [ translate " + std::to_string(i % 20 - 10) + " " + std::to_string(i / 20 - 10) +
                " 0 object sphere [ reflect .9 .9 .9 transparent .5 .5 .5 ior 1.3 ] ]\n";
    text += "]\n";
    std::string scene = write_file(dir, "heavy.sc", text);
    std::string out = dir + "/heavy.png";
    auto start = std::chrono::steady_clock::now();
    auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "3000", "--height", "3000", "--max-depth",
                          "12", "-q"},
                         500);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 130) << r.output;
    EXPECT_NE(r.output.find("interrupted"), std::string::npos) << r.output;
    Image img;
    ASSERT_EQ(read_image(out, img), "") << "a valid image of what was done";
    EXPECT_EQ(img.width, 3000);
    EXPECT_EQ(img.at(2999, 2999), glm::u8vec3(0)) << "the unrendered part is black";
    EXPECT_LT(seconds, 30.0) << "the interrupt must stop the render promptly";
}

}  // namespace
}  // namespace whitted
