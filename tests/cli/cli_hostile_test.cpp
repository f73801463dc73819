// The `whitted` command against hostile input and a hurried user (docs/robustness.md): special files,
// signals, a good image never replaced, names as long as a file name may be, the output checked
// before the render, --texture-path not swallowing the scene, a narrow terminal.
#include <sys/stat.h>
#include <signal.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

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

std::string read_all(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void expect_no_temporary_files(const std::string& dir) {
    for (auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << "left behind: " << e.path();
}

// Finding 3: /dev/zero grew ~0.8 GB/s and ignored SIGTERM; a FIFO blocked forever. Both are
// refused at once as what they are (the SIGKILL at 20 s only bounds the test if they are not).
TEST(CliHostile, SpecialFilesAreRefusedNotRead) {
    const std::string dir = test::make_temp_dir();
    const std::string fifo = dir + "/pipe.sc";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    for (const std::string& scene : {std::string("/dev/zero"), fifo}) {
        SCOPED_TRACE(scene);
        auto r = run_process({test::cli_path(), scene, "-o", dir + "/o.png", "-q"}, std::vector<TimedSignal>{{20000, SIGKILL}});
        EXPECT_EQ(r.exit_code, 3) << r.output;
        EXPECT_NE(r.output.find("cannot read scene file: it is not a regular file"), std::string::npos) << r.output;
    }
    auto r = run_process({test::cli_path(), dir, "-o", dir + "/o.png", "-q"});
    EXPECT_NE(r.output.find("it is a directory"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/o.png"));
}

// A scene file over the size limit is refused from its size (a sparse file: nothing to read).
TEST(CliHostile, AHugeSceneFileIsRefusedFromItsSize) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "huge.sc", test::kSimpleScene);
    fs::resize_file(scene, std::uintmax_t(1) << 30);
    auto r = run_process({test::cli_path(), scene, "-o", dir + "/o.png", "-q"}, std::vector<TimedSignal>{{20000, SIGKILL}});
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("it is 1073741824 bytes, more than the limit of 256.0 MiB"), std::string::npos) << r.output;
}

// Findings 7 and 8: SIGTERM (a batch timeout), SIGHUP (a closed terminal), SIGQUIT and Ctrl-C
// during the render of an image that already exists: the old image stays, byte for byte; the
// part rendered goes beside it as NAME.partial.EXT, and the message names it. No temporary file
// is left behind, also when a second signal ends the process in the middle of writing.
TEST(CliHostile, AnInterruptedRenderNeverReplacesTheImage) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "heavy.sc", test::heavy_scene());
    for (int sig : {SIGTERM, SIGHUP, SIGQUIT, SIGINT}) {
        SCOPED_TRACE(strsignal(sig));
        const std::string out = dir + "/good.png", partial = dir + "/good.partial.png";
        write_file(dir, "good.png", "a good image from yesterday");
        fs::remove(partial);
        auto r = run_process({test::cli_path(), scene, "-o", out, "--width", "2000", "--height", "2000",
                              "--max-depth", "12", "-q"},
                             std::vector<TimedSignal>{{1500, sig}, {60000, SIGKILL}});
        EXPECT_EQ(r.exit_code, 130) << r.output;
        EXPECT_EQ(read_all(out), "a good image from yesterday");
        EXPECT_NE(r.output.find("to " + partial + " (" + out + " was not written)"), std::string::npos) << r.output;
        Image img;
        EXPECT_EQ(read_image(partial, img), "");
        EXPECT_EQ(img.width, 2000);
        expect_no_temporary_files(dir);
    }
}

TEST(CliHostile, ASecondSignalInTheWriteLeavesNoTemporaryFile) {
    // SIGHUP used to end the process in the middle of writing a 48 MB PPM, leaving its
    // temporary file. Now the first HUP stops the render, the second the write, cleanly.
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "heavy.sc", test::heavy_scene());
    for (int gap : {0, 40, 120, 300}) {
        SCOPED_TRACE(gap);
        auto r = run_process({test::cli_path(), scene, "-o", dir + "/big.ppm", "--width", "4000", "--height", "4000",
                              "--max-depth", "1", "-q"},
                             std::vector<TimedSignal>{{300, SIGHUP}, {300 + gap, SIGHUP}, {60000, SIGKILL}});
        EXPECT_EQ(r.exit_code, 130) << r.output;
        EXPECT_FALSE(fs::exists(dir + "/big.ppm"));
        expect_no_temporary_files(dir);
    }
}

