#include "inspect_action.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <sstream>
#include <thread>

#include "inspect/report_text.h"

extern char** environ;

namespace whitted::viewer {

InspectResult inspect_shown_pixel(const RenderController& controller, int x, int y) {
    InspectResult r;
    const RenderController::Shown shown = controller.shown();
    if (!shown.scene) {
        r.message = "no image to inspect yet";
        return r;
    }
    const RenderJob& job = shown.settings;
    if (x < 0 || y < 0 || x >= job.width || y >= job.height) {
        r.message = "pixel " + std::to_string(x) + "," + std::to_string(y) + " is outside the " +
                    std::to_string(job.width) + "x" + std::to_string(job.height) + " image";
        return r;
    }
    r.report = inspect_pixel(*shown.scene, job, x, y);
    r.base_dir = std::filesystem::path(shown.scene_path).parent_path().string();
    if (r.base_dir.empty()) r.base_dir = ".";
    r.text = report_text(r.report, r.base_dir);
    r.ok = true;
    return r;
}

std::optional<SourceLoc> location_in_line(const std::string& line, const std::string& base_dir) {
    // Words of the line; a location is FILE:LINE:COL (the file may itself hold ':' characters).
    std::istringstream words(line);
    std::string w;
    while (words >> w) {
        // Punctuation around it in the report: "(point at FILE:L:C):", "FILE:L:C,".
        while (!w.empty() && (w.back() == ')' || w.back() == ':' || w.back() == ',')) w.pop_back();
        while (!w.empty() && w.front() == '(') w.erase(w.begin());
        const auto c2 = w.rfind(':');
        if (c2 == std::string::npos || c2 == 0) continue;
        const auto c1 = w.rfind(':', c2 - 1);
        if (c1 == std::string::npos || c1 == 0) continue;
        const std::string ln = w.substr(c1 + 1, c2 - c1 - 1), col = w.substr(c2 + 1);
        auto digits = [](const std::string& s) {
            if (s.empty() || s.size() > 9) return false;
            for (char ch : s)
                if (!std::isdigit(static_cast<unsigned char>(ch))) return false;
            return true;
        };
        if (!digits(ln) || !digits(col) || std::stoi(ln) <= 0) continue;
        SourceLoc loc;
        std::filesystem::path file(w.substr(0, c1));
        if (file.is_relative() && !base_dir.empty()) file = std::filesystem::path(base_dir) / file;
        loc.file = file.lexically_normal().string();
        loc.line = std::stoi(ln);
        loc.col = std::stoi(col);
        return loc;
    }
    return std::nullopt;
}

std::string chosen_editor(const char* visual, const char* editor) {
    if (visual && *visual) return visual;
    if (editor && *editor) return editor;
    return "";
}

std::vector<std::string> editor_command(const std::string& editor, const SourceLoc& loc) {
    std::vector<std::string> argv;
    std::istringstream words(editor);
    for (std::string w; words >> w;) argv.push_back(w);
    if (argv.empty() || loc.line <= 0 || loc.file.empty()) return {};
    const std::string program = std::filesystem::path(argv[0]).filename().string();
    if (program == "code" || program == "codium" || program == "code-insiders" || program == "cursor") {
        argv.push_back("-g");
        argv.push_back(loc.file + ":" + std::to_string(loc.line) + ":" + std::to_string(std::max(1, loc.col)));
    } else {
        std::string plus = "+";  // appended, not "+" + …: GCC 12 warns falsely (-Wrestrict) on that form
        plus += std::to_string(loc.line);
        argv.push_back(plus);
        argv.push_back(loc.file);
    }
    return argv;
}

bool launch_detached(const std::vector<std::string>& argv) {
    if (argv.empty()) return false;
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSID);  // its own session: outlives the viewer
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
    pid_t pid = -1;
    const int err = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    if (err != 0) return false;
    std::thread([pid] { waitpid(pid, nullptr, 0); }).detach();  // reaped when it ends: no zombie
    return true;
}

}  // namespace whitted::viewer
