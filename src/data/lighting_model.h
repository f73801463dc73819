#pragma once
// Which lighting equation a scene is drawn with: the labs' (scene-format.md §7) or Brown CSCI
// 1230's (§9.5: global coefficients, min(1, 1/att), smooth spot falloff, opaque shadows, the
// reflection clamped per level, colours truncated to bytes). Set by the file's reader.

namespace whitted {

enum class LightingModel : unsigned char { Labs, Cs1230 };

}  // namespace whitted
