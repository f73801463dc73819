#include "integrator/whitted_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "integrator/light_sample.h"
#include "integrator/surface.h"

namespace whitted {
namespace {

constexpr float kMinWeight = 1.0f / 256.0f;  // spec §7: rays weighing less are not traced
constexpr float kInfinity = std::numeric_limits<float>::infinity();

float max_component(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

// Refracts unit direction d through a surface with unit normal n facing d's origin side,
// eta = n_from / n_to. Returns false on total internal reflection.
bool refract(const glm::vec3& d, const glm::vec3& n, float eta, glm::vec3& out) {
    float cos_i = -glm::dot(n, d);
    float k = 1.0f - eta * eta * (1.0f - cos_i * cos_i);
    if (k < 0.0f) return false;
    out = glm::normalize(eta * d + (eta * cos_i - std::sqrt(k)) * n);
    return true;
}

// The range every nearest-hit query searches, one ray at a time or a packet at a time: anything
// in front of the ray's origin.
constexpr float kHitMin = 0.0f, kHitMax = kInfinity;

bool nearest_hit(const Scene& scene, const Ray& ray, Hit& hit) {
    return intersect_nearest(scene.bvh, scene.flat.instances, ray, kHitMin, kHitMax, hit);
}

}  // namespace

WhittedIntegrator::WhittedIntegrator(const Scene& scene, const IntegratorOptions& options)
    : scene_(scene), options_(options) {
    if (options_.mode == RenderMode::Depth && !scene.bvh.nodes.empty()) {
        // Shade the scene's own distance range from the eye: near = white, far = black.
        Bounds b = scene.bvh.bounds();
        glm::vec3 eye = scene.flat.camera.eye;
        glm::vec3 nearest = glm::clamp(eye, b.lo, b.hi);
        depth_near_ = glm::length(nearest - eye);
        float far = 0;
        for (int i = 0; i < 8; ++i) {
            glm::vec3 c((i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z);
            far = std::max(far, glm::length(c - eye));
        }
        depth_far_ = std::max(far, depth_near_ + 1e-6f);
    }
}

glm::vec3 WhittedIntegrator::camera_ray(const Ray& ray, RayCounts& counts) const {
    Hit hit;
    return camera_ray(ray, nearest_hit(scene_, ray, hit) ? &hit : nullptr, counts);
}

unsigned WhittedIntegrator::camera_hits(const Ray (&rays)[kPacketSize], unsigned active, Hit (&hits)[kPacketSize]) const {
    return intersect_nearest_packet(scene_.bvh, scene_.flat.instances, rays, active, kHitMin, kHitMax, hits);
}

glm::vec3 WhittedIntegrator::camera_ray(const Ray& ray, const Hit* first_hit, RayCounts& counts) const {
    ++counts.camera;
    if (options_.mode != RenderMode::Whitted) return debug_view(ray, first_hit);
    return shade(ray, first_hit, 0, glm::vec3(1.0f), counts);
}

glm::vec3 WhittedIntegrator::debug_view(const Ray& ray, const Hit* hit) const {
    if (!hit) return options_.mode == RenderMode::Raycast ? scene_.flat.background : glm::vec3(0.0f);
    Surface s = surface_at(scene_, ray, *hit);
    switch (options_.mode) {
        case RenderMode::Raycast: return s.diffuse;
        case RenderMode::Normals: return 0.5f * (s.normal + 1.0f);
        case RenderMode::Depth: {
            float d = hit->t * glm::length(ray.direction);
            return glm::vec3(1.0f - std::clamp((d - depth_near_) / (depth_far_ - depth_near_), 0.0f, 1.0f));
        }
        case RenderMode::Whitted: break;
    }
    return glm::vec3(0.0f);
}

glm::vec3 WhittedIntegrator::trace(const Ray& ray, int depth, const glm::vec3& weight, RayCounts& counts) const {
    Hit hit;
    return shade(ray, nearest_hit(scene_, ray, hit) ? &hit : nullptr, depth, weight, counts);
}

// The colour along `ray` given its nearest hit (nullptr: none), at recursion depth `depth`.
glm::vec3 WhittedIntegrator::shade(const Ray& ray, const Hit* nearest, int depth, const glm::vec3& weight,
                                   RayCounts& counts) const {
    const FlatScene& flat = scene_.flat;
    if (!nearest) return flat.background;
    const Hit& hit = *nearest;
    const Surface s = surface_at(scene_, ray, hit);
    const Material& m = *s.material;
    const glm::vec3 dir = glm::normalize(ray.direction);
    const glm::vec3 to_eye = -dir;
    const bool outside = glm::dot(s.normal, to_eye) >= 0.0f;
    const glm::vec3 n = outside ? s.normal : -s.normal;  // faces the viewer: lighting only
    const float offset = surface_offset(s.point);
    const glm::vec3 above = s.point + offset * n;  // the viewer's side of the surface
    const glm::vec3 below = s.point - offset * n;

    glm::vec3 color = m.emit + s.ambient * flat.ambient_intensity;

    for (const Light& light : flat.lights) {
        LightSample ls = sample_light(light, s.point);
        float n_dot_l = glm::dot(n, ls.to_light);
        if (n_dot_l <= 0.0f || max_component(ls.intensity) <= 0.0f) continue;
        ++counts.shadow;
        // The shadow ray starts on the lit side and stops short of a point or spot light.
        glm::vec3 start = above;
        float reach = std::isinf(ls.distance) ? kInfinity : glm::length(light.position - start);
        glm::vec3 shadow = transmittance(scene_.bvh, flat.instances, flat.materials, Ray{start, ls.to_light}, 0.0f, reach);
        if (max_component(shadow) <= 0.0f) continue;
        glm::vec3 r = 2.0f * n_dot_l * n - ls.to_light;
        float r_dot_v = glm::dot(r, to_eye);
        float spec = r_dot_v > 0.0f ? std::pow(r_dot_v, m.shine) : 0.0f;
        color += shadow * ls.intensity * (s.diffuse * n_dot_l + m.specular * spec);
    }

    if (depth >= options_.max_depth) return color;

    glm::vec3 reflect_weight = m.reflect;
    if (m.is_transparent()) {
        // Snell's law against an outside of ior 1 (spec §7), using the true outward normal.
        float eta = outside ? 1.0f / m.ior : m.ior;
        glm::vec3 refracted;
        if (refract(dir, n, eta, refracted)) {
            glm::vec3 w = weight * m.transparent;
            if (max_component(w) >= kMinWeight) {
                ++counts.refracted;
                color += m.transparent * trace(Ray{below, refracted}, depth + 1, w, counts);
            }
        } else {
            reflect_weight += m.transparent;  // total internal reflection: one mirror ray carries both
        }
    }
    if (max_component(reflect_weight) > 0.0f) {
        glm::vec3 w = weight * reflect_weight;
        if (max_component(w) >= kMinWeight) {
            ++counts.reflected;
            glm::vec3 mirrored = dir - 2.0f * glm::dot(dir, n) * n;
            color += reflect_weight * trace(Ray{above, mirrored}, depth + 1, w, counts);
        }
    }
    return color;
}

}  // namespace whitted
