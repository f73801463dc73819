// The command line and scene-format.md §9.4: `--time T` for velocity / angularrate, the dialect
// named by --stats, every error of a file at once, and a binary file given as a scene.
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>

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

// Renders `scene` (written to dir/name) to dir/name.ppm with `extra` options; returns the bytes.
std::string render(const std::string& dir, const std::string& name, const std::string& scene,
                   std::vector<std::string> extra = {}) {
    const std::string path = write_file(dir, name, scene), out = dir + "/" + name + ".ppm";
    std::vector<std::string> argv = {test::cli_path(), path, "-o", out, "--width", "48", "--height", "36", "-q"};
    argv.insert(argv.end(), extra.begin(), extra.end());
    const auto r = run_process(argv);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return bytes_of(out);
}

TEST(CliDialects, TimeMovesVelocityAndAngularRate) {
    const std::string dir = test::make_temp_dir();
    const std::string animated = scene_with("velocity 0.5 0.25 0 angularrate 0 1 1 40");
    const std::string still = render(dir, "still.sc", scene_with(""));
    const std::string moved = render(dir, "moved.sc", scene_with("translate 0.5 0.25 0 rotate 0 1 1 40"));
    ASSERT_NE(still, moved);  // the comparison below can tell them apart
    EXPECT_EQ(render(dir, "a0.sc", animated), still);                         // t = 0 by default
    EXPECT_EQ(render(dir, "a1.sc", animated, {"--time", "1"}), moved);      // t = 1
    EXPECT_EQ(run_process({test::cli_path(), dir + "/a1.sc", "--time", "nan", "-q"}).exit_code, 1);
}

TEST(CliDialects, StatsNameTheDialect) {
    const std::string dir = test::make_temp_dir();
    const std::string brown = write_file(dir, "b.sc", "light [ number 0 position 0 3 3 ]\ntrans [ object sphere [ ] ]\n");
    auto r = run_process({test::cli_path(), brown, "-o", dir + "/b.png", "--width", "8", "--height", "8", "-q", "--stats"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("dialect Brown/Tufts"), std::string::npos) << r.output;
    const std::string labs = write_file(dir, "l.sc", scene_with(""));
    r = run_process({test::cli_path(), labs, "-o", dir + "/l.png", "--width", "8", "--height", "8", "-q", "--stats"});
    EXPECT_NE(r.output.find("dialect SceneView/Ray labs"), std::string::npos) << r.output;
}

TEST(CliDialects, EveryErrorAtOnceAndBinaryFiles) {
    const std::string dir = test::make_temp_dir();
    const std::string bad = write_file(dir, "bad.sc",
                                       "camera [ eye 0 0 x ]\nmastersubgraph root [ trans [ object spere [ ] ] ]\n"
                                       "light [ colr 1 1 1 ]\n");
    auto r = run_process({test::cli_path(), bad, "-o", dir + "/bad.png", "-q"});
    EXPECT_EQ(r.exit_code, 2);
    const auto a = r.output.find(bad + ":1:18: error:"), b = r.output.find(bad + ":2:38: error: unknown object type 'spere' (did you mean 'sphere'?)"),
               c = r.output.find(bad + ":3:9: error: unknown keyword 'colr' in light block (did you mean 'color'?)");
    ASSERT_NE(a, std::string::npos) << r.output;
    ASSERT_NE(b, std::string::npos) << r.output;
    ASSERT_NE(c, std::string::npos) << r.output;
    EXPECT_TRUE(a < b && b < c) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/bad.png"));

    const std::string png = write_file(dir, "picture.sc", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16));
    r = run_process({test::cli_path(), png, "-o", dir + "/p.png", "-q"});
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find(png + ":1:1: error: this is not a scene file (it looks like a PNG image)"), std::string::npos)
        << r.output;
}

}  // namespace
}  // namespace whitted
