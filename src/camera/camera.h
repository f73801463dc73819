#pragma once
// The camera: a value handed to each render (the file's camera, or one the viewer moved), not
// part of the scene. A pinhole, or a thin lens (scene-format.md §9.1): a lens ray starts at a
// point of the lens disc and passes through the point where the pinhole ray of the same image
// position meets the plane in focus.
#include <glm/glm.hpp>

#include "shapes/ray.h"

namespace whitted {

struct Camera {
    glm::vec3 eye{0, 0, 1};
    glm::vec3 forward{0, 0, -1}, right{1, 0, 0}, up{0, 1, 0};  // orthonormal
    float tan_half_fov = 0.57735f;  // vertical
    float lens_radius = 0.0f;       // aperture / 2; 0 = pinhole
    float focal_distance = 1.0f;    // along forward, to the plane in focus

    // The ray through the point (x, y) of a width × height image, in pixels from the top left
    // corner (a pixel's centre is at +0.5; row 0 is the top), from the lens point that `lens`
    // (in [0, 1)², (0.5, 0.5) = the lens centre) picks. A pinhole ignores `lens`.
    Ray generate_ray(int width, int height, float x, float y, glm::vec2 lens) const;
    bool is_pinhole() const { return !(lens_radius > 0.0f); }
};

}  // namespace whitted
