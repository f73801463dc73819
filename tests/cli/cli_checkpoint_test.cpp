// `whitted --checkpoint FILE` / `--resume FILE`: a render stopped part-way (here by a Ctrl-C at a
// known tile, a hidden test option) and resumed writes the bytes of a render never stopped, for a
// single pass (tiles only) and across passes; a resume of another job is refused, naming the
// setting that differs; a checkpoint cut short loses only its last tile; a checkpoint that is the
// scene or the output is refused before anything is written.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

std::string bytes_of(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// Soft shadows: every sample of every pass changes the pixels. 96 × 64 is 3 × 2 tiles of 32.
const std::string kScene = std::string(WHITTED_SOURCE_DIR) + "/scenes/features/soft_shadows.sc";

std::vector<std::string> whitted(const std::string& out, int spp, std::vector<std::string> more = {}) {
    std::vector<std::string> args{test::cli_path(), kScene, "-o", out, "--width", "96", "--height", "64", "--spp",
                                  std::to_string(spp)};
    // An option given twice takes the later value (CLI11 would refuse a repeat).
    for (std::size_t i = 0; i < more.size(); ++i) {
        const auto at = std::find(args.begin(), args.end(), more[i]);
        if (at != args.end() && i + 1 < more.size() && more[i].rfind("--", 0) == 0 && at + 1 != args.end())
            *(at + 1) = more[++i];
        else
            args.push_back(more[i]);
    }
    return args;
}

class CliCheckpoint : public ::testing::Test {
protected:
    void SetUp() override { dir = test::make_temp_dir(); }
    // A render never stopped.
    std::string straight(int spp) {
        const std::string out = dir + "/straight" + std::to_string(spp) + ".png";
        const auto r = test::run_process(whitted(out, spp, {"-q"}));
        EXPECT_EQ(r.exit_code, 0) << r.output;
        return bytes_of(out);
    }
    // A render with a checkpoint, stopped by Ctrl-C as its nth tile finishes (one thread: the
    // tiles finish in order).
    void stopped(int spp, int tiles, const std::string& ck) {
        const auto r = test::run_process(whitted(dir + "/out.png", spp,
                                                 {"-q", "--checkpoint", ck, "--threads", "1", "--checkpoint-every", "0",
                                                  "--test-interrupt-after-tiles", std::to_string(tiles)}));
        ASSERT_EQ(r.exit_code, 130) << r.output;
        ASSERT_FALSE(fs::exists(dir + "/out.png"));
        ASSERT_TRUE(fs::exists(ck));
    }
    std::string dir;
};

TEST_F(CliCheckpoint, OnePassResumedFromItsTilesGivesTheSameBytes) {
    const std::string want = straight(1);
    const std::string ck = dir + "/ck";
    stopped(1, 4, ck);
    // Resumed on two threads, keeping the checkpoint up to date.
    const auto r = test::run_process(whitted(dir + "/out.png", 1, {"--resume", ck, "--checkpoint", ck}));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("resuming from " + ck + ": 4 of 6 tiles of the first pass"), std::string::npos)
        << r.output;
    EXPECT_EQ(bytes_of(dir + "/out.png"), want);
    // The checkpoint now holds the whole render: a resume renders nothing and writes the same.
    fs::remove(dir + "/out.png");
    const auto again = test::run_process(whitted(dir + "/out.png", 1, {"--resume", ck}));
    ASSERT_EQ(again.exit_code, 0) << again.output;
    EXPECT_NE(again.output.find("1 of 1 whole passes"), std::string::npos) << again.output;
    EXPECT_EQ(bytes_of(dir + "/out.png"), want);
}

TEST_F(CliCheckpoint, PassesResumedFromTheLastWholeOneAndTilesOfTheNextGiveTheSameBytes) {
    const std::string want = straight(8);  // passes of 1, 2, 4, 8 samples, 6 tiles each
    struct Stop {
        int tiles;
        const char* resumed;
    };
    for (const Stop& stop : {Stop{14, "2 of 4 whole passes (2 samples per pixel) and 2 of 6 tiles of the next"},
                             Stop{3, "3 of 6 tiles of the first pass"},
                             Stop{18, "3 of 4 whole passes (4 samples per pixel) and 0 of 6 tiles of the next"},
                             Stop{23, "3 of 4 whole passes (4 samples per pixel) and 5 of 6 tiles of the next"}}) {
        SCOPED_TRACE(stop.tiles);
        const std::string ck = dir + "/ck" + std::to_string(stop.tiles);
        stopped(8, stop.tiles, ck);
        fs::remove(dir + "/out.partial.png");
        const auto r = test::run_process(whitted(dir + "/out.png", 8, {"--resume", ck}));
        ASSERT_EQ(r.exit_code, 0) << r.output;
        EXPECT_NE(r.output.find(std::string("resuming from ") + ck + ": " + stop.resumed), std::string::npos)
            << r.output;
        EXPECT_EQ(bytes_of(dir + "/out.png"), want);
        fs::remove(dir + "/out.png");
    }
}

