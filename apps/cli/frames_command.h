#pragma once
// whitted --frames A..B: the frames of an animation, one numbered image file each.
#include "render_options.h"

namespace whitted::cli {

// Renders every frame of o.settings.frames whose file does not exist yet (those that do are
// skipped, saying so), frame n at scene time n / fps; returns the exit code. A scene that does
// not move is read once; one that moves is read again at each frame's time (the parser fixes it).
int render_frames(const RenderOptions& o);

}  // namespace whitted::cli
