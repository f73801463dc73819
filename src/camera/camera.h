#pragma once
// The camera: a value handed to each render (the file's camera, or one the viewer moved), not
// part of the scene. A pinhole, or a thin lens (scene-format.md §9.1): a lens ray starts at a
// point of the lens disc and passes through the point where the pinhole ray of the same image
// position meets the plane in focus.
#include <glm/glm.hpp>

#include "base/ray.h"
#include "base/ray_differential.h"

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
    // The pinhole ray (also the lens centre's, to the bit): inline, as it is the ray of every
    // one-sample render.
    Ray pinhole_ray(int width, int height, float x, float y) const {
        return Ray{eye, glm::normalize(through(width, height, x, y))};
    }
    // The point of the plane at distance 1 along `forward` that image position (x, y) shows.
    glm::vec3 through(int width, int height, float x, float y) const {
        const float aspect = float(width) / float(height);
        const float sx = (2.0f * x / float(width) - 1.0f) * tan_half_fov * aspect;
        const float sy = (1.0f - 2.0f * y / float(height)) * tan_half_fov;
        return forward + sx * right + sy * up;  // its forward component is 1
    }
    // The auxiliary rays of `ray` (one this camera made): through the image positions `pitch`
    // further right and down on the plane at distance 1 (2·tan_half_fov / rows for a pixel of an
    // image `rows` high), from the same lens point, so through the same point of the plane in focus.
    RayDifferential differential(const Ray& ray, float pitch) const;
    bool is_pinhole() const { return !(lens_radius > 0.0f); }
    bool operator==(const Camera&) const = default;
};

}  // namespace whitted
