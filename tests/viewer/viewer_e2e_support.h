#pragma once
// whitted-view's end-to-end tests: the harness (a child process, an X server of our own (Xvfb), the
// viewer's --ready-file, screen grabs, OCR, xdotool, window lookups). The test files are
// viewer_*_test.cpp; their fixtures are in viewer_e2e_fixtures.h.
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
#include <iostream>
#include <map>
#include <sstream>
#include <thread>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "support/needs.h"
#include "support/run_process.h"

namespace whitted::viewer_e2e {

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using test::run_process;

inline std::string find_on_path(const std::string& name) {
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/bin:/bin");
    for (std::string dir; std::getline(dirs, dir, ':');)
        if (!dir.empty() && access((dir + "/" + name).c_str(), X_OK) == 0) return dir + "/" + name;
    return "";
}

// "" when every tool is on the PATH, else which are missing and where they come from.
inline std::string missing_tools(std::initializer_list<const char*> tools) {
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
          const std::vector<std::pair<std::string, std::string>>& env = {})
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
inline bool accepts_connections(const std::string& number) {
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

// An X server of our own on a display number of our own. The number comes from the test's
// process id, not from Xvfb's -displayfd: that picks the lowest free number, which with tests
// running in parallel is often one whose server (another test's) is still shutting down; that
// server then removes the socket file of the new one as it exits (seen in CI: the viewer could not
// open the display it was given). A server is ours when the display's lock file holds its pid.
class Xvfb {
public:
    bool start(const std::string& dir, std::string& why) {
        std::string xvfb = find_on_path("Xvfb");
        if (xvfb.empty()) {
            why = "Xvfb is not installed (Debian package xvfb; scripts/install-deps.sh --viewer-test installs it)";
            return false;
        }
        const long first = 200 + (static_cast<long>(getpid()) * 8) % 24000;
        for (long number = first; number < first + 8; ++number) {
            if (fs::exists("/tmp/.X" + std::to_string(number) + "-lock")) continue;
            server_ = std::make_unique<Child>(
                // -noreset: an X server resets when its last client leaves (our probe of its
                // socket, xwd, xdotool), and a client that connects meanwhile can be refused.
                std::vector<std::string>{xvfb, ":" + std::to_string(number), "-screen", "0", "1280x1024x24",
                                         "-nolisten", "tcp", "-noreset"},
                dir + "/xvfb.log");
            if (wait_until_ours(number)) {
                display_ = ":" + std::to_string(number);
                return true;
            }
            why = "Xvfb did not start on :" + std::to_string(number) + ": " + server_->output();
            server_.reset();
        }
        return false;
    }
    const std::string& display() const { return display_; }

    // Before a client is started: the server still runs and still accepts connections. If not (seen
    // in CI: a viewer could not open the display of a server that had started), why is printed for
    // the log and another server is started; false if none could be.
    bool ensure_running(const std::string& dir, std::string& why) {
        const std::string number = display_.empty() ? "" : display_.substr(1);
        const int exited = server_ ? server_->wait_exit(0ms) : -2;
        if (exited == -1 && accepts_connections(number)) return true;
        std::cerr << "note: the X server of " << display_ << " went away before the client started ("
                  << (exited == -1 ? "still running, its socket " + std::string(fs::exists("/tmp/.X11-unix/X" + number)
                                                                                    ? "there but refusing connections"
                                                                                    : "file gone")
                                   : "exited with " + std::to_string(exited))
                  << "; its log: " << (server_ ? server_->output() : "") << "): starting another\n";
        server_.reset();
        display_.clear();
        return start(dir, why);
    }

private:
    // Until the server accepts connections and the lock file names it, or it has exited.
    bool wait_until_ours(long number) {
        const std::string lock = "/tmp/.X" + std::to_string(number) + "-lock";
        for (auto deadline = std::chrono::steady_clock::now() + 20s; std::chrono::steady_clock::now() < deadline;
             std::this_thread::sleep_for(20ms)) {
            if (server_->wait_exit(0ms) != -1) return false;
            long owner = 0;
            std::ifstream(lock) >> owner;
            if (owner == server_->pid && accepts_connections(std::to_string(number))) return true;
        }
        return false;
    }

    std::unique_ptr<Child> server_;
    std::string display_;
};

// The viewer links FLTK and Xlib, whose one-time allocations
// LeakSanitizer reports at exit; leaks are checked in the project's own code by the other tests.
inline std::string asan_options_for_viewer() {
    const char* o = std::getenv("ASAN_OPTIONS");
    return std::string(o ? o : "") + (o && *o ? ":" : "") + "detect_leaks=0";
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
    std::map<std::string, std::string> settings;     // the tool bar's values, by tool
    std::vector<std::string> banner;                 // the lines over the image area (an error)
    struct RayLine {
        std::string kind;
        int depth = 0;
        float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    };
    std::vector<RayLine> rays;                       // the ray tree drawn over the image (root coordinates)
    struct Mark {
        std::string shape;
        float x = 0, y = 0;
    };
    std::vector<Mark> marks;                         // its marks: hits, blockers, lights, total internal reflection
};

inline Ready read_ready(const std::string& path) {
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
        } else if (key == "setting" && ls >> name >> word) {
            r.settings[name] = word;
        } else if (key == "ray") {
            Ready::RayLine l;
            if (ls >> l.kind >> l.depth >> l.x0 >> l.y0 >> l.x1 >> l.y1) r.rays.push_back(l);
        } else if (key == "mark") {
            Ready::Mark m;
            if (ls >> m.shape >> m.x >> m.y) r.marks.push_back(m);
        } else if (key == "banner") {
            r.banner.push_back(line.substr(std::min(line.size(), key.size() + 1)));
        }
    }
    return r;
}