// Finding 8: a 255-byte output name (the longest a file name may be) works, and so does its
// partial image (whose name is shortened to fit).
TEST(CliHostile, AnOutputNameOf255BytesWorks) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "s.sc", test::kSimpleScene);
    const std::string name = std::string(251, 'n') + ".png";
    ASSERT_EQ(name.size(), 255u);
    auto r = run_process({test::cli_path(), scene, "-o", dir + "/" + name, "--width", "16", "--height", "16", "-q"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Image img;
    EXPECT_EQ(read_image(dir + "/" + name, img), "");
    EXPECT_EQ(img.width, 16);
    // NAME.partial.png would be 263 bytes: NAME loses 8 of them.
    EXPECT_EQ(partial_image_path(dir + "/" + name), dir + "/" + std::string(243, 'n') + ".partial.png");
    const std::string heavy = write_file(dir, "heavy.sc", test::heavy_scene());
    r = run_process({test::cli_path(), heavy, "-o", dir + "/" + name, "--width", "2000", "--height", "2000",
                     "--max-depth", "12", "-q"},
                    std::vector<TimedSignal>{{1500, SIGTERM}, {60000, SIGKILL}});
    EXPECT_EQ(r.exit_code, 130) << r.output;
    EXPECT_EQ(read_image(dir + "/" + std::string(243, 'n') + ".partial.png", img), "") << r.output;
    EXPECT_EQ(img.width, 2000);
    expect_no_temporary_files(dir);
}

// Finding 12: a missing output folder was found only after the render. Now before the load:
// a scene that takes minutes to render fails at once.
TEST(CliHostile, AnUnwritableOutputIsFoundBeforeTheRender) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "heavy.sc", test::heavy_scene());
    const auto start = std::chrono::steady_clock::now();
    auto r = run_process({test::cli_path(), scene, "-o", dir + "/missing/out.png", "--width", "3000", "--height", "3000",
                          "--max-depth", "12", "-q"},
                         std::vector<TimedSignal>{{60000, SIGKILL}});
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("the folder '" + dir + "/missing' does not exist"), std::string::npos) << r.output;
    EXPECT_LT(seconds, 5.0) << "the render (minutes) must not have started";
    // A directory where the image should go.
    fs::create_directory(dir + "/taken.png");
    r = run_process({test::cli_path(), scene, "-o", dir + "/taken.png", "-q"});
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("it is a directory"), std::string::npos) << r.output;
    expect_no_temporary_files(dir);
}

// Finding 11: `--texture-path DIR scene.sc` took the scene for a second folder and rendered the
// bundled showcase with exit 0. One value per --texture-path; repeat the option for more.
TEST(CliHostile, TexturePathDoesNotSwallowTheScene) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "mine.sc", test::kSimpleScene);
    auto r = run_process({test::cli_path(), "-o", dir + "/one.png", "--width", "8", "--height", "8", "-q", "--stats",
                          "--texture-path", dir, scene});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("objects 1, lights 1"), std::string::npos) << "the scene given, not the showcase:\n"
                                                                        << r.output;
    r = run_process({test::cli_path(), "-o", dir + "/two.png", "--width", "8", "--height", "8", "-q", "--stats",
                     "--texture-path", dir, "--texture-path", dir + "/b", scene});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("objects 1, lights 1"), std::string::npos) << r.output;
}

// Finding 13: on a terminal narrower than the progress line, each update wrapped into a new line.
// Every redraw now fits in the width less one column.
TEST(CliHostile, TheProgressLineFitsANarrowTerminal) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "heavy.sc", test::heavy_scene());
    for (int columns : {30, 42, 12}) {
        SCOPED_TRACE(columns);
        auto r = test::run_in_terminal({test::cli_path(), scene, "-o", dir + "/o.png", "--width", "300", "--height",
                                        "300", "--max-depth", "6"},
                                       columns);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        int draws = 0;
        for (std::size_t at = 0; (at = r.output.find("\r\033[K", at)) != std::string::npos; at += 4) {
            const std::size_t end = r.output.find_first_of("\r\n", at + 4);
            const std::string line = r.output.substr(at + 4, end - (at + 4));
            if (line.rfind("wrote", 0) == 0 || line.empty()) continue;
            ++draws;
            EXPECT_LT(int(line.size()), columns) << "'" << line << "'";
            EXPECT_NE(line.find('%'), std::string::npos) << "'" << line << "'";
        }
        EXPECT_GE(draws, 1) << r.output;
    }
}

// under a file size limit (`ulimit -f`) the write died of SIGXFSZ and left its
// temporary file. The signal is ignored: the write fails with "File too large" and is cleaned up.
TEST(CliHostile, AFileSizeLimitFailsTheWriteCleanly) {
    const std::string dir = test::make_temp_dir();
    const std::string scene = write_file(dir, "s.sc", test::kSimpleScene);
    // 100 KiB allowed, 120,015 bytes of PPM to write.
    auto r = run_process({"/bin/sh", "-c", "ulimit -f 100; exec \"$0\" \"$@\"", test::cli_path(), scene, "-o",
                          dir + "/big.ppm", "--width", "200", "--height", "200", "-q"});
    EXPECT_EQ(r.exit_code, 3) << r.output;
    EXPECT_NE(r.output.find("cannot write '" + dir + "/big.ppm': File too large"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/big.ppm"));
    expect_no_temporary_files(dir);
}

}  // namespace
}  // namespace whitted