TEST_F(CliCheckpoint, AResumeOfAnotherJobIsRefusedNamingTheSetting) {
    const std::string ck = dir + "/ck";
    stopped(8, 8, ck);
    struct Change {
        std::vector<std::string> args;
        const char* message;
    };
    for (const Change& c : {Change{{"--time", "0.5"}, "was made with --time 0, not 0.5"},
                            Change{{"--mode", "path"}, "was made with --mode whitted, not path"},
                            Change{{"--max-depth", "3"}, "was made with --max-depth 5, not 3"},
                            Change{{"--width", "97"}, "is of a 96x64 image in tiles of 32"}}) {
        SCOPED_TRACE(c.message);
        std::vector<std::string> more = c.args;
        more.insert(more.end(), {"--resume", ck});
        const auto r = test::run_process(whitted(dir + "/other.png", 8, more));
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << r.output;
        EXPECT_FALSE(fs::exists(dir + "/other.png"));
    }
    const auto spp = test::run_process(whitted(dir + "/other.png", 16, {"--resume", ck}));
    EXPECT_EQ(spp.exit_code, 1) << spp.output;
    EXPECT_NE(spp.output.find("was made with --spp 8, not 16"), std::string::npos) << spp.output;
    // Another scene (a copy with one more byte).
    const std::string scene = dir + "/scene.sc";
    std::ofstream(scene) << bytes_of(kScene) << "\n";
    auto args = whitted(dir + "/other.png", 8, {"--resume", ck});
    args[1] = scene;
    const auto other = test::run_process(args);
    EXPECT_EQ(other.exit_code, 1) << other.output;
    EXPECT_NE(other.output.find("another scene, textures or meshes"), std::string::npos) << other.output;
    // The thread count changes no pixel: taken.
    const auto threads = test::run_process(whitted(dir + "/out.png", 8, {"--resume", ck, "--threads", "2"}));
    EXPECT_EQ(threads.exit_code, 0) << threads.output;
}

TEST_F(CliCheckpoint, ACheckpointCutShortLosesOnlyItsLastTile) {
    const std::string want = straight(8);
    const std::string ck = dir + "/ck";
    stopped(8, 16, ck);  // 2 whole passes and 4 tiles of the third
    fs::resize_file(ck, fs::file_size(ck) - 100);  // the last record cut short, as by a kill
    const auto r = test::run_process(whitted(dir + "/out.png", 8, {"--resume", ck}));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("2 of 4 whole passes (2 samples per pixel) and 3 of 6 tiles of the next"),
              std::string::npos)
        << r.output;
    EXPECT_EQ(bytes_of(dir + "/out.png"), want);
}

TEST_F(CliCheckpoint, ACheckpointThatIsTheSceneOrTheOutputIsRefused) {
    const std::string scene = dir + "/scene.sc";
    std::ofstream(scene) << bytes_of(kScene);
    const std::string before = bytes_of(scene);
    for (const std::string& ck : {scene, dir + "/out.png", dir + "/out.partial.png"}) {
        SCOPED_TRACE(ck);
        auto args = whitted(dir + "/out.png", 1, {"--checkpoint", ck});
        args[1] = scene;
        const auto r = test::run_process(args);
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find("error: --checkpoint '" + ck + "' is"), std::string::npos) << r.output;
        EXPECT_EQ(bytes_of(scene), before) << "the scene is intact";
        EXPECT_FALSE(fs::exists(dir + "/out.png"));
    }
    // A resume from something not a regular file is refused too (read through the one input door).
    const auto fifo = test::run_process(whitted(dir + "/out.png", 1, {"--resume", "/dev/zero"}));
    EXPECT_EQ(fifo.exit_code, 1) << fifo.output;
    EXPECT_NE(fifo.output.find("cannot read the checkpoint '/dev/zero': it is not a regular file"), std::string::npos)
        << fifo.output;
}

TEST_F(CliCheckpoint, AdaptiveSamplingWithACheckpointIsRefusedWithAReason) {
    const auto r = test::run_process(whitted(dir + "/out.png", 8, {"--noise-threshold", "0.05", "--checkpoint",
                                                                   dir + "/ck"}));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("do not keep adaptive sampling's state"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/ck"));
}

}  // namespace
}  // namespace whitted
