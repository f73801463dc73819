#pragma once
#include <optional>
#include <string_view>

namespace whitted {

// whitted: full lighting; raycast: the unlit diffuse colour; normals / depth: debugging views;
// path: physically based path tracing (scene-format.md §9.2).
enum class RenderMode { Whitted, Raycast, Normals, Depth, Path };

std::optional<RenderMode> parse_render_mode(std::string_view name);
const char* render_mode_name(RenderMode mode);

}  // namespace whitted
