#include "integrator/debug_views.h"

#include <algorithm>
#include <bit>

#include "integrator/surface.h"

namespace whitted {

void HitViewIntegrator::radiance(const CameraBatch& batch, const Sampler&, glm::vec3 (&out)[kPacketSize],
                                 RayCounts& counts) const {
    Hit hits[kPacketSize];
    const unsigned found = timed_trace(counts, RayKind::Camera, std::popcount(batch.active),
                                       [&] { return scene_.intersect(batch.rays, batch.active, hits); });
    for (int l = 0; l < kPacketSize; ++l) {
        if (!((batch.active >> l) & 1)) continue;
        ++counts.camera;
        out[l] = (found >> l) & 1 ? hit_color(batch.rays[l], hits[l]) : miss_color();
    }
}

glm::vec3 RaycastIntegrator::hit_color(const Ray& ray, const Hit& hit) const {
    return surface_at(scene_, ray, hit).diffuse;
}

glm::vec3 NormalsIntegrator::hit_color(const Ray& ray, const Hit& hit) const {
    return 0.5f * (surface_at(scene_, ray, hit).normal + 1.0f);
}

DepthIntegrator::DepthIntegrator(const Scene& scene, const Camera& camera) : HitViewIntegrator(scene, camera) {
    if (scene.bvh.empty() && scene.motion.empty()) return;
    // Shade the scene's own distance range from the eye: near = white, far = black.
    const Bounds b = scene.bounds();
    const glm::vec3 eye = camera.eye;
    near_ = glm::length(glm::clamp(eye, b.lo, b.hi) - eye);
    float far = 0;
    for (int i = 0; i < 8; ++i) {
        glm::vec3 c((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
        far = std::max(far, glm::length(c - eye));
    }
    far_ = std::max(far, near_ + 1e-6f);
}

glm::vec3 DepthIntegrator::hit_color(const Ray& ray, const Hit& hit) const {
    const float d = hit.t * glm::length(ray.direction);
    return glm::vec3(1.0f - std::clamp((d - near_) / (far_ - near_), 0.0f, 1.0f));
}

}  // namespace whitted
