#pragma once
// Ctrl-C handling: the first SIGINT asks the render to stop (the partial image is still
// written); a second one exits at once.
#include <atomic>

namespace whitted::cli {

void install_interrupt_handler();
const std::atomic<bool>& interrupt_flag();

}  // namespace whitted::cli
