#include "integrator/render_mode.h"

namespace whitted {

std::optional<RenderMode> parse_render_mode(std::string_view name) {
    if (name == "whitted") return RenderMode::Whitted;
    if (name == "raycast") return RenderMode::Raycast;
    if (name == "normals") return RenderMode::Normals;
    if (name == "depth") return RenderMode::Depth;
    if (name == "path") return RenderMode::Path;
    return std::nullopt;
}

const char* render_mode_name(RenderMode mode) {
    switch (mode) {
        case RenderMode::Whitted: return "whitted";
        case RenderMode::Raycast: return "raycast";
        case RenderMode::Normals: return "normals";
        case RenderMode::Depth: return "depth";
        case RenderMode::Path: return "path";
    }
    return "?";
}

}  // namespace whitted
