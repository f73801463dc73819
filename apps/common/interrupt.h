#pragma once
// Ctrl-C handling: the first SIGINT asks the load or the render to stop (a partial image is
// still written); a second one exits at once, removing an image file only partly written.
#include <atomic>

namespace whitted::cli {

void install_interrupt_handler();
const std::atomic<bool>& interrupt_flag();

}  // namespace whitted::cli
