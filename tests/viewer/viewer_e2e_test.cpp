// whitted-view end to end: no display, and a real X server (Xvfb) with a real screen grab (xwd)
// compared with the command-line renderer's image of the same scene and size.
#ifdef WHITTED_VIEWER_PATH
#include <fcntl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/needs.h"
#include "support/run_process.h"
#include "inspect/inspect_scene.h"  // [inspector]

namespace whitted {
namespace {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using test::run_process;

std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && access((dir + "/" + name).c_str(), X_OK) == 0) return dir + "/" + name;
    return "";
}

// "" when every tool is on the PATH, else which are missing and where they come from.
std::string missing_tools(std::initializer_list<const char*> tools) {
    std::string missing;
    for (const char* tool : tools)
        if (find_on_path(tool).empty()) missing += std::string(missing.empty() ? "" : ", ") + tool;
    return missing.empty() ? "" : "the screen test needs " + missing +
                                      " (Debian xdotool, x11-apps, imagemagick, tesseract-ocr: scripts/install-deps.sh --viewer-test)";
}

// A child process with its output in a log file; killed (SIGTERM, then SIGKILL) when destroyed.
struct Child {
    pid_t pid = -1;
    std::string log;
    Child(const std::vector<std::string>& argv, const std::string& log_path,
          const std::vector<std::pair<std::string, std::string>>& env = {}, int pass_fd = -1)
        : log(log_path) {
        pid = fork();
        if (pid == 0) {
            int fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
            if (fd >= 0) {
                dup2(fd, STDOUT_FILENO);
                dup2(fd, STDERR_FILENO);
            }
            // The viewer remembers things in $HOME: each test gets its own (its log's folder)
            // unless it sets one, so runs never see each other's (or the user's) preferences.
            setenv("HOME", fs::path(log_path).parent_path().c_str(), 1);
            for (const auto& [k, v] : env) setenv(k.c_str(), v.c_str(), 1);
            std::vector<char*> args;
            for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
            args.push_back(nullptr);
            (void)pass_fd;  // inherited as is
            execv(args[0], args.data());
            _exit(127);
        }
    }
    // Waits up to `timeout` for the child to exit; returns its exit code, or -1 if it is still running.
    int wait_exit(std::chrono::milliseconds timeout) {
        const auto deadline = std::chrono::steady_clock::now() + timeout;
        while (pid > 0) {
            int status = 0;
            pid_t r = waitpid(pid, &status, WNOHANG);
            if (r == pid) {
                pid = -1;
                return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
            }
            if (std::chrono::steady_clock::now() >= deadline) return -1;
            std::this_thread::sleep_for(20ms);
        }
        return -1;
    }
    // Sends `sig` if it still runs (never to pid -1, which would mean every process).
    void signal(int sig) const {
        if (pid > 0) kill(pid, sig);
    }
    std::string output() const {
        std::ifstream in(log);
        return {std::istreambuf_iterator<char>(in), {}};
    }
    ~Child() {
        if (pid <= 0) return;
        kill(pid, SIGTERM);
        if (wait_exit(3s) == -1 && pid > 0) {
            kill(pid, SIGKILL);
            waitpid(pid, nullptr, 0);
        }
    }
};

// Whether an X server accepts connections on display `number`'s local socket.
bool accepts_connections(const std::string& number) {
    const std::string path = "/tmp/.X11-unix/X" + number;
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    if (path.size() >= sizeof addr.sun_path) return false;
    std::copy(path.begin(), path.end(), addr.sun_path);
    const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
    if (fd < 0) return false;
    const bool ok = connect(fd, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) == 0;
    close(fd);
    return ok;
}

// An X server of our own on a free display number (Xvfb picks it: -displayfd).
class Xvfb {
public:
    // Tries a few times: with tests running in parallel, a display number just given up by
    // another test's server can be announced while its socket is being taken away (seen in CI:
    // the viewer could not open the display it was given). A server that does not accept
    // connections on its socket is replaced by a new one.
    bool start(const std::string& dir, std::string& why) {
        for (int attempt = 0; attempt < 3; ++attempt) {
            if (!start_once(dir, why)) return false;
            for (auto deadline = std::chrono::steady_clock::now() + 2s; std::chrono::steady_clock::now() < deadline;
                 std::this_thread::sleep_for(20ms))
                if (accepts_connections(display_.substr(1))) return true;
            server_.reset();
        }
        why = "Xvfb announced displays that accepted no connection, three times";
        return false;
    }
    const std::string& display() const { return display_; }

private:
    bool start_once(const std::string& dir, std::string& why) {
        std::string xvfb = find_on_path("Xvfb");
        if (xvfb.empty()) {
            why = "Xvfb is not installed (Debian package xvfb; scripts/install-deps.sh --viewer-test installs it)";
            return false;
        }
        int fds[2];
        if (pipe(fds) != 0) return why = "pipe failed", false;
        server_ = std::make_unique<Child>(
            std::vector<std::string>{xvfb, "-displayfd", std::to_string(fds[1]), "-screen", "0", "1280x1024x24",
                                     "-nolisten", "tcp"},
            dir + "/xvfb.log", std::vector<std::pair<std::string, std::string>>{}, fds[1]);
        close(fds[1]);
        std::string number;
        char c;
        // Xvfb writes the display number and a newline once it accepts connections.
        fcntl(fds[0], F_SETFL, O_NONBLOCK);
        const auto deadline = std::chrono::steady_clock::now() + 20s;
        while (std::chrono::steady_clock::now() < deadline) {
            ssize_t n = read(fds[0], &c, 1);
            if (n == 1) {
                if (c == '\n') break;
                number += c;
            } else if (n == 0) {
                break;
            } else {
                std::this_thread::sleep_for(10ms);
            }
        }
        close(fds[0]);
        if (number.empty()) {
            why = "Xvfb did not start: " + server_->output();
            return false;
        }
        display_ = ":" + number;
        return true;
    }

    std::unique_ptr<Child> server_;
    std::string display_;
};

// The viewer links FLTK, Xlib and (for its file chooser) GTK, whose one-time allocations
// LeakSanitizer reports at exit; leaks are checked in the project's own code by the other tests.
std::string asan_options_for_viewer() {
    const char* o = std::getenv("ASAN_OPTIONS");
    return std::string(o ? o : "") + (o && *o ? ":" : "") + "detect_leaks=0";
}

const char* kScene = R"(camera [ eye 0 1 6 focus 0 0 0 angle 40 ]
light [ position 3 4 5 color 1 1 1 ]
light [ position -4 2 3 color 0.4 0.4 0.6 ]
background [ color 0.1 0.15 0.3 ]
mastersubgraph root [
  trans [ translate -1.2 0 0  object sphere [ diffuse 0.9 0.2 0.1 specular 0.5 0.5 0.5 shine 30 reflect 0.3 0.3 0.3 ] ]
  trans [ translate 1.2 0 0 rotate 0 1 0 30 object cube [ diffuse 0.2 0.7 0.3 ] ]
  trans [ translate 0 -1 0 scale 8 0.1 8 object cube [ diffuse 0.6 0.6 0.6 reflect 0.4 0.4 0.4 ] ]
  trans [ translate 0 1.2 -1 object cone [ diffuse 0.9 0.8 0.2 ] ]
]
)";

class ViewerE2E : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = test::make_temp_dir();
        scene_ = dir_ + "/scene.sc";
        std::ofstream(scene_) << kScene;
    }
    std::string dir_, scene_;
};

TEST(ViewerNoDisplay, ExitsWithAClearErrorWhenDisplayIsUnset) {
    auto r = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH, "--width", "10", "--height", "10"});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("whitted-view: error: no display"), std::string::npos) << r.output;
}

TEST(ViewerNoDisplay, ExitsWithAClearErrorWhenDisplayIsWrong) {
    auto r = run_process({"/usr/bin/env", "DISPLAY=:4321", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("whitted-view: error: cannot open display ':4321'"), std::string::npos) << r.output;
}

TEST(ViewerNoDisplay, HelpAndBadUsageNeedNoDisplay) {
    auto help = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH, "--help"});
    EXPECT_EQ(help.exit_code, 0);
    EXPECT_NE(help.output.find("--screenshot"), std::string::npos);
    EXPECT_EQ(run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(), WHITTED_VIEWER_PATH, "--mode", "fancy"}).exit_code, 1);
}

