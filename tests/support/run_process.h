#pragma once
// Runs a program as a child process and collects its exit code and stderr, for frontend tests.
#include <sys/types.h>

#include <chrono>
#include <string>
#include <vector>

namespace whitted::test {

struct ProcessResult {
    int exit_code = -1;  // 128 + signal if killed by a signal
    std::string output;  // stdout and stderr together
};

// A process run by run_process that has not exited after this long is killed (SIGKILL, exit
// code 137) and its output says so: a hang fails the test instead of holding it to ctest's timeout.
constexpr int kProcessDeadlineSeconds = 300;

// Runs argv[0] with argv; if interrupt_after_ms >= 0, sends SIGINT after that many milliseconds.
ProcessResult run_process(const std::vector<std::string>& argv, int interrupt_after_ms = -1);
// The same, sending SIGINT at each of the given times (milliseconds from the start, increasing).
ProcessResult run_process(const std::vector<std::string>& argv, const std::vector<int>& interrupts_ms);
// The same, sending each signal at its time (milliseconds from the start, increasing); a last
// {ms, SIGKILL} bounds a test whose program might hang.
struct TimedSignal {
    int ms;
    int signal;
};
ProcessResult run_process(const std::vector<std::string>& argv, const std::vector<TimedSignal>& signals);
// Runs argv with a pseudo-terminal as its stdin, stdout and stderr, as a user's shell would.
ProcessResult run_in_terminal(const std::vector<std::string>& argv, int columns = 80);

// A child process left running while the test watches it, its stdout and stderr going to a
// file. Every wait has a deadline, so that a bug makes a test fail instead of hang.
class BackgroundProcess {
public:
    BackgroundProcess(const std::vector<std::string>& argv, const std::string& log_path);
    ~BackgroundProcess();  // kills (SIGKILL) and reaps it if it still runs
    BackgroundProcess(const BackgroundProcess&) = delete;
    BackgroundProcess& operator=(const BackgroundProcess&) = delete;

    pid_t pid() const { return pid_; }
    // Waits until the process has a handler installed for `signal` (/proc/PID/status SigCgt).
    bool wait_until_it_catches(int signal, std::chrono::milliseconds timeout) const;
    // Waits until a thread other than the main one has used at least `cpu` of processor time
    // (/proc/PID/task/*/stat): a worker thread is well into its work.
    bool wait_until_a_second_thread_ran(std::chrono::milliseconds cpu, std::chrono::milliseconds timeout) const;
    // Sends `signal` and waits until it is no longer pending, i.e. a thread has taken it.
    bool signal_and_wait_delivered(int signal, std::chrono::milliseconds timeout) const;
    // Its exit code (128 + signal if killed), or -1 if it still runs after `timeout`.
    int wait_exit(std::chrono::milliseconds timeout);
    std::string output() const;

private:
    pid_t pid_ = -1;
    std::string log_;
};

// Paths the tests need.
std::string cli_path();
std::string source_dir();
// The shared corpus folder (…/shared), or "" when it is not there.
std::string shared_dir();
// A fresh empty directory for one test.
std::string make_temp_dir();
// Writes `text` to dir/name and returns that path.
std::string write_file(const std::string& dir, const std::string& name, const std::string& text);

}  // namespace whitted::test
