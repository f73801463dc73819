#include "interrupt.h"

#include <csignal>
#include <unistd.h>

#include "film/image_io.h"

namespace whitted::cli {
namespace {

std::atomic<bool> g_interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free, "the flag is set from a signal handler");

extern "C" void on_sigint(int) {
    if (g_interrupted.exchange(true)) {
        const char msg[] = "\nwhitted: interrupted twice, exiting now\n";
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
    sigaction(SIGINT, &sa, nullptr);
    sigaction(SIGTERM, &sa, nullptr);
}

const std::atomic<bool>& interrupt_flag() { return g_interrupted; }

}  // namespace whitted::cli
