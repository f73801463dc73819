#pragma once
#include <optional>
#include <string_view>

namespace whitted {

// whitted: full lighting; raycast: the unlit diffuse colour; normals / depth: debugging views.
enum class RenderMode { Whitted, Raycast, Normals, Depth };

std::optional<RenderMode> parse_render_mode(std::string_view name);
const char* render_mode_name(RenderMode mode);

}  // namespace whitted
