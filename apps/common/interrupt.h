#pragma once
// Ctrl-C handling: the first SIGINT, SIGTERM, SIGHUP or SIGQUIT asks the load or the render to stop
// (a partial image is still written, beside the output); a second one exits at once, removing an
// image file only partly written. SIGXFSZ is ignored: a write over `ulimit -f` fails and is cleaned up.
#include <atomic>

namespace whitted::cli {

void install_interrupt_handler();
const std::atomic<bool>& interrupt_flag();

// --timeout: after `seconds`, stops the load or the render as an interrupt would (timed_out()
// then says why). The watch ends with the object.
class Deadline {
public:
    explicit Deadline(double seconds);  // <= 0: no deadline
    ~Deadline();
    Deadline(const Deadline&) = delete;
    Deadline& operator=(const Deadline&) = delete;
    bool timed_out() const;

private:
    struct State;
    State* state_;
};

}  // namespace whitted::cli
