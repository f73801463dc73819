// `whitted --untrusted`, --timeout and --max-memory (docs/robustness.md): for files one
// did not write, every limit a clear error.
#include <signal.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli/cli_scenes.h"
#include "film/image_io.h"
#include "support/run_process.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using test::run_process;
using test::TimedSignal;
using test::write_file;

// A 2 × 2 PNG: any texture will do.
void write_texture(const std::string& path) {
    Image img(2, 2);
    ASSERT_EQ(write_image(img, path), "");
}

std::string textured_scene(const std::string& texture) {
    return "camera [ eye 0 0 5 focus 0 0 0 ]\nlight [ position 2 2 5 color 1 1 1 ]\n"
           "mastersubgraph root [ trans [ object sphere [ texture " + texture + " 1 1 ] ] ]\n";
}

// 2^levels spheres through doubling subgraphs, in a few hundred bytes.
std::string doubling_scene(int levels) {
    std::string text = "camera [ eye 0 0 5 focus 0 0 0 ]\nmastersubgraph s0 [ trans [ object sphere [ ] ] ]\n";
    for (int i = 1; i <= levels; ++i) {
        // (std::string("s") += …: GCC 12 warns falsely about "s" + std::string, its bug 105329.)
        const std::string name = i == levels ? std::string("root") : std::string("s") += std::to_string(i);
        const std::string child = std::string("s") += std::to_string(i - 1);
        text += "mastersubgraph " + name + " [ trans [ subgraph " + child + " subgraph " + child + " ] ]\n";
    }
    return text;
}

TEST(CliUntrusted, TexturesOnlyFromTheScenesFolderAndTexturePath) {
    const std::string root = test::make_temp_dir();
    fs::create_directories(root + "/class/alice");
    fs::create_directories(root + "/shared");
    write_texture(root + "/class/alice/mine.png");
    write_texture(root + "/secret.png");
    write_texture(root + "/shared/wood.png");
    fs::create_symlink(root + "/secret.png", root + "/class/alice/link.png");
    auto run = [&](const std::string& texture, std::vector<std::string> extra = {}) {
        const std::string scene = write_file(root + "/class/alice", "s.sc", textured_scene(texture));
        std::vector<std::string> args = {test::cli_path(), "--untrusted", scene, "-o", root + "/out.png",
                                         "--width", "8", "--height", "8", "-q"};
        args.insert(args.end(), extra.begin(), extra.end());
        return run_process(args);
    };
    EXPECT_EQ(run("mine.png").exit_code, 0);
    // Out through `..`, out through a link, an absolute path: each refused, located, saying why.
    auto r = run("../../secret.png");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    // (outside and missing are one message, so that the answer tells nothing of what exists
    // outside.)
    EXPECT_NE(r.output.find("s.sc:3:47: error: texture '../../secret.png': not found inside the scene's folder and "
                            "the --texture-path folders (--untrusted)"),
              std::string::npos)
        << r.output;
    const auto nothing = run("../../nothing.png");
    EXPECT_NE(nothing.output.find("error: texture '../../nothing.png': not found inside the scene's folder and the "
                                  "--texture-path folders (--untrusted)"),
              std::string::npos)
        << "the same message for a file that is not there:\n" << nothing.output;
    r = run("link.png");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("not found inside the scene's folder"), std::string::npos) << r.output;
    r = run(root + "/secret.png");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("an absolute path, refused for a file from others (--untrusted)"), std::string::npos)
        << r.output;
    // A --texture-path folder is allowed, and only the one given.
    EXPECT_EQ(run("wood.png", {"--texture-path", root + "/shared"}).exit_code, 0);
    EXPECT_EQ(run("wood.png").exit_code, 2);
    // Without --untrusted, the scene's parent and the current directory are looked in as before.
    const std::string scene = write_file(root + "/class/alice", "s.sc", textured_scene("../../secret.png"));
    EXPECT_EQ(run_process({test::cli_path(), scene, "-o", root + "/out.png", "--width", "8", "--height", "8", "-q"})
                  .exit_code,
              0);
}

TEST(CliUntrusted, LimitsObjectsImageSizeAndTime) {
    const std::string dir = test::make_temp_dir();
    // 2^21 objects: fine on a trusted run's limits, over --untrusted's million.
    const std::string many = write_file(dir, "many.sc", doubling_scene(21));
    auto r = run_process({test::cli_path(), "--untrusted", many, "-o", dir + "/m.png", "-q"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("expands to 2097152 objects through subgraph instancing, more than the limit of 1000000"),
              std::string::npos)
        << r.output;
    // The image: at most 8192 across or down.
    const std::string simple = write_file(dir, "s.sc", test::kSimpleScene);
    r = run_process({test::cli_path(), "--untrusted", simple, "-o", dir + "/w.png", "--width", "8193", "-q"});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("--untrusted renders images of at most 8192x8192 pixels"), std::string::npos) << r.output;
    // Time: --timeout stops the render, keeps its part beside the output, exits 4.
    const std::string heavy = write_file(dir, "heavy.sc", test::heavy_scene());
    const auto start = std::chrono::steady_clock::now();
    r = run_process({test::cli_path(), "--untrusted", heavy, "-o", dir + "/h.png", "--width", "2000", "--height", "2000",
                     "--max-depth", "12", "--timeout", "1.5", "-q"},
                    std::vector<TimedSignal>{{60000, SIGKILL}});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 4) << r.output;
    EXPECT_NE(r.output.find("the time limit of 1.5 s (--timeout) ran out: wrote the "), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/h.png"));
    EXPECT_TRUE(fs::exists(dir + "/h.partial.png"));
    EXPECT_LT(seconds, 15.0);
}

TEST(CliUntrusted, MaxMemoryRefusesWithTheEstimate) {
    // 2^20 objects at 128 bytes each (128 MiB) and 2^22 - 2 steps of expanding them at 8 bytes
    // (32 MiB; Flatten.RefusesWhatExceedsTheMemoryLimitWithTheEstimate counts them): about
    // 160 MiB, refused under 100M with the estimate.
    const std::string dir = test::make_temp_dir();
    const std::string many = write_file(dir, "many.sc", doubling_scene(20));
    auto r = run_process({test::cli_path(), many, "-o", dir + "/m.ppm", "--width", "8", "--height", "8",
                          "--max-memory", "100M", "-q"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("needs about 160.0 MiB of memory (1048576 objects"), std::string::npos) << r.output;
    // The image counts too: 20000 × 20000 pixels × (16 bytes of film + 3 of 8-bit image) is
    // 7.6e9 bytes, 7.1 GiB, over 1G before anything is read.
    r = run_process({test::cli_path(), many, "-o", dir + "/m.ppm", "--width", "20000", "--height", "20000",
                     "--max-memory", "1G", "-q"});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("a 20000x20000 image needs about 7.1 GiB of memory"), std::string::npos) << r.output;
    EXPECT_EQ(run_process({test::cli_path(), many, "--max-memory", "lots"}).exit_code, 1);
}

}  // namespace
}  // namespace whitted
