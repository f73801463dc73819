#pragma once
// What the image view draws of a pixel's ray tree (inspect/ray_tree.h): its segments up to a depth,
// projected into the image with the render's camera, coloured by kind (camera white, reflected blue,
// refracted orange; a shadow ray green when it reaches the light, red when blocked, yellow tinted
// by the glass it passes), with marks at the hits, the blockers, the lights and where total internal
// reflection happens. Image pixel coordinates (from the image's top-left corner, row 0 at the top).
// Display-free.
#include <vector>

#include <glm/glm.hpp>

#include "inspect/ray_tree.h"

namespace whitted::viewer {

struct OverlayLine {
    glm::vec2 a{0.0f}, b{0.0f};
    glm::u8vec3 color{0};
    RayKind kind = RayKind::Camera;
    int depth = 0;
};

enum class MarkShape { Hit, Blocked, Light, TotalInternalReflection };
const char* mark_shape_name(MarkShape shape);  // "hit", "blocked", "light", "tir"

struct OverlayMark {
    glm::vec2 at{0.0f};
    glm::u8vec3 color{0};
    MarkShape shape = MarkShape::Hit;
};

struct RayOverlay {
    std::vector<OverlayLine> lines;
    std::vector<OverlayMark> marks;
    bool empty() const { return lines.empty() && marks.empty(); }
};

glm::u8vec3 ray_color(const RaySegment& segment);

// The segments of `tree` whose depth is at most `max_depth`. A camera ray is seen end on (it
// projects to its pixel): only its hit is marked.
RayOverlay ray_overlay(const RayTree& tree, int max_depth);

}  // namespace whitted::viewer
