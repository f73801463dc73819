#pragma once
// Unidirectional path tracing (scene-format.md §9.2): at every vertex, next-event estimation of
// one light chosen by power and one direction drawn from the BSDF, combined by multiple importance
// sampling (power heuristic) where both could have found the light; Russian roulette after the
// third bounce. Emissive shapes are area lights, point/spot/directional lights are reached only by
// next-event estimation, and the background is a uniform environment seen by rays that escape.
#include <vector>

#include "integrator/integrator.h"
#include "integrator/path_lights.h"
#include "base/diagnostic.h"

namespace whitted {

class PathIntegrator final : public Integrator {
public:
    // max_bounces: path vertices after the camera's (1 = direct light only).
    PathIntegrator(const Scene& scene, const Camera& camera, int max_bounces);

    void radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                  RayCounts& counts) const override;
    bool clamps_samples() const override { return false; }  // radiance, averaged as it is

    // With photons from the emissive shapes (integrator/caustic_integrator.h): an emitter reached
    // through delta lobes from a vertex that drew a non-delta one is the photons' path; left out here.
    void leave_emitter_caustics_to_photons(bool leave) { emitter_caustics_to_photons_ = leave; }

    // One camera ray on its own (nullptr first: find its first hit here). With `direct`, also the
    // part of the colour that reached the camera in at most one bounce: emitters and the background
    // seen, and light reaching the first surface (its next-event estimate and the emitter or
    // background its sampled ray finds); the rest is indirect.
    glm::vec3 radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts,
                       const Hit* first = nullptr, bool first_known = false, glm::vec3* direct = nullptr) const;

private:
    struct Vertex;
    // `choice` and `u`: the vertex's light-choice dimension (its first coordinate picks the light)
    // and the point on the light's.
    glm::vec3 next_event(const Vertex& v, int bounce, glm::vec2 choice, glm::vec2 u, const SampleKey& key,
                         const Sampler& sampler, RayCounts& counts) const;

    int max_bounces_;
    PathLights lights_;
    bool emitter_caustics_to_photons_ = false;
};

// Warnings that hold only in path mode: materials whose weights sum above 1 in some channel and are
// scaled down (§9.2). `sources[i]` is material i's object block.
std::vector<Diagnostic> path_mode_warnings(const SceneData& scene, const std::vector<SourceLoc>& sources);

}  // namespace whitted