// Issue 15, finding 14: --screenshot / --exit-when-done with no scene waited forever for a render
// that never came; now a usage error at once (before the display is needed).
TEST(ViewerNoDisplay, AutomatedRunsNeedAScene) {
    for (const char* flag : {"--exit-when-done", "--screenshot=x.png"}) {
        auto r = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(),
                              WHITTED_VIEWER_PATH, flag},
                             std::vector<test::TimedSignal>{{20000, SIGKILL}});
        EXPECT_EQ(r.exit_code, 1) << r.output;
        EXPECT_NE(r.output.find("--screenshot and --exit-when-done need a scene file"), std::string::npos) << r.output;
    }
    // Finding 11: the scene after a --texture-path is the scene, not a second folder (it got as far
    // as looking for a display).
    auto r = run_process({"/usr/bin/env", "-u", "DISPLAY", "ASAN_OPTIONS=" + asan_options_for_viewer(),
                          WHITTED_VIEWER_PATH, "--exit-when-done", "--texture-path", "/tmp", "scene.sc"});
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("whitted-view: error: no display"), std::string::npos) << r.output;
}

// What the viewer writes to its --ready-file (root-window coordinates).
struct Box {
    int x = 0, y = 0, w = 0, h = 0;
    bool shown = true;
    int right() const { return x + w; }
};
struct Ready {
    std::uint64_t job = 0;  // the render reported
    bool reused = false;    // it reused the scene loaded before (the file had not changed)
    int watch_ticks = 0;    // times its once-a-second watch timer has fired
    std::string state;
    Box window, area, image;  // the area is where the image is shown
    std::vector<std::pair<std::string, Box>> tools;  // left to right as made; x and w include the label
    std::map<std::string, Box> fields;               // of the status bar
    std::map<std::string, int> needs;                // the width each field's text takes
    std::map<std::string, std::string> labels;       // each field's label, as given to FLTK
    std::vector<std::string> panel;                  // the messages panel's lines
    std::string camera;                              // "file camera [ ... ]" or "moved camera [ ... ]"
    bool dimmed = false;                             // the image is shown dimmed under an error banner
    std::vector<std::string> recent;                 // File > Open recent, most recent first
    double exposure = 0;                             // of the image view, in stops
};

Ready read_ready(const std::string& path) {
    Ready r;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        std::istringstream ls(line);
        std::string key, name, word;
        Box b;
        ls >> key;
        if (key == "job") {
            ls >> r.job >> word;
            r.reused = word == "reused";
        } else if (key == "state") ls >> r.state;
        else if (key == "watch_ticks") ls >> r.watch_ticks;
        else if (key == "window") ls >> r.window.x >> r.window.y >> r.window.w >> r.window.h;
        else if (key == "area") ls >> r.area.x >> r.area.y >> r.area.w >> r.area.h;
        else if (key == "image") ls >> r.image.x >> r.image.y >> r.image.w >> r.image.h;
        else if (key == "tool" && ls >> name >> b.x >> b.y >> b.w >> b.h >> word) {
            b.shown = word == "shown";
            r.tools.emplace_back(name, b);
        } else if (key == "field" && ls >> name >> b.x >> b.y >> b.w >> b.h >> word >> r.needs[name]) {
            r.fields[name] = b;
            std::string label;  // after "label" and one space
            if (ls >> word && std::getline(ls, label) && !label.empty()) r.labels[name] = label.substr(1);
        } else if (key == "panel") {
            r.panel.push_back(line.substr(std::min(line.size(), key.size() + 1)));
        } else if (key == "camera") {
            r.camera = line.substr(std::min(line.size(), key.size() + 1));
        } else if (key == "dimmed") {
            ls >> word;
            r.dimmed = word == "1";
        } else if (key == "exposure") {
            ls >> r.exposure;
        } else if (key == "recent") {
            r.recent.push_back(line.substr(std::min(line.size(), key.size() + 1)));
        }
    }
    return r;
}

// The text FLTK draws for a label: "@@" is a literal '@'; any other '@' starts a symbol (shown
// here as "<symbol>"), and the name would not show as written.
std::string drawn_text(const std::string& label) {
    std::string out;
    for (std::size_t i = 0; i < label.size(); ++i) {
        if (label[i] != '@') out += label[i];
        else if (i + 1 < label.size() && label[i + 1] == '@') out += label[i++];
        else return out + "<symbol>";
    }
    return out;
}

// Where `part` appears in `whole` (every pixel within 1 level), or {-1, -1}.
std::pair<int, int> find_subimage(const Image& whole, const Image& part, std::pair<int, int> hint) {
    auto matches_at = [&](int ox, int oy) {
        for (int y = 0; y < part.height; ++y)
            for (int x = 0; x < part.width; ++x) {
                glm::ivec3 a(whole.at(ox + x, oy + y)), b(part.at(x, y));
                glm::ivec3 d = glm::abs(a - b);
                if (d.x > 1 || d.y > 1 || d.z > 1) return false;
            }
        return true;
    };
    if (hint.first >= 0 && hint.first + part.width <= whole.width && hint.second >= 0 &&
        hint.second + part.height <= whole.height && matches_at(hint.first, hint.second))
        return hint;
    for (int oy = 0; oy + part.height <= whole.height; ++oy)
        for (int ox = 0; ox + part.width <= whole.width; ++ox)
            if (matches_at(ox, oy)) return {ox, oy};
    return {-1, -1};
}

TEST_F(ViewerE2E, TheWindowShowsTheSameImageAsTheCommandLineRenderer) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xwd", "convert"}));
    const std::string xwd = find_on_path("xwd"), convert = find_on_path("convert");

    const int W = 320, H = 240;
    auto cli = run_process({test::cli_path(), scene_, "-o", dir_ + "/cli.png", "--width", std::to_string(W),
                            "--height", std::to_string(H), "-q"});
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    Image expected;
    ASSERT_EQ(read_image(dir_ + "/cli.png", expected), "");

    // The viewer renders on start and says when the image is on screen.
    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", std::to_string(W), "--height", std::to_string(H),
                  "--threads", "2", "--ready-file", ready},
                 dir_ + "/viewer.log", {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    const auto deadline = std::chrono::steady_clock::now() + 120s;
    while (!fs::exists(ready) && std::chrono::steady_clock::now() < deadline) {
        ASSERT_EQ(viewer.wait_exit(0ms), -1) << "the viewer exited early:\n" << viewer.output();
        std::this_thread::sleep_for(50ms);
    }
    ASSERT_TRUE(fs::exists(ready)) << "the render did not finish in time:\n" << viewer.output();
    const Ready r = read_ready(ready);
    EXPECT_EQ(r.state, "finished");
    const int wx = r.window.x, ww = r.window.w, ix = r.image.x, iy = r.image.y;
    EXPECT_EQ(r.image.w, W);
    EXPECT_EQ(r.image.h, H);

    // A real screen grab of the whole X screen.
    auto grab = run_process({"/bin/sh", "-c",
                             "'" + xwd + "' -root -silent -display " + x.display() + " | '" + convert + "' xwd:- '" +
                                 dir_ + "/screen.png'"});
    ASSERT_EQ(grab.exit_code, 0) << grab.output;
    Image screen;
    ASSERT_EQ(read_image(dir_ + "/screen.png", screen), "");
    ASSERT_EQ(screen.width, 1280);

    auto [fx, fy] = find_subimage(screen, expected, {ix, iy});
    ASSERT_GE(fx, 0) << "the rendered image was not found on the screen (see " << dir_ << "/screen.png)";
    EXPECT_EQ(fx, ix) << "the viewer reported the image at another place";
    EXPECT_EQ(fy, iy);
    // The image lies inside the window.
    EXPECT_GE(fx, wx);
    EXPECT_LE(fx + W, wx + ww);

    // Ctrl-C / SIGTERM closes the window cleanly.
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

TEST_F(ViewerE2E, ScreenshotFlagSavesTheDisplayedPixels) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    auto cli = run_process({test::cli_path(), scene_, "-o", dir_ + "/cli.png", "--width", "200", "--height", "150",
                            "--mode", "normals", "-q"});
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", "200", "--height", "150", "--mode", "normals",
                  "--screenshot", dir_ + "/shot.png"},
                 dir_ + "/viewer.log", {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    ASSERT_EQ(viewer.wait_exit(120s), 0) << viewer.output();
    Image expected, shot;
    ASSERT_EQ(read_image(dir_ + "/cli.png", expected), "");
    ASSERT_EQ(read_image(dir_ + "/shot.png", shot), "");
    ASSERT_EQ(shot.width, 200);
    ASSERT_EQ(shot.height, 150);
    EXPECT_EQ(find_subimage(shot, expected, {0, 0}), std::make_pair(0, 0));
}