// The text FLTK draws for a label: "@@" is a literal '@'; any other '@' starts a symbol (shown
// here as "<symbol>"), and the name would not show as written.
inline std::string drawn_text(const std::string& label) {
    std::string out;
    for (std::size_t i = 0; i < label.size(); ++i) {
        if (label[i] != '@') out += label[i];
        else if (i + 1 < label.size() && label[i + 1] == '@') out += label[i++];
        else return out + "<symbol>";
    }
    return out;
}

// Where `part` appears in `whole` (every pixel within 1 level), or {-1, -1}.
inline std::pair<int, int> find_subimage(const Image& whole, const Image& part, std::pair<int, int> hint) {
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

// Waits until the viewer has written a ready file that `good` accepts; the file is read whole
// (the viewer writes it under another name and renames it).
inline bool wait_for_ready(Child& viewer, const std::string& path, Ready& out, const std::function<bool(const Ready&)>& good,
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
inline Image grab_screen(const std::string& display, const std::string& png) {
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
inline std::string screen_text(const std::string& png, const Box& box, Lines lines) {
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
inline std::string unquoted(std::string text) {
    for (const char* q : {"\u2018", "\u2019", "\u201C", "\u201D", "'", "\""})
        for (std::size_t i; (i = text.find(q)) != std::string::npos;) text.erase(i, std::strlen(q));
    return text;
}

// Whether OCR output `read` contains `meant`, quotation marks aside.
inline bool reads(const std::string& read, const std::string& meant) {
    return unquoted(read).find(unquoted(meant)) != std::string::npos;
}

// xdotool on our X server; returns the first line of its output (e.g. a window id).
inline std::string xdotool(const std::string& display, const std::string& args) {
    auto r = run_process({"/bin/sh", "-c", "DISPLAY=" + display + " '" + find_on_path("xdotool") + "' " + args});
    EXPECT_EQ(r.exit_code, 0) << "xdotool " << args << ":\n" << r.output;
    return r.output.substr(0, r.output.find('\n'));
}

inline bool overlap(const Box& a, const Box& b) {
    return a.x < b.right() && b.x < a.right() && a.y < b.y + b.h && b.y < a.y + a.h;
}

// Whether the screen shows `expected` whole, exactly where the ready file says the image is.
inline bool shows(const Image& screen, const Image& expected, const Box& image) {
    return image.w == expected.width && image.h == expected.height &&
           find_subimage(screen, expected, {image.x, image.y}) == std::make_pair(image.x, image.y);
}

// The ids of the mapped windows on `display` whose title matches `name` (a regular expression).
inline std::vector<std::string> visible_windows(const std::string& display, const std::string& name) {
    auto r = run_process({"/bin/sh", "-c", "DISPLAY=" + display + " '" + find_on_path("xdotool") +
                                               "' search --onlyvisible --name '" + name + "' 2>/dev/null"});
    std::vector<std::string> ids;
    std::istringstream in(r.output);
    for (std::string id; in >> id;) ids.push_back(id);
    return ids;
}

// Waits up to `timeout` for a mapped window titled `name`; returns its id, or "".
inline std::string wait_for_window(const std::string& display, const std::string& name, std::chrono::seconds timeout) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        const std::vector<std::string> ids = visible_windows(display, name);
        if (!ids.empty()) return ids.front();
        if (std::chrono::steady_clock::now() >= deadline) return "";
        std::this_thread::sleep_for(50ms);
    }
}

// A window's place and size in root-window coordinates.
inline Box window_geometry(const std::string& display, const std::string& id) {
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
inline bool shows_a_dialog(const Image& screen, const Box& box) {
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

inline Image crop(const Image& screen, const Box& b) {
    Image out(b.w, b.h);
    for (int y = 0; y < b.h; ++y)
        for (int x = 0; x < b.w; ++x) {
            const glm::u8vec3 c = screen.at(b.x + x, b.y + y);
            std::uint8_t* p = &out.rgb[(std::size_t(y) * b.w + x) * 3];
            p[0] = c.x, p[1] = c.y, p[2] = c.z;
        }
    return out;
}

}  // namespace whitted::viewer_e2e
