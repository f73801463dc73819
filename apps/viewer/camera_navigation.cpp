#include "camera_navigation.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "flatten/flatten.h"

namespace whitted::viewer {
namespace {

// The camera's own axes, as the renderer makes them (make_camera).
struct Axes {
    glm::vec3 forward, right, up;
};
Axes axes(const CameraDesc& c) {
    const Camera cam = make_camera(c);
    return {cam.forward, cam.right, cam.up};
}

glm::vec3 rotate(const glm::vec3& v, const glm::vec3& axis, float radians) {
    return glm::vec3(glm::rotate(glm::mat4(1.0f), radians, glm::normalize(axis)) * glm::vec4(v, 0.0f));
}

}  // namespace

CameraDesc navigable(const CameraDesc& file) {
    CameraDesc c = file;
    if (!c.use_focus) {
        const glm::vec3 dir = glm::normalize(c.look);
        const float along = glm::dot(-c.eye, dir);  // where the origin projects onto the view line
        c.focus = c.eye + dir * (along > 1e-3f ? along : 1.0f);
        c.use_focus = true;
    }
    return c;
}

float focus_distance(const CameraDesc& c) { return glm::length(c.focus - c.eye); }

CameraDesc orbit(const CameraDesc& c, float dx, float dy) {
    CameraDesc out = c;
    const glm::vec3 world_up = glm::normalize(c.up);
    glm::vec3 offset = c.eye - c.focus;
    // Yaw about the world's up, through the focus point; dragging right turns the scene right.
    offset = rotate(offset, world_up, -glm::radians(dx * kOrbitDegreesPerPixel));
    // Tilt about the camera's right axis, within 1 degree of either pole.
    const float dist = glm::length(offset);
    const float polar = std::acos(std::clamp(glm::dot(offset / dist, world_up), -1.0f, 1.0f));
    const float lo = glm::radians(1.0f), hi = glm::radians(179.0f);
    const float target = std::clamp(polar - glm::radians(dy * kOrbitDegreesPerPixel), lo, hi);
    const glm::vec3 right = glm::cross(-offset, world_up);
    if (glm::length(right) > 0.0f) offset = rotate(offset, right, target - polar);
    out.eye = c.focus + offset;
    return out;
}

CameraDesc pan(const CameraDesc& c, float dx, float dy, int image_height) {
    const Axes a = axes(c);
    // Pixels to world units on the plane through the focus point.
    const float per_pixel =
        2.0f * focus_distance(c) * std::tan(glm::radians(c.angle_deg) * 0.5f) / float(std::max(1, image_height));
    const glm::vec3 move = (-dx * a.right + dy * a.up) * per_pixel;
    CameraDesc out = c;
    out.eye += move;
    out.focus += move;
    return out;
}

CameraDesc dolly(const CameraDesc& c, float steps) {
    CameraDesc out = c;
    const float scale = std::pow(0.9f, steps);
    const glm::vec3 offset = (c.eye - c.focus) * scale;
    if (glm::length(offset) > 1e-4f && std::isfinite(glm::length(offset))) out.eye = c.focus + offset;
    return out;
}

CameraDesc change_fov(const CameraDesc& c, float steps) {
    CameraDesc out = c;
    out.angle_deg = std::clamp(c.angle_deg / std::pow(1.1f, steps), 1.0f, 170.0f);
    return out;
}

CameraDesc fly(const CameraDesc& c, char key, float fraction) {
    const Axes a = axes(c);
    glm::vec3 dir{0.0f};
    switch (key) {
        case 'w': case 'W': dir = a.forward; break;
        case 's': case 'S': dir = -a.forward; break;
        case 'a': case 'A': dir = -a.right; break;
        case 'd': case 'D': dir = a.right; break;
        case 'q': case 'Q': dir = -a.up; break;
        case 'e': case 'E': dir = a.up; break;
        default: return c;
    }
    const glm::vec3 move = dir * (fraction * focus_distance(c));
    CameraDesc out = c;
    out.eye += move;
    out.focus += move;
    return out;
}

}  // namespace whitted::viewer
