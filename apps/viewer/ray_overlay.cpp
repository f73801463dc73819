#include "ray_overlay.h"

#include <algorithm>

namespace whitted::viewer {

const char* mark_shape_name(MarkShape shape) {
    switch (shape) {
        case MarkShape::Hit: return "hit";
        case MarkShape::Blocked: return "blocked";
        case MarkShape::Light: return "light";
        case MarkShape::TotalInternalReflection: return "tir";
    }
    return "?";
}

glm::u8vec3 ray_color(const RaySegment& s) {
    switch (s.kind) {
        case RayKind::Camera: return {255, 255, 255};
        case RayKind::Reflected: return {60, 140, 255};
        case RayKind::Refracted: return {255, 150, 30};
        case RayKind::Shadow: break;
    }
    if (s.shadow == ShadowState::Lit) return {40, 220, 40};
    if (s.shadow == ShadowState::Blocked) return {230, 30, 30};
    // Yellow, in the glass's colour (its brightest channel at full).
    const float top = std::max({s.tint.x, s.tint.y, s.tint.z, 1e-6f});
    const glm::vec3 c = glm::vec3(230, 230, 60) * (s.tint / top);
    return glm::u8vec3(glm::clamp(c + 0.5f, 0.0f, 255.0f));
}

RayOverlay ray_overlay(const RayTree& tree, int max_depth) {
    RayOverlay o;
    const auto at = [&](const glm::vec3& p) { return project_point(tree.camera, tree.width, tree.height, p); };
    const auto inside = [&](const glm::vec2& p) {
        return p.x >= 0 && p.y >= 0 && p.x <= float(tree.width) && p.y <= float(tree.height);
    };
    for (const RaySegment& s : tree.segments) {
        if (s.depth > max_depth) continue;
        const glm::u8vec3 color = ray_color(s);
        if (s.kind != RayKind::Camera)
            if (const auto seg = project_segment(tree.camera, tree.width, tree.height, s.from, s.to))
                o.lines.push_back({seg->a, seg->b, color, s.kind, s.depth});
        if (s.total_internal_reflection)
            if (const auto p = at(s.from); p && inside(*p)) o.marks.push_back({*p, {255, 230, 0}, MarkShape::TotalInternalReflection});
        const MarkShape end = s.kind != RayKind::Shadow             ? MarkShape::Hit
                              : s.shadow == ShadowState::Blocked ? MarkShape::Blocked
                                                                 : MarkShape::Light;
        if ((s.hit || (s.kind == RayKind::Shadow && !s.escaped)))
            if (const auto p = at(s.to); p && inside(*p)) o.marks.push_back({*p, color, end});
    }
    return o;
}

}  // namespace whitted::viewer
