#include "support/run_process.h"

#include <fcntl.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <thread>

namespace whitted::test {

namespace {

[[noreturn]] void exec_child(const std::vector<std::string>& argv) {
    std::vector<char*> args;
    for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
}

void read_all(int fd, std::string& out) {
    char buf[4096];
    for (ssize_t n; (n = read(fd, buf, sizeof buf)) > 0;) out.append(buf, size_t(n));
}

int exit_code_of(pid_t pid) {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

ProcessResult run_process(const std::vector<std::string>& argv, int interrupt_after_ms) {
    return run_process(argv, interrupt_after_ms >= 0 ? std::vector<int>{interrupt_after_ms} : std::vector<int>{});
}

ProcessResult run_in_terminal(const std::vector<std::string>& argv, int columns) {
    ProcessResult result;
    int master = -1;
    struct winsize size {};
    size.ws_row = 24;
    size.ws_col = static_cast<unsigned short>(columns);
    pid_t pid = forkpty(&master, nullptr, nullptr, &size);
    if (pid < 0) return result;
    if (pid == 0) exec_child(argv);
    read_all(master, result.output);  // ends with EIO once the child has gone
    close(master);
    result.exit_code = exit_code_of(pid);
    return result;
}

ProcessResult run_process(const std::vector<std::string>& argv, const std::vector<int>& interrupts_ms) {
    std::vector<TimedSignal> signals;
    for (int ms : interrupts_ms) signals.push_back({ms, SIGINT});
    return run_process(argv, signals);
}

ProcessResult run_process(const std::vector<std::string>& argv, const std::vector<TimedSignal>& signals) {
    ProcessResult result;
    int pipe_fd[2];
    if (pipe(pipe_fd) != 0) return result;
    pid_t pid = fork();
    if (pid == 0) {
        dup2(pipe_fd[1], STDOUT_FILENO);
        dup2(pipe_fd[1], STDERR_FILENO);
        close(pipe_fd[0]);
        close(pipe_fd[1]);
        exec_child(argv);
    }
    close(pipe_fd[1]);
    std::thread interrupter;
    std::atomic<bool> exited{false};
    if (!signals.empty())
        interrupter = std::thread([pid, signals, &exited] {
            const auto start = std::chrono::steady_clock::now();
            for (const TimedSignal& s : signals) {
                // Sleeps in short steps so that a finished child does not keep the test waiting
                // for a last SIGKILL meant only for a hang.
                const auto when = start + std::chrono::milliseconds(s.ms);
                while (!exited && std::chrono::steady_clock::now() < when)
                    std::this_thread::sleep_for(std::min<std::chrono::steady_clock::duration>(
                        when - std::chrono::steady_clock::now(), std::chrono::milliseconds(20)));
                if (exited) return;
                kill(pid, s.signal);  // harmless once the child has exited: it stays a zombie until waited for
            }
        });
    read_all(pipe_fd[0], result.output);
    close(pipe_fd[0]);
    exited = true;  // (or at least closed its output: what is left is waiting for it)
    if (interrupter.joinable()) interrupter.join();
    result.exit_code = exit_code_of(pid);
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
