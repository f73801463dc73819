#include "support/run_process.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

namespace whitted::test {

ProcessResult run_process(const std::vector<std::string>& argv, int interrupt_after_ms) {
    ProcessResult result;
    int pipe_fd[2];
    if (pipe(pipe_fd) != 0) return result;
    pid_t pid = fork();
    if (pid == 0) {
        dup2(pipe_fd[1], STDOUT_FILENO);
        dup2(pipe_fd[1], STDERR_FILENO);
        close(pipe_fd[0]);
        close(pipe_fd[1]);
        std::vector<char*> args;
        for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
        args.push_back(nullptr);
        execv(args[0], args.data());
        _exit(127);
    }
    close(pipe_fd[1]);
    std::thread interrupter;
    if (interrupt_after_ms >= 0)
        interrupter = std::thread([pid, interrupt_after_ms] {
            std::this_thread::sleep_for(std::chrono::milliseconds(interrupt_after_ms));
            kill(pid, SIGINT);
        });
    char buf[4096];
    for (ssize_t n; (n = read(pipe_fd[0], buf, sizeof buf)) > 0;) result.output.append(buf, size_t(n));
    close(pipe_fd[0]);
    int status = 0;
    waitpid(pid, &status, 0);
    if (interrupter.joinable()) interrupter.join();
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

std::string cli_path() { return WHITTED_CLI_PATH; }
std::string source_dir() { return WHITTED_SOURCE_DIR; }

std::string shared_dir() {
    namespace fs = std::filesystem;
    if (const char* env = std::getenv("WHITTED_SHARED_DIR"); env && fs::is_directory(env)) return env;
    fs::path beside = fs::path(WHITTED_SOURCE_DIR) / ".." / "shared";
    return fs::is_directory(beside / "scenes") ? beside.lexically_normal().string() : "";
}

std::string make_temp_dir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "whitted-test-XXXXXX").string();
    return mkdtemp(tmpl.data()) ? tmpl : "";
}

std::string write_file(const std::string& dir, const std::string& name, const std::string& text) {
    std::string path = dir + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

}  // namespace whitted::test
