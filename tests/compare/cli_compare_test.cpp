// `whitted compare A B` as a student or a grading script runs it: idiff's exit codes at the
// thresholds, the size and file errors, bad usage, --json parsed back, the --diff image.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "compare/colour_map.h"
#include "film/image_io.h"
#include "support/json.h"
#include "support/run_process.h"

namespace whitted {
namespace {

using test::Json;
using test::run_process;

// 10 × 10 grey 100; B has three pixels 51 brighter (0.2 in every channel): 3% of the pixels.
struct CliCompare : ::testing::Test {
    std::string dir = test::make_temp_dir();
    std::string a = dir + "/a.png", b = dir + "/b.png";
    void SetUp() override {
        Image im(10, 10);
        std::fill(im.rgb.begin(), im.rgb.end(), std::uint8_t(100));
        ASSERT_EQ(write_image(im, a), "");
        for (int i : {11, 55, 99}) std::fill_n(im.rgb.begin() + 3 * i, 3, std::uint8_t(151));
        ASSERT_EQ(write_image(im, b), "");
    }
    void TearDown() override { std::filesystem::remove_all(dir); }
    test::ProcessResult compare(std::vector<std::string> args) {
        args.insert(args.begin(), {test::cli_path(), "compare"});
        return run_process(args);
    }
};

TEST_F(CliCompare, EqualImagesPass) {
    const auto r = compare({a, a});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("PASS"), std::string::npos);
    EXPECT_NE(r.output.find("infinite"), std::string::npos);  // the PSNR
}

TEST_F(CliCompare, IdiffExitCodesAtTheThresholds) {
    EXPECT_EQ(compare({a, b}).exit_code, 2);                                  // any difference fails by default
    EXPECT_EQ(compare({a, b, "--failpercent", "3"}).exit_code, 1);            // 3% is not more than 3%; warn's 0% is
    EXPECT_EQ(compare({a, b, "--failpercent", "3", "--warnpercent", "3"}).exit_code, 0);
    EXPECT_EQ(compare({a, b, "--failpercent", "2.9"}).exit_code, 2);
    EXPECT_EQ(compare({a, b, "--fail", "0.3"}).exit_code, 1);                 // 0.2 is under the fail threshold
    EXPECT_EQ(compare({a, b, "--fail", "0.3", "--warn", "0.3"}).exit_code, 0);
    EXPECT_EQ(compare({a, b, "--fail", "0.1", "--failpercent", "50", "--hardfail", "0.15"}).exit_code, 2);
    EXPECT_EQ(compare({a, b, "--failpercent", "5", "--warnpercent", "5", "--hardwarn", "0.1"}).exit_code, 1);
    const auto r = compare({a, b});
    EXPECT_NE(r.output.find("FAILURE"), std::string::npos);
    EXPECT_NE(r.output.find("over --fail   3 pixels (3.00%) by more than 1e-06; FAILURE above 0% of the pixels"),
              std::string::npos)
        << r.output;
}

TEST_F(CliCompare, JsonParsesBackWithEveryMetric) {
    const auto r = compare({a, b, "--json", "--fail", "0.1", "--failpercent", "10"});
    ASSERT_EQ(r.exit_code, 1) << r.output;
    const Json j = Json::parse(r.output);
    EXPECT_EQ(j["a"]["path"].string, a);
    EXPECT_EQ(j["b"]["format"].string, "PNG");
    EXPECT_EQ(j["width"].number, 10);
    EXPECT_EQ(j["height"].number, 10);
    EXPECT_EQ(j["result"].string, "WARNING");
    EXPECT_EQ(j["exit_code"].number, 1);
    // Nine values of 300 differ by 0.2: MSE = 9 · 0.04 / 300 = 0.0012.
    EXPECT_NEAR(j["psnr"].number, 10.0 * std::log10(1.0 / 0.0012), 1e-4);
    EXPECT_NEAR(j["mean_error"].number, 9 * 0.2 / 300, 1e-7);
    EXPECT_NEAR(j["max_error"]["value"].number, 0.2, 1e-6);
    EXPECT_EQ(j["max_error"]["x"].number, 1);
    EXPECT_EQ(j["max_error"]["y"].number, 1);
    EXPECT_EQ(j["max_error"]["channel"].string, "R");
    EXPECT_EQ(j["fail"]["pixels"].number, 3);
    EXPECT_NEAR(j["fail"]["share"].number, 0.03, 1e-12);
    EXPECT_NEAR(j["fail"]["threshold"].number, 0.1, 1e-9);
    EXPECT_EQ(j["fail"]["percent"].number, 10);
    EXPECT_TRUE(j["fail"]["hard"].is_null());  // no hard limit: infinite
    EXPECT_EQ(j["warn"]["pixels"].number, 3);
    EXPECT_EQ(j["ssim"]["block"].number, 8);
    EXPECT_EQ(j["ssim"]["blocks"].number, 4);  // 10 × 10: two blocks across, two down
    EXPECT_LT(j["ssim"]["worst"]["ssim"].number, 1.0);
    EXPECT_EQ(j["ssim"]["threshold"].number, 0.996);
    EXPECT_GT(j["flip"]["mean"].number, 0.0);
    EXPECT_LE(j["flip"]["max"].number, 1.0);
    EXPECT_NEAR(j["flip"]["pixels_per_degree"].number, 67.0206, 1e-4);
    EXPECT_FALSE(j.has("diff_image"));

    const Json same = Json::parse(compare({a, a, "--json"}).output);
    EXPECT_TRUE(same["psnr"].is_null());  // infinite
    EXPECT_EQ(same["result"].string, "PASS");
    EXPECT_EQ(same["flip"]["mean"].number, 0);
    EXPECT_EQ(same["ssim"]["mean"].number, 1);
}

TEST_F(CliCompare, DiffImageInMagma) {
    const std::string diff = dir + "/diff.png";
    const auto r = compare({a, b, "--diff", diff, "--json"});
    ASSERT_EQ(r.exit_code, 2) << r.output;
    EXPECT_EQ(Json::parse(r.output)["diff_image"].string, diff);
    Image im;
    ASSERT_EQ(read_image(diff, im), "");
    ASSERT_EQ(im.width, 10);
    ASSERT_EQ(im.height, 10);
    EXPECT_EQ(im.at(0, 9), magma(0.0f));  // far from the three pixels: no difference
    const glm::u8vec3 hit = im.at(5, 5);  // one of them: brighter than black
    EXPECT_GT(int(hit.x) + hit.y + hit.z, 100);
}

TEST_F(CliCompare, DiffNeverReplacesAnInput) {
    const auto before = std::filesystem::file_size(a);
    const auto r = compare({a, b, "--diff", a});
    EXPECT_EQ(r.exit_code, 5) << r.output;
    EXPECT_EQ(std::filesystem::file_size(a), before);
    EXPECT_EQ(compare({a, b, "--diff", dir + "/no/such/folder/d.png"}).exit_code, 4);
    EXPECT_EQ(compare({a, b, "--diff", dir + "/d.tiff"}).exit_code, 5);  // a format whitted cannot write
}

TEST_F(CliCompare, SizesDifferIsExitThree) {
    ASSERT_EQ(write_image(Image(12, 10), dir + "/wide.png"), "");
    const auto r = compare({a, dir + "/wide.png"});
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("differ in size: 10x10 and 12x10"), std::string::npos) << r.output;
}

