#include "interrupt.h"

#include <chrono>
#include <condition_variable>
#include <csignal>
#include <mutex>
#include <thread>
#include <unistd.h>

#include "film/image_io.h"

namespace whitted::cli {
namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");

extern "C" void on_sigint(int) {
    if (g_interrupted.exchange(true)) {
        const char msg[] = "\nwhitted: interrupted twice, exiting now\n";  // (any two of the signals)
        (void)!write(STDERR_FILENO, msg, sizeof msg - 1);
        if (const char* partial = image_file_being_written()) unlink(partial);  // never leave half a file
        _exit(130);
    }
}

}  // namespace

void install_interrupt_handler() {
    struct sigaction sa {};
    sa.sa_handler = on_sigint;
    sigemptyset(&sa.sa_mask);
    // Ctrl-C, a batch system's timeout (TERM), a closed terminal (HUP), Ctrl-\\ (QUIT): all stop
    // the render the same way, and none may leave a temporary file behind.
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT}) sigaction(sig, &sa, nullptr);
    // A file size limit (`ulimit -f`): the write fails with EFBIG and is cleaned up like any
    // failed write, instead of the process dying in it and leaving its temporary file.
    signal(SIGXFSZ, SIG_IGN);
}

const std::atomic<bool>& interrupt_flag() { return g_interrupted; }

struct Deadline::State {
    std::mutex mutex;
    std::condition_variable done;
    bool finished = false;
    std::atomic<bool> fired{false};
    std::thread watch;
};

Deadline::Deadline(double seconds) : state_(new State) {
    if (seconds <= 0) return;
    state_->watch = std::thread([s = state_, seconds] {
        std::unique_lock lock(s->mutex);
        if (s->done.wait_for(lock, std::chrono::duration<double>(seconds), [s] { return s->finished; })) return;
        s->fired = true;
        g_interrupted = true;  // as a first Ctrl-C: the load or the render stops, the part done is kept
    });
}

Deadline::~Deadline() {
    {
        std::lock_guard lock(state_->mutex);
        state_->finished = true;
    }
    state_->done.notify_all();
    if (state_->watch.joinable()) state_->watch.join();
    delete state_;
}

bool Deadline::timed_out() const { return state_->fired; }

}  // namespace whitted::cli