TEST_F(ViewerE2E, ASceneWithErrorsIsReportedNotACrash) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    std::ofstream(scene_) << "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n";
    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--exit-when-done", "--ready-file", ready}, dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    ASSERT_EQ(viewer.wait_exit(60s), 2) << viewer.output();
    const std::string output = viewer.output();
    EXPECT_NE(output.find(scene_ + ":2:"), std::string::npos) << output;

    // The window showed the error, as FILE:LINE:COL: error: ..., in the messages panel and the status bar.
    Ready r = read_ready(ready);
    EXPECT_EQ(r.state, "failed");
    ASSERT_EQ(r.panel.size(), 1u) << output;
    // In the window, the path is relative to the scene's folder; on stderr, as given.
    const std::string& error = r.panel[0];
    ASSERT_EQ(error.rfind("scene.sc:2:", 0), 0u) << error;
    // After "FILE:2:": the column's digits, then the message.
    const std::string rest = error.substr(std::string("scene.sc:2:").size());
    const std::size_t digits = rest.find_first_not_of("0123456789");
    EXPECT_GT(digits, 0u) << error;
    EXPECT_EQ(rest.substr(digits).rfind(": error: unknown object type 'blob'", 0), 0u) << error;
    EXPECT_NE(output.find(dir_ + "/" + error + "\n"), std::string::npos) << "the panel and stderr differ:\n" << output;
    EXPECT_EQ(drawn_text(r.labels["message"]), " " + error);
    EXPECT_EQ(drawn_text(r.labels["progress"]), " the scene has errors");
}

// Waits until the viewer has written a ready file that `good` accepts; the file is read whole
// (the viewer writes it under another name and renames it).
bool wait_for_ready(Child& viewer, const std::string& path, Ready& out, const std::function<bool(const Ready&)>& good,
                    std::chrono::seconds timeout = 120s) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (std::chrono::steady_clock::now() < deadline) {
        if (viewer.wait_exit(0ms) != -1) return false;
        if (fs::exists(path) && good(out = read_ready(path))) return true;
        std::this_thread::sleep_for(50ms);
    }
    return false;
}

// A real grab of the whole X screen.
Image grab_screen(const std::string& display, const std::string& png) {
    auto grab = run_process({"/bin/sh", "-c",
                             "'" + find_on_path("xwd") + "' -root -silent -display " + display + " | '" +
                                 find_on_path("convert") + "' xwd:- '" + png + "'"});
    Image screen;
    EXPECT_EQ(grab.exit_code, 0) << grab.output;
    if (grab.exit_code == 0) {
        EXPECT_EQ(read_image(png, screen), "");
    }
    return screen;
}

// The text the screen grab `png` shows inside `box`, read by OCR (tesseract, on the region scaled
// up 4× in grey: FLTK's small UI font is then read reliably). `lines`: one line, or a block.
// For checks of what the user reads, where the ready file only says what the viewer meant to show.
enum class Lines { One, Block };
std::string screen_text(const std::string& png, const Box& box, Lines lines) {
    const std::string region = png + "." + std::to_string(box.x) + "_" + std::to_string(box.y) + ".png";
    auto r = run_process({"/bin/sh", "-c",
                          "'" + find_on_path("convert") + "' '" + png + "' -crop " + std::to_string(box.w) + "x" +
                              std::to_string(box.h) + "+" + std::to_string(box.x) + "+" + std::to_string(box.y) +
                              " +repage -resize 400% -colorspace Gray '" + region + "' && '" +
                              find_on_path("tesseract") + "' '" + region + "' - --psm " +
                              (lines == Lines::One ? "7" : "6") + " 2>/dev/null"});
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return r.output;
}

// `text` without quotation marks, straight or curly (OCR reads ' as ‘ or ’, or doubles it):
// compare what OCR read with what was meant with both unquoted.
std::string unquoted(std::string text) {
    for (const char* q : {"\u2018", "\u2019", "\u201C", "\u201D", "'", "\""})
        for (std::size_t i; (i = text.find(q)) != std::string::npos;) text.erase(i, std::strlen(q));
    return text;
}
// Whether OCR output `read` contains `meant`, quotation marks aside.
bool reads(const std::string& read, const std::string& meant) {
    return unquoted(read).find(unquoted(meant)) != std::string::npos;
}

// xdotool on our X server; returns the first line of its output (e.g. a window id).
std::string xdotool(const std::string& display, const std::string& args) {
    auto r = run_process({"/bin/sh", "-c", "DISPLAY=" + display + " '" + find_on_path("xdotool") + "' " + args});
    EXPECT_EQ(r.exit_code, 0) << "xdotool " << args << ":\n" << r.output;
    return r.output.substr(0, r.output.find('\n'));
}

// The error of ASceneWithErrorsIsReportedNotACrash as the user reads it on the screen.
TEST_F(ViewerE2E, ASceneWithErrorsShowsTheErrorOnTheScreen) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xwd", "convert", "tesseract"}));
    std::ofstream(scene_) << "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n";
    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--ready-file", ready}, dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "failed"; }, 60s))
        << viewer.output();
    const std::string png = dir_ + "/screen.png";
    grab_screen(x.display(), png);
    // In the status bar: the error (after the scene's folder, which OCR need not spell) and the
    // state; in the messages panel: the error.
    const std::string message = screen_text(png, r.fields["message"], Lines::One);
    EXPECT_TRUE(reads(message, "scene.sc:2:")) << message << " (see " << png << ")";
    EXPECT_TRUE(reads(message, "error: unknown object type 'blob'")) << message << " (see " << png << ")";
    const std::string progress = screen_text(png, r.fields["progress"], Lines::One);
    EXPECT_TRUE(reads(progress, "the scene has errors")) << progress << " (see " << png << ")";
    const Box panel{r.window.x, r.area.y + r.area.h, r.window.w, r.fields["scene"].y - (r.area.y + r.area.h)};
    const std::string panel_text = screen_text(png, panel, Lines::Block);
    EXPECT_TRUE(reads(panel_text, "scene.sc:2:")) << panel_text << " (see " << png << ")";
    EXPECT_TRUE(reads(panel_text, "error: unknown object type 'blob'")) << panel_text << " (see " << png << ")";
    viewer.signal(SIGTERM);
    EXPECT_NE(viewer.wait_exit(10s), -1) << viewer.output();
}

bool overlap(const Box& a, const Box& b) {
    return a.x < b.right() && b.x < a.right() && a.y < b.y + b.h && b.y < a.y + a.h;
}

