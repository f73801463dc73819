// `whitted --time-limit S`: whole passes while they fit, then the complete image at the samples
// reached, exit 0; the file says how many (PNG tEXt); the bytes are those of a render of that many.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

// The tEXt chunks of a PNG file: keyword → text.
std::map<std::string, std::string> png_text(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string d = ss.str();
    std::map<std::string, std::string> text;
    for (std::size_t i = 8; i + 12 <= d.size();) {
        const std::uint32_t n = std::uint32_t(std::uint8_t(d[i])) << 24 | std::uint32_t(std::uint8_t(d[i + 1])) << 16 |
                                std::uint32_t(std::uint8_t(d[i + 2])) << 8 | std::uint8_t(d[i + 3]);
        if (d.compare(i + 4, 4, "tEXt") == 0) {
            const std::string body = d.substr(i + 8, n);
            const std::size_t zero = body.find('\0');
            text[body.substr(0, zero)] = body.substr(zero + 1);
        }
        i += 12 + n;
    }
    return text;
}

TEST(CliTimeLimit, WritesTheCompleteImageOfTheSamplesReached) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = std::string(WHITTED_SOURCE_DIR) + "/scenes/features/soft_shadows.sc";
    const std::string out = dir + "/budget.png";
    auto r = test::run_process({test::cli_path(), scene, "-o", out, "--width", "64", "--height", "48", "--spp",
                                "65536", "--time-limit", "1.5", "--threads", "2"},
                               std::vector<test::TimedSignal>{{120000, SIGKILL}});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("fitted in the time limit of 1.5 s (65536 asked for)"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/budget.partial.png"));
    const auto text = png_text(out);
    ASSERT_TRUE(text.count("whitted:samples")) << "the samples reached are in the file";
    const int samples = std::stoi(text.at("whitted:samples"));
    const std::string passes = text.at("whitted:passes");
    // Passes of 1, 2, 4 … samples: k whole passes are 2^(k-1) samples; 17 passes reach 65536.
    const int k = std::stoi(passes);
    EXPECT_EQ(passes, std::to_string(k) + " of 17");
    EXPECT_EQ(samples, 1 << (k - 1));
    ASSERT_GE(k, 2) << "a 64 x 48 image takes more than two passes in 1.5 s";
    ASSERT_LT(k, 17);
    // The same bytes as a render of that many samples, on another thread count: no tile missing,
    // none with samples of an unfinished pass.
    const std::string same = dir + "/same.png";
    r = test::run_process({test::cli_path(), scene, "-o", same, "--width", "64", "--height", "48", "--spp",
                           std::to_string(samples), "--threads", "1", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Image a, b;
    ASSERT_EQ(read_image(out, a), "");
    ASSERT_EQ(read_image(same, b), "");
    EXPECT_EQ(a.rgb, b.rgb);
    EXPECT_EQ(png_text(same).at("whitted:samples"), std::to_string(samples));
}

// A budget the load alone uses up: nothing is written, and the exit code says the time ran out.
TEST(CliTimeLimit, ABudgetTooSmallForTheFirstPassWritesNoCompleteImage) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc";
    const auto r = test::run_process({test::cli_path(), scene, "-o", dir + "/o.png", "--width", "4000", "--height",
                                      "3000", "--aa", "4", "--time-limit", "0.3", "-q"},
                                     std::vector<test::TimedSignal>{{120000, SIGKILL}});
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_NE(r.output.find("(--time-limit) ran out"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/o.png")) << "the image asked for is complete or not there";
}

}  // namespace
}  // namespace whitted
