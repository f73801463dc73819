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

// Whether the shadow query may start at the light. A hit found along a ray is off by about 1e-7
// of its distance from the ray's origin; from a light far away (relative to the scene around the
// point) that error would swallow the offset that keeps the point's own surface out of the query,
// so such lights are asked from the point. Decided the same way one ray at a time and in packets.
bool WhittedIntegrator::query_from_light(const Light& light, const glm::vec3& start) {
    return light.type != LightType::Directional && glm::length(light.position - start) * 1e-6f <= surface_offset(start);
}

// What reaches `start` (just off the lit side of a surface) from `light`: 1 if nothing is in the
// way, 0 behind anything opaque, the product of the transparent colours crossed otherwise.
glm::vec3 WhittedIntegrator::shadow_factor(const Light& light, const LightSample& ls, const glm::vec3& start) const {
    const FlatScene& flat = scene_.flat;
    if (query_from_light(light, start)) {
        // From the light to the point (t in (0, 1)): the nearest thing on the way decides it,
        // unless it is glass, whose every crossing on the way counts.
        Hit h;
        if (!intersect_nearest(scene_.bvh, flat.instances, Ray{light.position, start - light.position}, 0.0f, 1.0f, h))
            return glm::vec3(1.0f);
        if (!flat.materials[flat.instances[h.instance].material].is_transparent()) return glm::vec3(0.0f);
    }
    return through_glass(light, ls, start);
}

// The full query from the point toward the light: every transparent surface crossed tints it.
glm::vec3 WhittedIntegrator::through_glass(const Light& light, const LightSample& ls, const glm::vec3& start) const {
    const FlatScene& flat = scene_.flat;
    const float reach = std::isinf(ls.distance) ? kInfinity : glm::length(light.position - start);
    return transmittance(scene_.bvh, flat.instances, flat.materials, Ray{start, ls.to_light}, 0.0f, reach);
}

void WhittedIntegrator::camera_packet(const Ray (&rays)[kPacketSize], unsigned active, const Hit (&hits)[kPacketSize],
                                      unsigned found, glm::vec3 (&colors)[kPacketSize], RayCounts& counts) const {
    if (options_.mode != RenderMode::Whitted) {
        for (int l = 0; l < kPacketSize; ++l)
            if ((active >> l) & 1) colors[l] = camera_ray(rays[l], (found >> l) & 1 ? &hits[l] : nullptr, counts);
        return;
    }
    const FlatScene& flat = scene_.flat;
    found &= active;
    ShadingPoint points[kPacketSize];
    for (int l = 0; l < kPacketSize; ++l)
        if ((found >> l) & 1) points[l] = shading_point(rays[l], hits[l]);
    // The shadow rays toward each point or spot light, traced together from the light: they share
    // their origin and fan out over neighbouring points, as coherent as the camera rays were.
    // Exactly shadow_factor's first query, so the colours are those of camera_ray one by one.
    PacketShadows shadows;
    const std::size_t packet_lights = std::min(flat.lights.size(), std::size_t(kPacketLights));
    for (std::size_t li = 0; li < packet_lights; ++li) {
        const Light& light = flat.lights[li];
        if (light.type == LightType::Directional) continue;
        Ray back[kPacketSize];
        unsigned want = 0;
        for (int l = 0; l < kPacketSize; ++l) {
            if (!((found >> l) & 1) || !faces_light(points[l], sample_light(light, points[l].s.point)) ||
                !query_from_light(light, points[l].above))
                continue;  // not lit at all, or asked from the point (shadow_factor)
            back[l] = Ray{light.position, points[l].above - light.position};
            want |= 1u << l;
        }
        if (!want) continue;
        Hit blockers[kPacketSize];
        const unsigned blocked = intersect_nearest_packet(scene_.bvh, flat.instances, back, want, 0.0f, 1.0f, blockers);
        for (int l = 0; l < kPacketSize; ++l) {
            if (!((want >> l) & 1)) continue;
            shadows.query[li][l] = !((blocked >> l) & 1) ? ShadowQuery::Lit
                                   : flat.materials[flat.instances[blockers[l].instance].material].is_transparent()
                                       ? ShadowQuery::Glass
                                       : ShadowQuery::Blocked;
        }
    }
    for (int l = 0; l < kPacketSize; ++l) {
        if (!((active >> l) & 1)) continue;
        ++counts.camera;
        colors[l] = (found >> l) & 1 ? shade_at(points[l], 0, glm::vec3(1.0f), counts, &shadows, l) : flat.background;
    }
}

glm::vec3 WhittedIntegrator::trace(const Ray& ray, int depth, const glm::vec3& weight, RayCounts& counts) const {
    Hit hit;
    return shade(ray, nearest_hit(scene_, ray, hit) ? &hit : nullptr, depth, weight, counts);
}

WhittedIntegrator::ShadingPoint WhittedIntegrator::shading_point(const Ray& ray, const Hit& hit) const {
    ShadingPoint p;
    p.s = surface_at(scene_, ray, hit);
    p.dir = glm::normalize(ray.direction);
    p.outside = glm::dot(p.s.normal, -p.dir) >= 0.0f;
    p.n = p.outside ? p.s.normal : -p.s.normal;  // faces the viewer: lighting only
    const float offset = surface_offset(p.s.point);
    p.above = p.s.point + offset * p.n;  // the viewer's side of the surface
    p.below = p.s.point - offset * p.n;
    return p;
}

// Whether `light` lights the point at all (before shadows): facing it, and not out of its cone.
bool WhittedIntegrator::faces_light(const ShadingPoint& p, const LightSample& ls) {
    return glm::dot(p.n, ls.to_light) > 0.0f && max_component(ls.intensity) > 0.0f;
}

// The colour along `ray` given its nearest hit (nullptr: none), at recursion depth `depth`.
glm::vec3 WhittedIntegrator::shade(const Ray& ray, const Hit* nearest, int depth, const glm::vec3& weight,
                                   RayCounts& counts) const {
    if (!nearest) return scene_.flat.background;
    return shade_at(shading_point(ray, *nearest), depth, weight, counts, nullptr, 0);
}

glm::vec3 WhittedIntegrator::shade_at(const ShadingPoint& p, int depth, const glm::vec3& weight, RayCounts& counts,
                                      const PacketShadows* shadows, int lane) const {
    const FlatScene& flat = scene_.flat;
    const Surface& s = p.s;
    const Material& m = *s.material;
    const glm::vec3 dir = p.dir, to_eye = -dir, n = p.n, above = p.above, below = p.below;
    const bool outside = p.outside;

    glm::vec3 color = m.emit + s.ambient * flat.ambient_intensity;

    for (std::size_t li = 0; li < flat.lights.size(); ++li) {
        const Light& light = flat.lights[li];
        LightSample ls = sample_light(light, s.point);
        if (!faces_light(p, ls)) continue;
        const float n_dot_l = glm::dot(n, ls.to_light);
        ++counts.shadow;
        // Camera-ray hits ask from the light first (so that a packet's shadow rays can share an
        // origin, and one by one they get the same answer); deeper hits, whose shadow rays are
        // not traced in packets, go straight to the query from the point, faster for single rays.
        const ShadowQuery known = shadows && li < kPacketLights ? shadows->query[li][lane] : ShadowQuery::Unknown;
        const glm::vec3 shadow = known == ShadowQuery::Lit                  ? glm::vec3(1.0f)
                                 : known == ShadowQuery::Blocked            ? glm::vec3(0.0f)
                                 : known == ShadowQuery::Glass || depth > 0 ? through_glass(light, ls, above)
                                                                            : shadow_factor(light, ls, above);
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