TEST_F(ViewerE2E, TheToolBarKeepsItsLayoutWhenTheWindowIsResized) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool", "xwd", "convert"}));

    const std::string ready = dir_ + "/ready.txt";
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", "160", "--height", "120", "--threads", "2", "--ready-file",
                  ready},
                 dir_ + "/viewer.log", {{"DISPLAY", x.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready made;
    ASSERT_TRUE(wait_for_ready(viewer, ready, made, [](const Ready&) { return true; })) << viewer.output();
    ASSERT_EQ(made.window.w, 1000);  // the default size, wide enough for every tool
    ASSERT_EQ(made.tools.size(), 10u);  // render, stop, width, height, fit, depth, mode, AA, SPP, threads
    for (const auto& [name, b] : made.tools) {
        EXPECT_TRUE(b.shown) << name;
        EXPECT_EQ(b.h, 24) << name;
    }
    const Image made_screen = grab_screen(x.display(), dir_ + "/made.png");
    const std::string window = xdotool(x.display(), "search --name whitted-view");
    ASSERT_FALSE(window.empty());

    for (auto [W, H] : {std::pair{600, 400}, std::pair{1270, 950}}) {
        SCOPED_TRACE(std::to_string(W) + "x" + std::to_string(H));
        fs::remove(ready);
        xdotool(x.display(), "windowsize " + window + " " + std::to_string(W) + " " + std::to_string(H));
        Ready r;
        ASSERT_TRUE(wait_for_ready(viewer, ready, r, [&](const Ready& n) { return n.window.w == W && n.window.h == H; },
                                   20s))
            << "no ready file for the new size:\n" << viewer.output();
        EXPECT_EQ(r.job, made.job) << "without Fit window a resize renders nothing";

        // Every tool keeps the size and place it was made with, relative to the window; those
        // that would stick out are hidden, and no two that are shown overlap.
        ASSERT_EQ(r.tools.size(), made.tools.size());
        int shown_right = 0;
        for (std::size_t i = 0; i < r.tools.size(); ++i) {
            const auto& [name, b] = r.tools[i];
            const Box& m = made.tools[i].second;
            EXPECT_EQ(b.x - r.window.x, m.x - made.window.x) << name;
            EXPECT_EQ(b.y - r.window.y, m.y - made.window.y) << name;
            EXPECT_EQ(b.w, m.w) << name;
            EXPECT_EQ(b.h, m.h) << name;
            if (!b.shown) {
                EXPECT_GT(b.right(), r.window.right() - 10) << name << " is hidden though it fits";
                continue;
            }
            EXPECT_LE(b.right(), r.window.right()) << name;
            EXPECT_TRUE(r.tools[i > 0 ? i - 1 : 0].second.shown) << name << " is shown after a hidden one";
            for (std::size_t j = 0; j < i; ++j)
                EXPECT_FALSE(overlap(b, r.tools[j].second)) << name << " overlaps " << r.tools[j].first;
            shown_right = std::max(shown_right, b.right() - r.window.x);
        }
        EXPECT_TRUE(r.tools[0].second.shown && r.tools[1].second.shown) << "Render and Stop always fit";

        // The tool bar looks as it did at the start, as far as it is shown.
        const Image screen = grab_screen(x.display(), dir_ + "/resized.png");
        const int top = made.tools[0].second.y - made.window.y - 2, rows = made.tools[0].second.h + 4;
        int differ = 0;
        for (int yy = top; yy < top + rows; ++yy)
            for (int xx = 0; xx < shown_right; ++xx)
                differ += made_screen.at(made.window.x + xx, made.window.y + yy) !=
                          screen.at(r.window.x + xx, r.window.y + yy);
        EXPECT_EQ(differ, 0) << "the tool bar changed (see " << dir_ << "/made.png and resized.png)";

        // The status bar's fields fill its row left to right; the progress text fits its field.
        const Box &scene = r.fields["scene"], &progress = r.fields["progress"], &message = r.fields["message"];
        EXPECT_EQ(scene.x, r.window.x);
        EXPECT_EQ(progress.x, scene.right());
        EXPECT_EQ(message.x, progress.right());
        EXPECT_EQ(message.right(), r.window.right());
        EXPECT_EQ(scene.y + scene.h, r.window.y + r.window.h);
        EXPECT_GE(progress.w, r.needs["progress"]);
    }
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

// File > Save image as proposes the scene's folder and name; a name it cannot write is an error
// in the status bar and in the messages panel.
TEST_F(ViewerE2E, SaveImageAsStartsInTheScenesFolder) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    fs::create_directory(dir_ + "/scenes");
    const std::string scene = dir_ + "/scenes/room.sc", ready = dir_ + "/ready.txt";
    fs::copy_file(scene_, scene);
    // (HOME: the file chooser keeps a list of recent files there.)
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", "160", "--height", "120", "--threads", "2", "--ready-file",
                  ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready&) { return true; })) << viewer.output();
    ASSERT_EQ(r.state, "finished");
    const std::string window = xdotool(x.display(), "search --name whitted-view");

    // Opens the dialog with Ctrl+S and types into it.
    auto save_as = [&](const std::vector<std::string>& keys) {
        xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
        const std::string dialog = xdotool(x.display(), "search --sync --name 'Save image as'");
        xdotool(x.display(), "windowfocus --sync " + dialog);
        for (const std::string& k : keys) xdotool(x.display(), k);
    };
    save_as({"key Return"});
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (!fs::exists(dir_ + "/scenes/room.png") && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(50ms);
    Image saved;
    ASSERT_EQ(read_image(dir_ + "/scenes/room.png", saved), "") << viewer.output();
    EXPECT_EQ(saved.width, 160);

    // The suggested name is selected without its folder: typing replaces it.
    save_as({"type x.gif", "key Return"});
    const std::string error = "error: cannot write '" + dir_ + "/scenes/x.gif': use .png, .bmp, .ppm, .jpg or .jpeg";
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return !n.panel.empty(); }, 20s))
        << viewer.output();
    EXPECT_EQ(r.panel, std::vector<std::string>{error});

    // A name typed alone into the emptied field is in the folder shown, not the working directory
    // (FLTK 1.3.8 resolved it there and moved the cursor to the start, garbling the next keys).
    // (Shift+Home selects the whole field: Ctrl+A is the start of the line in FLTK.)
    save_as({"key End", "key shift+Home", "type y.png", "key Return"});
    const auto saved_y = [](const Ready& n) {
        return n.labels.count("message") && n.labels.at("message").find("y.png") != std::string::npos;
    };
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, saved_y, 20s))
        << viewer.output();
    EXPECT_EQ(drawn_text(r.labels["message"]), " saved " + dir_ + "/scenes/y.png");
    ASSERT_EQ(read_image(dir_ + "/scenes/y.png", saved), "") << viewer.output();
    EXPECT_EQ(saved.width, 160);

    // Saving over a file asks first; Escape keeps the file as it was.
    const auto written = fs::last_write_time(dir_ + "/scenes/room.png");
    save_as({"key Return"});
    const std::string ask = xdotool(x.display(), "search --sync --name '^Save$'");
    ASSERT_FALSE(ask.empty()) << viewer.output();
    xdotool(x.display(), "windowfocus --sync " + ask + " key Escape");
    const auto closed = std::chrono::steady_clock::now() + 10s;
    while (run_process({"/bin/sh", "-c", "DISPLAY=" + x.display() + " xdotool search --name '^Save'"}).exit_code == 0 &&
           std::chrono::steady_clock::now() < closed)
        std::this_thread::sleep_for(50ms);
    EXPECT_EQ(fs::last_write_time(dir_ + "/scenes/room.png"), written);
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

// The window goes on showing the render while the Save dialog is open (issue 15, item 14): the
// ready file, written from the window's own timer when the render ends, appears with the dialog
// still open. (GTK's chooser ran an event loop of its own, in which no timer of ours fired.)
TEST_F(ViewerE2E, TheWindowKeepsUpdatingWhileTheSaveDialogIsOpen) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    const std::string ready = dir_ + "/ready.txt", scene = dir_ + "/showcase.sc";
    fs::copy_file(std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc", scene);
    // Long enough (16 samples a pixel of the showcase) for the dialog to open well before the end.
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", "320", "--height", "240", "--spp", "16", "--threads", "2",
                  "--ready-file", ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    const std::string window = xdotool(x.display(), "search --sync --name whitted-view");
    ASSERT_FALSE(window.empty()) << viewer.output();
    xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
    const std::string dialog = xdotool(x.display(), "search --sync --name 'Save image as'");
    ASSERT_FALSE(dialog.empty()) << viewer.output();
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "finished"; }, 120s))
        << "the render's end was not seen while the dialog was open:\n" << viewer.output();
    EXPECT_FALSE(xdotool(x.display(), "search --name 'Save image as'").empty());  // still open

    // Saved now, it is the finished image, as whitted renders it, and no word of it being partial.
    xdotool(x.display(), "windowfocus --sync " + dialog + " key Return");
    const std::string png = dir_ + "/showcase.png";
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) {
        return n.labels.count("message") && n.labels.at("message").find("saved") != std::string::npos;
    }, 20s))
        << viewer.output();
    EXPECT_EQ(drawn_text(r.labels["message"]), " saved " + png);
    Image saved, expected;
    ASSERT_EQ(read_image(png, saved), "") << viewer.output();
    auto cli = run_process({test::cli_path(), scene, "-o", dir_ + "/cli.png", "--width", "320", "--height", "240",
                            "--spp", "16", "-q"});
    ASSERT_EQ(cli.exit_code, 0) << cli.output;
    ASSERT_EQ(read_image(dir_ + "/cli.png", expected), "");
    EXPECT_TRUE(saved.rgb == expected.rgb) << "see " << png << " and " << dir_ << "/cli.png";

    // Quitting with the dialog open saves nothing (its name field still holds a name).
    xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
    const std::string again = xdotool(x.display(), "search --sync --name 'Save image as'");
    xdotool(x.display(), "windowfocus --sync " + again + " type later.png");
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
    EXPECT_FALSE(fs::exists(dir_ + "/later.png"));
}

