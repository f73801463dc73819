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

RayDifferential Camera::differential(const Ray& ray, float pitch) const {
    // Where the ray meets the plane in focus (a pinhole's rays all start at the eye, so any plane
    // will do: the one at distance 1). The ray starts on the lens plane, through the eye.
    const float plane = is_pinhole() ? 1.0f : focal_distance;
    const glm::vec3 focus =
        ray.origin + ray.direction * ((plane - glm::dot(ray.origin - eye, forward)) / glm::dot(ray.direction, forward));
    RayDifferential d;
    d.x = Ray{ray.origin, glm::normalize(focus + plane * pitch * right - ray.origin)};
    d.y = Ray{ray.origin, glm::normalize(focus - plane * pitch * up - ray.origin)};  // row y + 1 is lower
    return d;
}

}  // namespace whitted
