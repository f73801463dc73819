// `whitted explain SCENE IMAGE` as a student runs it: the reference itself exits 0 with "no
// difference", an image one bounce short exits 2 and names the depth, --json parses back, the error
// image is written beside the image; a wrong size, an unreadable image and a bad scene get their codes.
#include <filesystem>

#include <gtest/gtest.h>

#include "support/json.h"
#include "support/run_process.h"

namespace whitted {
namespace {

using test::Json;
using test::run_process;

struct CliExplain : ::testing::Test {
    std::string dir = test::make_temp_dir();
    std::string scene = test::source_dir() + "/scenes/features/reflection.sc";
    void TearDown() override { std::filesystem::remove_all(dir); }
    test::ProcessResult whitted(std::vector<std::string> args) {
        args.insert(args.begin(), test::cli_path());
        return run_process(args);
    }
    std::string render(const std::string& name, std::vector<std::string> extra = {}) {
        std::vector<std::string> args{scene, "-q", "--width", "64", "--height", "48", "-o", dir + "/" + name};
        args.insert(args.end(), extra.begin(), extra.end());
        const auto r = whitted(args);
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return dir + "/" + name;
    }
};

TEST_F(CliExplain, TheReferenceItselfExitsZero) {
    const auto r = whitted({"explain", scene, render("ref.png")});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("no difference"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("PASS"), std::string::npos);
    EXPECT_FALSE(std::filesystem::exists(dir + "/ref.explain.png"));  // nothing differs: no error image
}

TEST_F(CliExplain, AnImageOneBounceShortIsNamed) {
    const std::string mine = render("mine.png", {"--max-depth", "4"});
    const auto r = whitted({"explain", scene, mine});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("your image matches whitted with *recursion one level shallower"), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("FAILURE"), std::string::npos);
    EXPECT_TRUE(std::filesystem::exists(dir + "/mine.explain.png"));

    const auto j = whitted({"explain", scene, mine, "--json", "--no-diff"});
    ASSERT_EQ(j.exit_code, 2) << j.output;
    const Json json = Json::parse(j.output);
    EXPECT_EQ(json["result"].string, "FAILURE");
    EXPECT_EQ(json["exit_code"].number, 2);
    ASSERT_FALSE(json["matches"].array.empty());
    EXPECT_EQ(json["matches"].array[0]["name"].string, "depth-minus-1");
    EXPECT_FALSE(json["regions"].array.empty());
}

TEST_F(CliExplain, ErrorsGetTheirExitCodes) {
    const std::string ref = render("ref.png");
    EXPECT_EQ(whitted({"explain", scene, ref, "--width", "32"}).exit_code, 3);  // the image is 64x48
    EXPECT_EQ(whitted({"explain", scene, dir + "/missing.png"}).exit_code, 4);
    EXPECT_EQ(whitted({"explain", scene}).exit_code, 5);
    const std::string bad = test::write_file(dir, "bad.sc", "camera [ angle 500 ]\n");
    const auto r = whitted({"explain", bad, ref});
    EXPECT_EQ(r.exit_code, 6) << r.output;
    EXPECT_NE(r.output.find("bad.sc:1:"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace whitted