// Saved while a render runs, the image is the one on screen then, and the message says it is
// partial (issue 15, item 14).
TEST_F(ViewerE2E, SavingWhileRenderingSaysTheImageIsPartial) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    const std::string ready = dir_ + "/ready.txt", scene = dir_ + "/showcase.sc", png = dir_ + "/showcase.png";
    fs::copy_file(std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc", scene);
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", "160", "--height", "120", "--threads", "2", "--ready-file",
                  ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer.output();
    // A render of minutes: 4096 samples a pixel (Render > Samples per pixel, then F5), stopped by
    // the quit at the end.
    const std::string window = xdotool(x.display(), "search --name whitted-view");
    xdotool(x.display(), "windowfocus --sync " + window + " key alt+r p");
    xdotool(x.display(), "search --sync --name '^Samples per pixel$'");
    xdotool(x.display(), "key End shift+Home");
    xdotool(x.display(), "type 4096");
    xdotool(x.display(), "key Return");
    xdotool(x.display(), "windowfocus --sync " + window + " key F5");
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) {
        return n.labels.count("progress") && n.labels.at("progress").find("of 4096 samples") != std::string::npos;
    }, 30s)) << viewer.output();

    xdotool(x.display(), "windowfocus --sync " + window + " key ctrl+s");
    const std::string dialog = xdotool(x.display(), "search --sync --name 'Save image as'");
    xdotool(x.display(), "windowfocus --sync " + dialog + " key Return");
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) {
        return n.labels.count("message") && n.labels.at("message").find("saved") != std::string::npos;
    }, 20s))
        << viewer.output();
    EXPECT_EQ(drawn_text(r.labels["message"]), " saved " + png + " while still rendering: the image is partial");
    Image saved;
    ASSERT_EQ(read_image(png, saved), "") << viewer.output();
    EXPECT_EQ(saved.width, 160);
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

// A one-sphere scene in the given diffuse colour: quick to render, easy to tell apart.
std::string sphere_scene(const std::string& diffuse, const std::string& texture = "") {
    return "camera [ eye 0 0 5 focus 0 0 0 angle 40 ]\n"
           "light [ position 3 4 5 color 1 1 1 ]\n"
           "background [ color 0.1 0.1 0.1 ]\n"
           "mastersubgraph root [ trans [ object sphere [ diffuse " + diffuse +
           (texture.empty() ? "" : " texture " + texture + " 1 1") + " ] ] ]\n";
}

// The command-line renderer's image of `scene` at W×H.
Image cli_image(const std::string& scene, int W, int H, const std::string& png) {
    auto cli = run_process({test::cli_path(), scene, "-o", png, "--width", std::to_string(W), "--height",
                            std::to_string(H), "-q"});
    EXPECT_EQ(cli.exit_code, 0) << cli.output;
    Image img;
    EXPECT_EQ(read_image(png, img), "");
    return img;
}

// Whether the screen shows `expected` whole, exactly where the ready file says the image is.
bool shows(const Image& screen, const Image& expected, const Box& image) {
    return image.w == expected.width && image.h == expected.height &&
           find_subimage(screen, expected, {image.x, image.y}) == std::make_pair(image.x, image.y);
}

// Rewrites a file in place with text of the same length (as an editor saving a colour change)
// and moves its modification time on, whatever the file system's timestamp resolution.
void rewrite_scene(const std::string& path, const std::string& text) {
    const auto before = fs::last_write_time(path);
    std::ofstream(path) << text;
    fs::last_write_time(path, before + 2s);
}

class ViewerOnScreen : public ViewerE2E {
protected:
    void SetUp() override {
        ViewerE2E::SetUp();
        ready_ = dir_ + "/ready.txt";
        WHITTED_NEEDS(test::kSkipViewerTests, x_.start(dir_, why_) ? "" : "no X server for the screen test: " + why_);
        WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xwd", "convert"}));
        std::ofstream(scene_) << sphere_scene("0.9 0.1 0.1");
        red_ = cli_image(scene_, kW, kH, dir_ + "/red.png");
        std::ofstream(dir_ + "/blue.sc") << sphere_scene("0.1 0.1 0.9");
        blue_ = cli_image(dir_ + "/blue.sc", kW, kH, dir_ + "/blue.png");
    }
    std::unique_ptr<Child> start_viewer(const std::vector<std::string>& extra) {
        std::vector<std::string> argv{WHITTED_VIEWER_PATH, scene_, "--width", std::to_string(kW), "--height",
                                      std::to_string(kH), "--threads", "2", "--ready-file", ready_};
        argv.insert(argv.end(), extra.begin(), extra.end());
        return std::make_unique<Child>(argv, dir_ + "/viewer.log",
                                       std::vector<std::pair<std::string, std::string>>{
                                           {"DISPLAY", x_.display()},
                                           {"ASAN_OPTIONS", asan_options_for_viewer()},
                                           {"WHITTED_VIEW_TEST_DIR", dir_}});  // see processes_left()
    }
    // Processes the viewer started (it included) that are still running: they have its environment.
    std::vector<pid_t> processes_left() const {
        const std::string marker = "WHITTED_VIEW_TEST_DIR=" + dir_;
        std::vector<pid_t> left;
        for (const auto& entry : fs::directory_iterator("/proc")) {
            const std::string name = entry.path().filename().string();
            if (name.find_first_not_of("0123456789") != std::string::npos) continue;
            std::ifstream in(entry.path() / "environ");
            for (std::string var; std::getline(in, var, '\0');)
                if (var == marker) left.push_back(pid_t(std::stoi(name)));
        }
        return left;
    }
    static constexpr int kW = 160, kH = 120;
    Xvfb x_;
    std::string why_, ready_;
    Image red_, blue_;
};

// --watch: saving the scene reloads it and renders again; the window then shows the new scene.
TEST_F(ViewerOnScreen, AChangedSceneIsReloadedAndShown) {
    auto viewer = start_viewer({"--watch"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen1.png"), red_, first.image))
        << "the red sphere is not on the screen (see " << dir_ << "/screen1.png)";

    rewrite_scene(scene_, sphere_scene("0.1 0.1 0.9"));
    Ready again;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, again,
                               [&](const Ready& n) { return n.job > first.job && n.state == "finished"; }, 30s))
        << "the changed scene was not rendered again:\n" << viewer->output();
    EXPECT_FALSE(again.reused) << "the changed file must be loaded again";
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen2.png"), blue_, again.image))
        << "the blue sphere is not on the screen (see " << dir_ << "/screen2.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Without --watch a saved change is not picked up (until File > Reload, Ctrl+R).
TEST_F(ViewerOnScreen, WithoutWatchAChangedSceneIsNotReloaded) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();

    Ready before;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, before, [](const Ready&) { return true; }, 5s)) << viewer->output();
    rewrite_scene(scene_, sphere_scene("0.1 0.1 0.9"));
    // Three ticks of the viewer's watch timer: with --watch, the change would have been seen at
    // the first and its render reported by the third.
    Ready later;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, later,
                               [&](const Ready& n) { return n.watch_ticks >= before.watch_ticks + 3; }, 30s))
        << viewer->output();
    EXPECT_EQ(later.job, first.job) << "the scene was rendered again without --watch";
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen1.png"), red_, later.image))
        << "the red sphere is no longer on the screen (see " << dir_ << "/screen1.png)";

    // The change was real: reloading by hand shows it.
    const std::string window = xdotool(x_.display(), "search --name whitted-view");
    xdotool(x_.display(), "windowfocus --sync " + window + " key ctrl+r");
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, later,
                               [&](const Ready& n) { return n.job > first.job && n.state == "finished"; }, 30s))
        << viewer->output();
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen2.png"), blue_, later.image))
        << "the blue sphere is not on the screen after Reload (see " << dir_ << "/screen2.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Fit window: once a resize has settled the scene is rendered again (without loading it again)
// at the size of the new image area; resizes in quick succession give one render.
TEST_F(ViewerOnScreen, FitWindowRendersAgainAtTheNewSizeAfterAResize) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    auto viewer = start_viewer({"--fit", "--window-size", "640x480"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_EQ(first.window.w, 640);
    EXPECT_EQ(first.area.w, 640);
    EXPECT_LT(first.area.h, 480);
    EXPECT_EQ(first.image.w, first.area.w);
    EXPECT_EQ(first.image.h, first.area.h);
    const int chrome_h = first.window.h - first.area.h;  // menu, tool and status bars

    const std::string window = xdotool(x_.display(), "search --name whitted-view");
    xdotool(x_.display(), "windowsize " + window + " 600 400 windowsize " + window + " 700 500");
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r,
                               [&](const Ready& n) {
                                   return n.window.w == 700 && n.window.h == 500 && n.job > first.job &&
                                          n.state == "finished";
                               },
                               30s))
        << "no render at the new size:\n" << viewer->output();
    EXPECT_EQ(r.job, first.job + 1) << "one render for the resizes, after they settled";
    EXPECT_TRUE(r.reused) << "the unchanged scene is not loaded again";
    EXPECT_EQ(r.area.w, 700);
    EXPECT_EQ(r.area.h, 500 - chrome_h);
    const Image expected = cli_image(scene_, r.area.w, r.area.h, dir_ + "/fitted.png");
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen.png"), expected, r.image))
        << "the image at the new size is not on the screen (see " << dir_ << "/screen.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Names with '@' (the scene's, a texture's) show as written in the status bar and the panel.
