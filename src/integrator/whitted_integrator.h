#pragma once
// Recursive Whitted ray tracing (scene-format.md §7): Phong direct lighting with shadow rays,
// mirror reflection and Snell refraction up to a user-set depth.
#include <cstdint>

#include <glm/glm.hpp>

#include "accel/bvh_packet.h"
#include "accel/scene.h"
#include "integrator/surface.h"
#include "integrator/light_sample.h"
#include "integrator/render_mode.h"

namespace whitted {

// Rays traced, by kind; each render thread keeps its own and they are summed at the end.
struct RayCounts {
    std::uint64_t camera = 0, reflected = 0, refracted = 0, shadow = 0;
    std::uint64_t total() const { return camera + reflected + refracted + shadow; }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera; reflected += o.reflected; refracted += o.refracted; shadow += o.shadow;
        return *this;
    }
};

struct IntegratorOptions {
    int max_depth = 5;  // camera ray = depth 0; no ray deeper than this is traced
    RenderMode mode = RenderMode::Whitted;
};

class WhittedIntegrator {
public:
    WhittedIntegrator(const Scene& scene, const IntegratorOptions& options);

    // Colour seen along a camera ray (linear, unclamped).
    glm::vec3 camera_ray(const Ray& ray, RayCounts& counts) const;

    // The same for a camera ray whose nearest hit was found beforehand by camera_hits
    // (nullptr = it hit nothing): the renderer finds a tile's camera hits a packet at a time.
    glm::vec3 camera_ray(const Ray& ray, const Hit* first_hit, RayCounts& counts) const;

    // The nearest hits of a packet of camera rays (the lanes set in `active`), exactly as
    // camera_ray(ray, counts) would find them one by one; bit l of the result = lane l hit.
    unsigned camera_hits(const Ray (&rays)[kPacketSize], unsigned active, Hit (&hits)[kPacketSize]) const;

    // The colours of a packet of camera rays whose hits camera_hits found (`found`), exactly as
    // camera_ray(ray, hit, counts) gives them one by one; the shadow rays toward point and spot
    // lights from the packet's hits are traced as packets too.
    void camera_packet(const Ray (&rays)[kPacketSize], unsigned active, const Hit (&hits)[kPacketSize], unsigned found,
                       glm::vec3 (&colors)[kPacketSize], RayCounts& counts) const;

private:
    // A hit made ready for shading: its surface, the normal facing the viewer, the points just
    // above and below it where secondary rays start.
    struct ShadingPoint {
        Surface s;
        glm::vec3 dir, n, above, below;
        bool outside;
    };
    // What a packet's shadow rays found for each lane and light (the first kPacketLights lights).
    enum class ShadowQuery : unsigned char { Unknown, Lit, Blocked, Glass };
    static constexpr std::size_t kPacketLights = 8;
    struct PacketShadows {
        ShadowQuery query[kPacketLights][kPacketSize] = {};
    };
    ShadingPoint shading_point(const Ray& ray, const Hit& hit) const;
    static bool faces_light(const ShadingPoint& p, const LightSample& ls);
    static bool query_from_light(const Light& light, const glm::vec3& start);
    glm::vec3 shade_at(const ShadingPoint& p, int depth, const glm::vec3& weight, RayCounts& counts,
                       const PacketShadows* shadows, int lane) const;
    glm::vec3 through_glass(const Light& light, const LightSample& ls, const glm::vec3& start) const;
    glm::vec3 trace(const Ray& ray, int depth, const glm::vec3& weight, RayCounts& counts) const;
    glm::vec3 shade(const Ray& ray, const Hit* nearest, int depth, const glm::vec3& weight, RayCounts& counts) const;
    glm::vec3 debug_view(const Ray& ray, const Hit* hit) const;
    glm::vec3 shadow_factor(const Light& light, const LightSample& ls, const glm::vec3& start) const;

    const Scene& scene_;
    IntegratorOptions options_;
    float depth_near_ = 0, depth_far_ = 1;  // distance range for the depth view
};

// Distance by which secondary rays leave a surface, relative to the point's magnitude so that
// it stays above float rounding wherever the scene sits.
inline float surface_offset(const glm::vec3& p) {
    float m = std::max(std::max(std::abs(p.x), std::abs(p.y)), std::max(std::abs(p.z), 1.0f));
    return 1e-4f * m;
}

}  // namespace whitted
