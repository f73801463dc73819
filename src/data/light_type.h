#pragma once
// The three kinds of light of scene-format.md §6, shared by the file's description and the
// render-ready data.

namespace whitted {

enum class LightType { Point, Directional, Spot };

}  // namespace whitted