TEST_F(ViewerOnScreen, NamesWithAnAtSignShowAsWritten) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"tesseract"}));
    scene_ = dir_ + "/a@b.sc";
    std::ofstream(scene_) << sphere_scene("1 1 1", "t@x.png");
    auto viewer = start_viewer({"--missing-textures", "checker"});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_EQ(drawn_text(r.labels["scene"]).rfind(" a@b.sc: 1 objects", 0), 0u) << r.labels["scene"];
    const std::string warning = "a@b.sc:4:";  // relative to the scene's folder
    const std::string texture = "warning: texture 't@x.png': not found (drawn as a checkerboard)";
    const std::string message = drawn_text(r.labels["message"]);
    EXPECT_EQ(message.rfind(" " + warning, 0), 0u) << r.labels["message"];
    EXPECT_NE(message.find(texture), std::string::npos) << r.labels["message"];
    ASSERT_FALSE(r.panel.empty());
    EXPECT_EQ(r.panel[0].rfind(warning, 0), 0u) << r.panel[0];
    EXPECT_NE(r.panel[0].find(texture), std::string::npos) << r.panel[0];

    // What the user reads on the screen: the names with their '@', in the status bar and the
    // messages panel (between the image area and the status bar).
    const std::string png = dir_ + "/screen.png";
    grab_screen(x_.display(), png);
    const std::string scene_field = screen_text(png, r.fields["scene"], Lines::One);
    EXPECT_TRUE(reads(scene_field, "a@b.sc: 1 objects")) << scene_field << " (see " << png << ")";
    const std::string message_field = screen_text(png, r.fields["message"], Lines::One);
    EXPECT_TRUE(reads(message_field, "a@b.sc:4:")) << message_field << " (see " << png << ")";
    EXPECT_TRUE(reads(message_field, "warning: texture 't@x.png'")) << message_field << " (see " << png << ")";
    const Box panel{r.window.x, r.area.y + r.area.h, r.window.w, r.fields["scene"].y - (r.area.y + r.area.h)};
    const std::string panel_text = screen_text(png, panel, Lines::Block);
    EXPECT_TRUE(reads(panel_text, "a@b.sc:4:")) << panel_text << " (see " << png << ")";
    EXPECT_TRUE(reads(panel_text, texture)) << panel_text << " (see " << png << ")";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// The ids of the mapped windows on `display` whose title matches `name` (a regular expression).
std::vector<std::string> visible_windows(const std::string& display, const std::string& name) {
    auto r = run_process({"/bin/sh", "-c", "DISPLAY=" + display + " '" + find_on_path("xdotool") +
                                               "' search --onlyvisible --name '" + name + "' 2>/dev/null"});
    std::vector<std::string> ids;
    std::istringstream in(r.output);
    for (std::string id; in >> id;) ids.push_back(id);
    return ids;
}

// Waits up to `timeout` for a mapped window titled `name`; returns its id, or "".
std::string wait_for_window(const std::string& display, const std::string& name, std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        const std::vector<std::string> ids = visible_windows(display, name);
        if (!ids.empty()) return ids.front();
        if (std::chrono::steady_clock::now() >= deadline) return "";
        std::this_thread::sleep_for(50ms);
    }
}

// A window's place and size in root-window coordinates.
Box window_geometry(const std::string& display, const std::string& id) {
    auto r = run_process({"/bin/sh", "-c", "DISPLAY=" + display + " '" + find_on_path("xdotool") +
                                               "' getwindowgeometry --shell " + id + " 2>/dev/null"});
    Box b;
    std::istringstream in(r.output);
    for (std::string line; std::getline(in, line);) {
        const std::size_t eq = line.find('=');
        if (eq == std::string::npos) continue;
        const std::string key = line.substr(0, eq);
        const int value = std::atoi(line.c_str() + eq + 1);
        if (key == "X") b.x = value;
        else if (key == "Y") b.y = value;
        else if (key == "WIDTH") b.w = value;
        else if (key == "HEIGHT") b.h = value;
    }
    return b;
}

// Whether the screen shows a dialog at `box`: light grey and white (its background and list)
// with dark text. Behind it is the dark grey image area.
bool shows_a_dialog(const Image& screen, const Box& box) {
    if (box.w <= 0 || box.h <= 0 || box.x < 0 || box.y < 0 || box.right() > screen.width ||
        box.y + box.h > screen.height)
        return false;
    int light = 0, dark = 0;
    for (int y = box.y; y < box.y + box.h; ++y)
        for (int x = box.x; x < box.right(); ++x) {
            const glm::ivec3 c(screen.at(x, y));
            light += std::min({c.x, c.y, c.z}) >= 150;
            dark += std::max({c.x, c.y, c.z}) < 80;
        }
    const int all = box.w * box.h;
    return light > all * 8 / 10 && dark > all / 200;
}

// A texture that is not found: the viewer asks for its file in a dialog; Cancel draws it as the
// magenta/black checkerboard, with a warning naming it; the viewer then quits cleanly.
TEST_F(ViewerOnScreen, CancellingTheMissingTextureDialogDrawsACheckerboard) {
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    std::ofstream(scene_) << sphere_scene("1 1 1", "nowhere.png");
    auto viewer = start_viewer({"--mode", "raycast"});  // unlit: the texture's own colours

    // The dialog is mapped and drawn on the screen while the viewer waits for an answer.
    const std::string dialog = wait_for_window(x_.display(), "^Texture not found$", 60s);
    ASSERT_FALSE(dialog.empty()) << "no dialog was shown:\n" << viewer->output();
    const Box d = window_geometry(x_.display(), dialog);
    ASSERT_EQ(d.w, 640) << "the dialog's width, as made in ask_texture_dialog()";
    bool shown = false;
    for (auto deadline = std::chrono::steady_clock::now() + 10s;
         !shown && std::chrono::steady_clock::now() < deadline; std::this_thread::sleep_for(50ms))
        shown = shows_a_dialog(grab_screen(x_.display(), dir_ + "/dialog.png"), d);
    ASSERT_TRUE(shown) << "the dialog is not on the screen (see " << dir_ << "/dialog.png)";
    EXPECT_EQ(visible_windows(x_.display(), "^Texture not found$").size(), 1u);

    // A click on "Cancel (checkerboard)": 180×28 at (w - 340, h - 38) in the dialog.
    xdotool(x_.display(), "mousemove --window " + dialog + " " + std::to_string(d.w - 250) + " " +
                              std::to_string(d.h - 24) + " click 1");
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }, 60s))
        << "no render after Cancel:\n" << viewer->output();
    EXPECT_TRUE(visible_windows(x_.display(), "Texture").empty()) << "the dialog, or a file chooser, is open";

    // Inside the sphere (about 36 pixels across, in the middle) only the board's colours and
    // their blends at the squares' edges: both colours, and nothing off the line between them.
    const Image screen = grab_screen(x_.display(), dir_ + "/checker.png");
    ASSERT_EQ(r.image.w, kW);
    ASSERT_EQ(r.image.h, kH);
    int magenta = 0, black = 0, other = 0;
    const int cx = r.image.x + kW / 2, cy = r.image.y + kH / 2;
    for (int y = cy - 8; y < cy + 8; ++y)
        for (int x = cx - 8; x < cx + 8; ++x) {
            const glm::ivec3 c(screen.at(x, y));
            if (c.x >= 254 && c.y <= 1 && c.z >= 254) ++magenta;
            else if (c.x <= 1 && c.y <= 1 && c.z <= 1) ++black;
            else if (c.y > 1 || std::abs(c.x - c.z) > 1) ++other;
        }
    EXPECT_GT(magenta, 0) << "see " << dir_ << "/checker.png";
    EXPECT_GT(black, 0) << "see " << dir_ << "/checker.png";
    EXPECT_EQ(other, 0) << "see " << dir_ << "/checker.png";

    // The messages panel and the status bar name the texture.
    ASSERT_FALSE(r.panel.empty());
    EXPECT_EQ(r.panel[0].rfind("scene.sc:4:", 0), 0u) << r.panel[0];
    EXPECT_NE(r.panel[0].find("warning: texture 'nowhere.png': not found (drawn as a checkerboard)"),
              std::string::npos)
        << r.panel[0];
    EXPECT_EQ(drawn_text(r.labels["message"]).rfind(" warning: texture 'nowhere.png' drawn as a checkerboard", 0), 0u)
        << r.labels["message"];

    // File > Quit (Ctrl+Q) ends it with 0, leaving no process behind.
    const std::vector<std::string> main_window = visible_windows(x_.display(), "^whitted-view");
    ASSERT_EQ(main_window.size(), 1u);
    xdotool(x_.display(), "windowfocus --sync " + main_window[0] + " key ctrl+q");
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
    EXPECT_EQ(processes_left(), std::vector<pid_t>{});
}

