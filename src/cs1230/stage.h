#pragma once
// The course's two ray-tracing projects (scene-format.md §9.5), which draw the same files
// differently: Intersect is Phong lighting from directional lights only (point and spot lights are
// ignored), without shadows, reflections or textures; Illuminate draws everything.
#include <optional>
#include <string_view>

namespace whitted::cs1230 {

enum class Stage : unsigned char { Illuminate, Intersect };

std::optional<Stage> parse_stage(std::string_view name);  // "illuminate", "intersect"
const char* stage_name(Stage stage);

}  // namespace whitted::cs1230
