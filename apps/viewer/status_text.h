#pragma once
// The status bar's texts for a render's status: what was loaded, and how far the render is.
// Display-free (the window puts them into its fields).
#include <optional>
#include <string>

#include "render_controller.h"

namespace whitted::viewer {

// ": 5 objects, 2 lights (labs)" once a load has counted them, else "".
std::string load_summary(const RenderStatus& st);

// "rendering 320×240: 40% (12/30 tiles), 1.2 s", "done 320×240 in 0.50 s", "the scene has errors", ...
std::string progress_text(const RenderStatus& st);

// What a render of the scene cannot show at its settings (sampled_effects_hint), once it renders;
// "" otherwise. For the status bar when there is no message.
std::string render_hint(const RenderStatus& st);

// The pixel under the pointer: "x 10  y 20   RGB 255 128 0", and its radiance when given (path
// mode's values above 1 that the bytes clip): "   linear 4.000 0.513 0". "" off the image.
std::string pixel_readout(const Image& image, int x, int y, const std::optional<glm::vec3>& linear = std::nullopt);

}  // namespace whitted::viewer