// ---------------------------------------------------------------------------------------------
// The workbench (issue 12): the camera moved on the image, back home, into the file; the error
// loop; what is remembered between runs.

Image crop(const Image& screen, const Box& b) {
    Image out(b.w, b.h);
    for (int y = 0; y < b.h; ++y)
        for (int x = 0; x < b.w; ++x) {
            const glm::u8vec3 c = screen.at(b.x + x, b.y + y);
            std::uint8_t* p = &out.rgb[(std::size_t(y) * b.w + x) * 3];
            p[0] = c.x, p[1] = c.y, p[2] = c.z;
        }
    return out;
}

class ViewerWorkbench : public ViewerOnScreen {
protected:
    void SetUp() override {
        ViewerOnScreen::SetUp();
        WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    }
    // A real left drag with the mouse from the image's centre, `dx` pixels to the right.
    void drag(const Ready& r, int dx) {
        const int cx = r.image.x + r.image.w / 2, cy = r.image.y + r.image.h / 2;
        std::string moves;
        for (int step = 1; step <= 4; ++step) moves += " mousemove " + std::to_string(cx + dx * step / 4) + " " + std::to_string(cy) + " sleep 0.05";
        xdotool(x_.display(), "mousemove " + std::to_string(cx) + " " + std::to_string(cy) + " mousedown 1" + moves +
                                  " mouseup 1");
    }
    void keys(const std::string& k) {
        const std::string window = xdotool(x_.display(), "search --name whitted-view");
        xdotool(x_.display(), "windowfocus --sync " + window + " key " + k);
    }
    static constexpr const char* kShapes = R"(camera [ eye 0 1 6 focus 0 0 0 angle 40 ]
light [ position 3 4 5 color 1 1 1 ]
background [ color 0.1 0.15 0.3 ]
mastersubgraph root [
  trans [ translate -1.2 0 0  object sphere [ diffuse 0.9 0.2 0.1 specular 0.5 0.5 0.5 shine 30 ] ]
  trans [ translate 1.2 0 0 rotate 0 1 0 30 object cube [ diffuse 0.2 0.7 0.3 ] ]
  trans [ translate 0 -1 0 scale 8 0.1 8 object cube [ diffuse 0.6 0.6 0.6 ] ]
]
)";
};

TEST_F(ViewerWorkbench, ADragMovesTheCameraAndHomeRestoresTheFilesImageByteForByte) {
    std::ofstream(scene_) << kShapes;
    const Image file_image = cli_image(scene_, kW, kH, dir_ + "/file.png");
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen1.png"), file_image, first.image));
    EXPECT_EQ(first.camera.rfind("file camera [ eye 0 1 6 focus 0 0 0 ", 0), 0u) << first.camera;

    drag(first, 60);  // 15 degrees of orbit
    Ready moved;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, moved, [&](const Ready& n) {
        return n.job > first.job && n.state == "finished" && n.camera.rfind("moved ", 0) == 0;
    })) << viewer->output();
    EXPECT_TRUE(moved.reused) << "moving the camera must not load the scene again";
    const Image after_drag = crop(grab_screen(x_.display(), dir_ + "/screen2.png"), moved.image);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < after_drag.rgb.size(); ++i) differ += after_drag.rgb[i] != file_image.rgb[i];
    EXPECT_GT(differ, after_drag.rgb.size() / 20) << "the image did not change (see " << dir_ << "/screen2.png)";

    keys("Home");
    Ready home;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, home, [&](const Ready& n) {
        return n.job > moved.job && n.state == "finished" && n.camera.rfind("file ", 0) == 0;
    })) << viewer->output();
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/screen3.png"), file_image, home.image))
        << "Home must give the file's image byte for byte (see " << dir_ << "/screen3.png)";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

TEST_F(ViewerWorkbench, SaveCameraIntoSceneKeepsEveryOtherByteAndTheImageOnScreen) {
    const std::string head = "# my scene\n";
    const std::string old_block = "camera [ eye 0 1 6 focus 0 0 0 angle 40 ]";
    const std::string tail = std::string("   # the camera\n") + (std::strchr(kShapes, '\n') + 1);
    std::ofstream(scene_) << head + old_block + tail;
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    drag(first, -80);
    Ready moved;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, moved, [&](const Ready& n) {
        return n.job > first.job && n.state == "finished" && n.camera.rfind("moved ", 0) == 0;
    })) << viewer->output();
    const Image on_screen = crop(grab_screen(x_.display(), dir_ + "/moved.png"), moved.image);

    keys("ctrl+shift+s");
    const std::string dialog = wait_for_window(x_.display(), "^Save camera into scene$", 30s);
    ASSERT_FALSE(dialog.empty()) << "no confirmation was asked:\n" << viewer->output();
    xdotool(x_.display(), "windowfocus --sync " + dialog + " key Return");
    Ready saved;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, saved, [&](const Ready& n) {
        return n.job > moved.job && n.state == "finished" && n.camera.rfind("file ", 0) == 0;
    })) << viewer->output();

    // The file: the same bytes around a new camera block, which is the one the window had.
    std::ifstream in(scene_);
    const std::string text{std::istreambuf_iterator<char>(in), {}};
    ASSERT_EQ(text.rfind(head, 0), 0u) << text;
    ASSERT_GE(text.size(), head.size() + tail.size());
    EXPECT_EQ(text.substr(text.size() - tail.size()), tail) << text;
    const std::string block = text.substr(head.size(), text.size() - head.size() - tail.size());
    EXPECT_NE(block, old_block);
    EXPECT_EQ("moved " + block, moved.camera);
    // Loaded again: the window shows the image it showed before saving, and so does the renderer.
    EXPECT_FALSE(saved.reused);
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/saved.png"), on_screen, saved.image))
        << "see " << dir_ << "/moved.png and saved.png";
    EXPECT_EQ(cli_image(scene_, kW, kH, dir_ + "/saved_cli.png").rgb, on_screen.rgb);
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

TEST_F(ViewerWorkbench, ABrokenSceneKeepsTheLastImageDimmedUnderTheErrorUntilFixed) {
    auto viewer = start_viewer({"--watch"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    ASSERT_TRUE(shows(grab_screen(x_.display(), dir_ + "/red.png"), red_, first.image));

    rewrite_scene(scene_, "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n");
    Ready broken;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, broken,
                               [&](const Ready& n) { return n.job > first.job && n.state == "failed"; }, 30s))
        << viewer->output();
    EXPECT_TRUE(broken.dimmed);
    ASSERT_FALSE(broken.panel.empty());
    EXPECT_EQ(broken.panel[0].rfind("scene.sc:2:", 0), 0u) << broken.panel[0];
    const Image screen = grab_screen(x_.display(), dir_ + "/broken.png");
    // Below the banner (two lines of text at the top), the red image at 2/5 of its brightness.
    ASSERT_EQ(broken.image.w, kW);
    int wrong = 0;
    for (int y = kH - 40; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const glm::ivec3 want = glm::ivec3(red_.at(x, y)) * 2 / 5;
            wrong += glm::ivec3(screen.at(broken.image.x + x, broken.image.y + y)) != want;
        }
    EXPECT_EQ(wrong, 0) << "see " << dir_ << "/broken.png";
    EXPECT_EQ(glm::ivec3(screen.at(broken.area.x + 2, broken.area.y + 2)), glm::ivec3(70, 20, 20))
        << "no error banner at the top of the image area (see " << dir_ << "/broken.png)";

    rewrite_scene(scene_, sphere_scene("0.1 0.1 0.9"));
    Ready fixed;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, fixed,
                               [&](const Ready& n) { return n.job > broken.job && n.state == "finished"; }, 30s))
        << viewer->output();
    EXPECT_FALSE(fixed.dimmed);
    EXPECT_TRUE(shows(grab_screen(x_.display(), dir_ + "/blue.png"), blue_, fixed.image));
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

