#include "camera/camera.h"

#include "sampler/warp.h"

namespace whitted {

Ray Camera::generate_ray(int width, int height, float x, float y, glm::vec2 lens) const {
    // The lens centre is the pinhole: the same ray to the bit (one sample per pixel, §9.1).
    if (is_pinhole() || lens == glm::vec2(0.5f)) return pinhole_ray(width, height, x, y);
    const glm::vec2 d = lens_radius * concentric_disc(lens);
    const glm::vec3 origin = eye + d.x * right + d.y * up;
    const glm::vec3 in_focus = eye + focal_distance * through(width, height, x, y);
    return Ray{origin, glm::normalize(in_focus - origin)};
}

}  // namespace whitted
