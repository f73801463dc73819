#include "session/image_text.h"

#include <string>

namespace whitted {

ImageText render_image_text(const RenderSettings& settings, int samples, int passes_done, int passes_total) {
    return {{"Software", "whitted 0.1.0"},
            {"whitted:samples", std::to_string(samples)},
            {"whitted:passes", std::to_string(passes_done) + " of " + std::to_string(passes_total)},
            {"whitted:settings", pixel_key(settings)}};
}

}  // namespace whitted
