#include "camera/camera.h"

#include "sampler/warp.h"

namespace whitted {

Ray Camera::generate_ray(int width, int height, float x, float y, glm::vec2 lens) const {
    const float aspect = float(width) / float(height);
    const float sx = (2.0f * x / float(width) - 1.0f) * tan_half_fov * aspect;
    const float sy = (1.0f - 2.0f * y / float(height)) * tan_half_fov;
    const glm::vec3 through = forward + sx * right + sy * up;  // its forward component is 1
    // The lens centre is the pinhole: the same ray to the bit (one sample per pixel, §9.1).
    if (is_pinhole() || lens == glm::vec2(0.5f)) return Ray{eye, glm::normalize(through)};
    const glm::vec2 d = lens_radius * concentric_disc(lens);
    const glm::vec3 origin = eye + d.x * right + d.y * up;
    const glm::vec3 in_focus = eye + focal_distance * through;
    return Ray{origin, glm::normalize(in_focus - origin)};
}

}  // namespace whitted