TEST_F(ViewerWorkbench, RecentFilesAndTheWindowSizeSurviveARestart) {
    // HOME is the test's folder (Child): the preferences start empty and stay there.
    {
        auto viewer = start_viewer({});
        Ready r;
        ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
            << viewer->output();
        EXPECT_EQ(r.window.w, 1000);  // the default, nothing remembered yet
        const std::string window = xdotool(x_.display(), "search --name whitted-view");
        xdotool(x_.display(), "windowsize " + window + " 720 520");
        ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.window.w == 720; }, 20s))
            << viewer->output();
        keys("ctrl+q");
        ASSERT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
    }
    EXPECT_TRUE(fs::exists(dir_ + "/.fltk/whitted/whitted-view.prefs"));
    fs::remove(ready_);
    const std::string first_scene = scene_;
    scene_ = dir_ + "/blue.sc";
    auto viewer = start_viewer({});
    Ready r;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    EXPECT_EQ(r.window.w, 720);
    EXPECT_EQ(r.window.h, 520);
    EXPECT_EQ(r.recent, (std::vector<std::string>{scene_, first_scene}));
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// Zoom with '+' (2x, nearest neighbour: each image pixel a 2 x 2 block) and exposure with ']'
// (one stop: each byte doubled, clamped), about the centre of the area.
TEST_F(ViewerWorkbench, ZoomShowsPixelsAsBlocksAndExposureDoublesTheBytes) {
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    keys("plus");
    Ready zoomed;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, zoomed, [](const Ready& n) { return n.image.w == 2 * kW; }, 20s))
        << viewer->output();
    ASSERT_EQ(zoomed.image.h, 2 * kH);
    const Image screen = grab_screen(x_.display(), dir_ + "/zoomed.png");
    int wrong = 0;
    for (int y = 0; y < 2 * kH; ++y)
        for (int x = 0; x < 2 * kW; ++x)
            wrong += screen.at(zoomed.image.x + x, zoomed.image.y + y) != red_.at(x / 2, y / 2);
    EXPECT_EQ(wrong, 0) << "see " << dir_ << "/zoomed.png";

    keys("1 bracketright");
    Ready exposed;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, exposed,
                               [](const Ready& n) { return n.image.w == kW && n.exposure == 1.0; }, 20s))
        << viewer->output();
    const Image bright = grab_screen(x_.display(), dir_ + "/exposed.png");
    wrong = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const glm::ivec3 want = glm::min(glm::ivec3(red_.at(x, y)) * 2, glm::ivec3(255));
            wrong += glm::ivec3(bright.at(exposed.image.x + x, exposed.image.y + y)) != want;
        }
    EXPECT_EQ(wrong, 0) << "see " << dir_ << "/exposed.png";
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// --watch also reloads when a texture file of the scene changes (not only the scene file).
TEST_F(ViewerWorkbench, WatchReloadsWhenATextureChanges) {
    Image tex(4, 4);
    std::fill(tex.rgb.begin(), tex.rgb.end(), std::uint8_t(200));
    ASSERT_EQ(write_image(tex, dir_ + "/tex.png"), "");
    std::ofstream(scene_, std::ios::trunc) << sphere_scene("1 1 1", "tex.png");
    auto viewer = start_viewer({"--watch"});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    const auto before = fs::last_write_time(dir_ + "/tex.png");
    std::fill(tex.rgb.begin(), tex.rgb.end(), std::uint8_t(40));
    ASSERT_EQ(write_image(tex, dir_ + "/tex.png"), "");
    fs::last_write_time(dir_ + "/tex.png", before + 2s);
    Ready again;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, again,
                               [&](const Ready& n) { return n.job > first.job && n.state == "finished"; }, 30s))
        << "the changed texture was not loaded again:\n" << viewer->output();
    EXPECT_FALSE(again.reused);
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

TEST_F(ViewerWorkbench, F1OpensTheKeyboardShortcutsWindow) {
    auto viewer = start_viewer({});
    Ready first;
    ASSERT_TRUE(wait_for_ready(*viewer, ready_, first, [](const Ready& n) { return n.state == "finished"; }))
        << viewer->output();
    keys("F1");
    EXPECT_FALSE(wait_for_window(x_.display(), "^Keyboard shortcuts$", 20s).empty()) << viewer->output();
    viewer->signal(SIGTERM);
    EXPECT_EQ(viewer->wait_exit(10s), 0) << viewer->output();
}

// A double-click on an error in the messages panel opens the editor at the error's line (issue 12,
// item 5); the editor here is a script that writes down how it was called.
TEST_F(ViewerWorkbench, DoubleClickingAnErrorOpensTheEditorAtItsLine) {
    std::ofstream(scene_, std::ios::trunc) << "camera [ eye 0 0 5 ]\nmastersubgraph root [ trans [ object blob [ ] ] ]\n";
    const std::string editor = dir_ + "/editor.sh", called = dir_ + "/editor-called";
    std::ofstream(editor) << "#!/bin/sh\necho \"$@\" > '" << called << ".tmp' && mv '" << called << ".tmp' '" << called
                          << "'\n";
    fs::permissions(editor, fs::perms::owner_all);
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", std::to_string(kW), "--height", std::to_string(kH), "--threads",
                  "2", "--ready-file", ready_},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x_.display()}, {"HOME", dir_}, {"VISUAL", ""}, {"EDITOR", editor},
                  {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready_, r, [](const Ready& n) { return n.state == "failed" && !n.panel.empty(); }))
        << viewer.output();
    ASSERT_EQ(r.panel[0].rfind("scene.sc:2:", 0), 0u) << r.panel[0];
    // The panel lies under the image area, across the window: its first line, double-clicked.
    xdotool(x_.display(), "mousemove --sync " + std::to_string(r.area.x + 40) + " " +
                              std::to_string(r.area.y + r.area.h + 10) + " click --repeat 2 --delay 80 1");
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (!fs::exists(called) && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(50ms);
    std::ifstream in(called);
    std::string args;
    std::getline(in, args);
    std::string want = "+2 ";  // (piece by piece: GCC 12's -Wrestrict misfires on the one-expression form)
    want += scene_;
    EXPECT_EQ(args, want) << viewer.output();
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

// [inspector] A click on a pixel of the image opens the inspector with that pixel's report; its
// button opens $EDITOR at the line of the object's `object` keyword (the editor here a script that
// writes down how it was called).
TEST_F(ViewerE2E, ClickingAPixelInspectsItAndOpensTheEditorAtTheObjectsLine) {
    Xvfb x;
    std::string why;
    WHITTED_NEEDS(test::kSkipViewerTests, x.start(dir_, why) ? "" : "no X server for the screen test: " + why);
    WHITTED_NEEDS(test::kSkipViewerTests, missing_tools({"xdotool"}));
    const std::string scene = dir_ + "/pillars.sc", ready = dir_ + "/ready.txt", called = dir_ + "/editor-args.txt";
    std::ofstream(scene) << test::kInspectScene;
    const std::string editor = dir_ + "/editor.sh";
    std::ofstream(editor) << "#!/bin/sh\necho \"$@\" > '" << called << ".tmp' && mv '" << called << ".tmp' '" << called
                          << "'\n";
    fs::permissions(editor, fs::perms::owner_all);
    Child viewer({WHITTED_VIEWER_PATH, scene, "--width", std::to_string(test::kInspectWidth), "--height",
                  std::to_string(test::kInspectHeight), "--threads", "2", "--ready-file", ready},
                 dir_ + "/viewer.log",
                 {{"DISPLAY", x.display()}, {"HOME", dir_}, {"VISUAL", ""}, {"EDITOR", editor},
                  {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer.output();
    ASSERT_EQ(r.image.w, test::kInspectWidth);

    // The right pillar, projected; clicked at its pixel's centre (root-window coordinates).
    const glm::ivec2 px = test::project(test::kRightPillarFront);
    xdotool(x.display(), "mousemove --sync " + std::to_string(r.image.x + px.x) + " " + std::to_string(r.image.y + px.y) +
                             " click 1");
    const std::string inspector = xdotool(x.display(), "search --sync --name 'Pixel inspector'");
    ASSERT_FALSE(inspector.empty());
    const Box w = window_geometry(x.display(), inspector);
    // Its button "Open FILE:LINE:COL in the editor", left of the bottom row (inspector_window.cpp).
    xdotool(x.display(), "mousemove --window " + inspector + " 200 " + std::to_string(w.h - 8 - 14) + " click 1");
    const auto deadline = std::chrono::steady_clock::now() + 20s;
    while (!fs::exists(called) && std::chrono::steady_clock::now() < deadline) std::this_thread::sleep_for(50ms);
    std::ifstream in(called);
    std::string args;
    std::getline(in, args);
    // Appended piece by piece: GCC 12's -Wrestrict misfires on the one-expression form.
    std::string want = "+";
    want += std::to_string(test::find_in_scene("object cylinder").line);
    want += ' ';
    want += scene;
    EXPECT_EQ(args, want) << viewer.output();
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

}  // namespace
}  // namespace whitted
#endif