TEST_F(CliCompare, UnreadableImageIsExitFour) {
    auto r = compare({a, dir + "/missing.png"});
    EXPECT_EQ(r.exit_code, 4);
    EXPECT_NE(r.output.find("missing.png"), std::string::npos);
    test::write_file(dir, "scene.png", "camera [ ]\n");
    EXPECT_EQ(compare({dir + "/scene.png", a}).exit_code, 4);
}

TEST_F(CliCompare, BadUsageIsExitFive) {
    EXPECT_EQ(compare({a}).exit_code, 5);
    EXPECT_EQ(compare({a, b, "--frobnicate"}).exit_code, 5);
    EXPECT_EQ(compare({a, b, "--fail", "-1"}).exit_code, 5);
    EXPECT_EQ(compare({a, b, "--fail", "much"}).exit_code, 5);
    const auto help = compare({"--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--failpercent"), std::string::npos);
    EXPECT_NE(help.output.find("--diff"), std::string::npos);
}

TEST_F(CliCompare, QuietSaysNothing) {
    const auto r = compare({a, b, "-q"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(r.output, "");
}

// The linear .exr of a render against its 8-bit .png: the same picture, up to the 8-bit rounding.
TEST_F(CliCompare, ExrAgainstPng) {
    const std::string scene = test::write_file(dir, "s.sc", R"(camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]
)");
    for (const char* ext : {".png", ".exr"}) {
        const auto r = run_process({test::cli_path(), scene, "-o", dir + "/r" + ext, "--width", "32", "--height", "24", "-q"});
        ASSERT_EQ(r.exit_code, 0) << r.output;
    }
    const auto r = compare({dir + "/r.exr", dir + "/r.png", "--json", "--fail", "0.0020", "--warn", "0.0020"});
    ASSERT_EQ(r.exit_code, 0) << r.output;  // within half a step of 1/255
    const Json j = Json::parse(r.output);
    EXPECT_EQ(j["a"]["format"].string, "OpenEXR");
    EXPECT_GT(j["max_error"]["value"].number, 0.0);
}

}  // namespace
}  // namespace whitted
