#pragma once
// Recursive Whitted ray tracing (scene-format.md §7): Phong direct lighting with shadow rays,
// mirror reflection and Snell refraction up to a user-set depth; with the distribution effects
// of §9.1 (disc and cone lights, glossy reflect and transparent rays) drawn from the sampler.
#include <cstdint>

#include <glm/glm.hpp>

#include "integrator/aov_recorder.h"
#include "integrator/conventions.h"
#include "integrator/integrator.h"
#include "integrator/light_sample.h"
#include "integrator/shading_record.h"
#include "integrator/surface.h"
#include "integrator/texture_footprint.h"

namespace whitted {

// The reflected and refracted rays one camera sample may trace: a full tree of depth 11. A mirror
// and glass scene doubles its rays at each level (at --max-depth 38, a camera ray took minutes), so
// past this, as past the depth limit, no further secondary ray of the sample is traced (depth
// first: the refracted ray's subtree, then the reflected one's). Bounds the time a sample takes,
// and so how soon a render stops when asked to.
constexpr std::uint32_t kMaxSecondaryRays = 4094;

class WhittedIntegrator final : public Integrator {
public:
    WhittedIntegrator(const Scene& scene, const Camera& camera, int max_depth, const Conventions& conventions = {});
    // Textures read with `filter`; for trilinear and ewa over the footprint of camera samples
    // spaced as the rows of an image `sample_rows` high (integrator_settings.h; 0 = none), carried
    // through mirrors and glass.
    WhittedIntegrator(const Scene& scene, const Camera& camera, int max_depth, const Conventions& conventions,
                      TextureFilter filter, float sample_rows);

    // The camera rays' nearest hits are found a packet at a time, and the shadow rays toward
    // point and spot lights from those hits are traced as packets too; every colour is exactly
    // the one radiance(ray, key, …) gives one ray at a time.
    void radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                  RayCounts& counts) const override;

    // One camera ray on its own, as sample `key`.
    glm::vec3 radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts) const;
    // The same, telling `recorder` every step of the shading (the pixel inspector): the same code,
    // which the renderer runs with a recorder that does nothing.
    glm::vec3 radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts,
                       ShadingRecorder& recorder) const;
    // The same, recording the sample's per-term images (integrator/aov_recorder.h).
    glm::vec3 radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts,
                       AovRecorder& recorder) const;

private:
    // A hit made ready for shading: its surface, the normal facing the viewer, the points just
    // above and below it where secondary rays start.
    struct ShadingPoint {
        Surface s;
        glm::vec3 dir, n, above, below;
        bool outside;
        float time;  // the ray's (Ray::time): its shadow and secondary rays meet the scene then too
        // Whether the Differentials beside it hold the hit's footprint: set by filter_texture, read
        // only for rays that carry differentials (which a filter reading footprints gives).
        bool differentials;
    };
    // Which sample is being shaded: where its further random numbers come from.
    struct SampleContext {
        const Sampler& sampler;
        SampleKey key;
        mutable std::uint32_t rays_left = kMaxSecondaryRays;  // of the sample's secondary rays
        glm::vec2 get2d(std::uint32_t dim) const { return sampler.get2d(key, dim); }
        // Takes one of the sample's secondary rays, if any is left.
        bool take_ray() const { return rays_left > 0 && (--rays_left, true); }
    };
    // What a packet's rays found for its camera hits, lane by lane: the shadow queries toward the
    // first kPacketLights lights, and an opaque mirror's reflection (the first secondary ray its
    // shading traces) with the hit it found.
    enum class ShadowQuery : unsigned char { Unknown, Lit, Blocked, Glass };
    static constexpr std::size_t kPacketLights = 8;
    struct PacketQueries {
        ShadowQuery query[kPacketLights][kPacketSize] = {};
        unsigned mirrored = 0, mirror_found = 0;  // the lanes whose reflection was traced, and hit
        Hit mirror_hit[kPacketSize];
    };
    // A ray's differentials and, once it has hit, the surface's there.
    struct Differentials {
        RayDifferential ray;
        SurfaceDifferentials surface;
    };
    ShadingPoint shading_point(const Ray& ray, const Hit& hit, Differentials* d = nullptr) const;
    void filter_texture(ShadingPoint& p, const Hit& hit, Differentials* d) const;
    // The camera ray's auxiliary rays into `rd` when textures are read over a footprint, else null.
    const RayDifferential* camera_differential(const Ray& ray, RayDifferential& rd) const;
    static bool faces_light(const ShadingPoint& p, const LightSample& ls);
    static bool query_from_light(const Light& light, const LightSample& ls, const glm::vec3& start);
    // (light_sample, through_glass and secondary_direction are inline: called per light and
    // per bounce, they are a test and a call in the common case.)
    inline LightSample light_sample(const Light& light, std::size_t li, const glm::vec3& point, int depth,
                                    bool centred, const SampleContext& ctx) const;
    template <class Recorder>
    glm::vec3 shade_at(const ShadingPoint& p, int depth, const glm::vec3& weight, const SampleContext& ctx,
                       RayCounts& counts, const PacketQueries* packet, int lane, Recorder& rec,
                       const Differentials* d = nullptr) const;
    inline glm::vec3 through_glass(const LightSample& ls, const glm::vec3& start, float time) const;
    glm::vec3 shadow_factor(const Light& light, const LightSample& ls, const glm::vec3& start, float time) const;
    // A ray of `kind` (what --stats times it as) traced and shaded.
    template <class Recorder>
    glm::vec3 trace(RayKind kind, const Ray& ray, int depth, const glm::vec3& weight, const SampleContext& ctx, RayCounts& counts,
                    Recorder& rec, const RayDifferential* rd = nullptr) const;
    // The colour a ray brings back from its hit (null: it hit nothing).
    template <class Recorder>
    glm::vec3 shade_hit(const Ray& ray, const Hit* hit, int depth, const glm::vec3& weight, const SampleContext& ctx,
                        RayCounts& counts, Recorder& rec, const RayDifferential* rd) const;
    // The direction of a reflected or refracted ray: the ideal one, or with gloss one drawn from
    // the lobe around it (false: it fell on the wrong side of the surface and carries nothing).
    inline bool secondary_direction(const glm::vec3& ideal, const glm::vec3& n, bool above, float gloss,
                             std::uint32_t dim, const SampleContext& ctx, glm::vec3& out) const;

    int max_depth_;
    Conventions conventions_;
    bool variant_;  // conventions_.any(): camera rays one at a time, where the switches are read
    TextureFilter filter_ = TextureFilter::Bilinear;
    float pitch_ = 0.0f;  // > 0: camera rays carry differentials this far apart on the plane at 1
};

// Distance by which secondary rays leave a surface, relative to the point's magnitude so that
// it stays above float rounding wherever the scene sits.
inline float surface_offset(const glm::vec3& p) {
    float m = std::max(std::max(std::abs(p.x), std::abs(p.y)), std::max(std::abs(p.z), 1.0f));
    return 1e-4f * m;
}

}  // namespace whitted
