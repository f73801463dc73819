#include "support/run_process.h"

#include <fcntl.h>
#include <poll.h>
#include <pty.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
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

// Reads fd to its end, or until `deadline`; then kills `pid` (a child that hangs fails its test
// with a message instead of holding it until ctest's timeout). Returns false if it had to.
bool read_all_until(int fd, std::string& out, pid_t pid, std::chrono::steady_clock::time_point deadline) {
    char buf[4096];
    for (;;) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        pollfd p{fd, POLLIN, 0};
        const int ready = left.count() > 0 ? poll(&p, 1, int(std::min<long long>(left.count(), 1000))) : 0;
        if (ready < 0 && errno == EINTR) continue;
        if (ready == 0) {
            if (std::chrono::steady_clock::now() < deadline) continue;
            if (pid > 0) kill(pid, SIGKILL);
            out += "\n[test: killed after " + std::to_string(kProcessDeadlineSeconds) + " s without exiting]\n";
            return false;
        }
        const ssize_t n = read(fd, buf, sizeof buf);
        if (n <= 0) return true;
        out.append(buf, size_t(n));
    }
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
    if (pid < 0) {
        close(pipe_fd[0]);
        close(pipe_fd[1]);
        return result;
    }
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
    read_all_until(pipe_fd[0], result.output, pid,
                   std::chrono::steady_clock::now() + std::chrono::seconds(kProcessDeadlineSeconds));
    close(pipe_fd[0]);
    exited = true;  // (or at least closed its output: what is left is waiting for it)
    if (interrupter.joinable()) interrupter.join();
    result.exit_code = exit_code_of(pid);
    return result;
}

BackgroundProcess::BackgroundProcess(const std::vector<std::string>& argv, const std::string& log_path)
    : log_(log_path) {
    pid_ = fork();
    if (pid_ == 0) {
        const int fd = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, STDOUT_FILENO);
            dup2(fd, STDERR_FILENO);
            close(fd);
        }
        exec_child(argv);
    }
}

BackgroundProcess::~BackgroundProcess() {
    if (pid_ <= 0) return;
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
}

namespace {

// The signal mask on line `field` ("SigCgt", "ShdPnd", ...) of /proc/PID/status.
bool status_mask_has(pid_t pid, const std::string& field, int signal) {
    std::ifstream in("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(field + ":", 0) != 0) continue;
        std::istringstream hex(line.substr(field.size() + 1));
        unsigned long long mask = 0;
        hex >> std::hex >> mask;
        return (mask >> (signal - 1)) & 1;
    }
    return false;
}

template <class Done>
bool poll_until(std::chrono::milliseconds timeout, Done done) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        if (done()) return true;
        if (std::chrono::steady_clock::now() >= deadline) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
}

}  // namespace

bool BackgroundProcess::wait_until_it_catches(int signal, std::chrono::milliseconds timeout) const {
    return poll_until(timeout, [&] { return status_mask_has(pid_, "SigCgt", signal); });
}

bool BackgroundProcess::wait_until_a_second_thread_ran(std::chrono::milliseconds cpu,
                                                       std::chrono::milliseconds timeout) const {
    const long ticks_per_second = sysconf(_SC_CLK_TCK);
    const long long wanted = (cpu.count() * ticks_per_second + 999) / 1000;
    return poll_until(timeout, [&] {
        std::error_code ec;
        const std::string tasks = "/proc/" + std::to_string(pid_) + "/task";
        for (const auto& task : std::filesystem::directory_iterator(tasks, ec)) {
            if (task.path().filename() == std::to_string(pid_)) continue;  // the main thread
            std::ifstream in(task.path() / "stat");
            std::string stat((std::istreambuf_iterator<char>(in)), {});
            const std::size_t after_name = stat.rfind(')');
            if (after_name == std::string::npos) continue;
            // After "pid (comm)": state is field 3; utime and stime are fields 14 and 15.
            std::istringstream fields(stat.substr(after_name + 2));
            std::string field;
            long long utime = 0, stime = 0;
            for (int i = 3; i <= 13 && fields >> field; ++i) {
            }
            if (fields >> utime >> stime && utime + stime >= wanted) return true;
        }
        return false;
    });
}

bool BackgroundProcess::signal_and_wait_delivered(int signal, std::chrono::milliseconds timeout) const {
    if (pid_ <= 0 || kill(pid_, signal) != 0) return false;  // (pid -1 would mean every process)
    return poll_until(timeout, [&] {
        return !status_mask_has(pid_, "ShdPnd", signal) && !status_mask_has(pid_, "SigPnd", signal);
    });
}

int BackgroundProcess::wait_exit(std::chrono::milliseconds timeout) {
    int code = -1;
    poll_until(timeout, [&] {
        int status = 0;
        if (pid_ <= 0 || waitpid(pid_, &status, WNOHANG) != pid_) return false;
        pid_ = -1;
        code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
        return true;
    });
    return code;
}

std::string BackgroundProcess::output() const {
    std::ifstream in(log_);
    return {std::istreambuf_iterator<char>(in), {}};
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
