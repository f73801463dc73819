#pragma once
// Runs a program as a child process and collects its exit code and stderr, for frontend tests.
#include <string>
#include <vector>

namespace whitted::test {

struct ProcessResult {
    int exit_code = -1;  // 128 + signal if killed by a signal
    std::string output;  // stdout and stderr together
};

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
