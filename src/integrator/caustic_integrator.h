#pragma once
// Path mode with caustics: the path tracer's image plus the light that reaches a surface from a
// light or an emissive shape by way of an ideal mirror or refraction first (scene-format.md §9.2),
// which the path tracer cannot find from a point, spot or directional light (a delta light is
// reached only by next-event estimation, and a delta lobe cannot be connected to) and finds from an
// emissive shape only by chance (a sampled direction that happens to refract onto it).
//
// The two estimators split the paths between them, so nothing is counted twice: the path tracer
// takes every path whose vertex next to the light scatters by a non-delta lobe (its next-event
// estimate and its BSDF-sampled hits), and an emitter seen through delta lobes alone from the
// camera; the photons take every path whose vertex next to the light scatters by a delta lobe and
// that has a non-delta vertex before the camera (the path tracer leaves those out:
// PathIntegrator::leave_emitter_caustics_to_photons).
// A photon leaves a light (integrator/photon_emitter.h), ends at its first surface unless a delta
// lobe is drawn there, then is stored at every later surface with a non-delta lobe, scattering on
// by the BSDF with Russian roulette. A camera sample follows delta lobes to the first vertex that
// draws a non-delta one and gathers there the photons within radius r: Σ f · Φ / (π r² N).
//
// Progressive photon mapping as Knaus and Zwicker's probabilistic formulation (2011): sample index
// s of every pixel gathers from a photon map of its own, `photons` photons traced for it alone, with
// the radius r_s² = r0² · (s + 1)^(α − 1), α = 2/3. Each sample's estimate is then independent of
// the others and slightly biased, bias and variance both vanishing as s grows, so the mean the film
// keeps converges (its error as N^(−1/3)) with no per-pixel state: passes, checkpoints, the viewer
// and MPI ranks work as for any other integrator. The maps depend on the sample index alone, never
// on the passes: a render in passes, in one go or shared among ranks gathers from the same photons.
// Photon i of sample s is traced from numbers hashed from (seed, s, i), never from a thread, and
// each map is built in photon order: the same bytes for any thread count, tile size or rank.
//
// Memory: the maps of the samples being rendered are kept (a pass of n samples: n maps), at most
// max_stored photons in all (bytes_per_photon() each at most; PhotonMap::bytes measures them). When
// the pass's photons would store more, each of its samples emits fewer (whole chunks, decided in
// photon order): still deterministic, no longer the photons of a render in other passes.
#include <atomic>
#include <cstdint>

#include "integrator/integrator.h"
#include "integrator/path_integrator.h"
#include "integrator/photon_emitter.h"
#include "integrator/photon_map.h"

namespace whitted {

// Whether photons carry any light in the scene: a light or an emissive shape, and a material with
// an ideal (delta) mirror or refraction lobe.
bool scene_has_caustic_paths(const SceneData& scene);

struct CausticSettings {
    int max_bounces = 64;
    int photons_per_sample = 1 << 16;  // emitted, per sample index
    float radius = 0.0f;               // r0 in world units; 0 = 1/500 of the scene's bounding diagonal
    std::size_t max_stored = std::size_t(1) << 23;  // photons the maps of one prepare() may store
    bool aim = true;  // photons drawn toward the objects with a delta lobe (integrator/photon_emitter.h)
};

struct PhotonPassStats {
    std::size_t emitted = 0, stored = 0;
    std::size_t reached = 0;  // photons whose first surface has a delta lobe (the others are wasted)
    std::size_t bytes = 0;  // the map's memory
    float radius = 0.0f;
    bool cut = false;  // the photon budget cut the samples' photons
};

class CausticIntegrator final : public Integrator {
public:
    CausticIntegrator(const Scene& scene, const Camera& camera, const CausticSettings& settings);

    void radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                  RayCounts& counts) const override;
    bool clamps_samples() const override { return false; }
    bool prepare(const SampleRange& range) const override;

    // The photon-map part of one camera ray's radiance (the map of the last prepare()).
    glm::vec3 caustic(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts,
                      const Hit* first = nullptr, bool first_known = false) const;

    // The gather radius of sample index s.
    float radius_of_sample(int s) const;
    // The photons of the last prepare(); the map sample index s gathers from (empty if not prepared).
    const PhotonPassStats& last_pass() const { return stats_; }
    const PhotonMap& photon_map(int s = 0) const;
    // Photon, hash-grid bucket and build scratch: what a stored photon costs at most.
    static constexpr std::size_t bytes_per_photon() { return sizeof(Photon) + 4 * sizeof(std::uint32_t); }

private:
    // Traces photon `index` keyed `key` (seed and sample index), appending what it stores to `out`;
    // whether its first surface had a delta lobe.
    bool trace_photon(std::uint64_t key, std::uint64_t index, std::vector<Photon>& out) const;

    struct SampleMap {
        PhotonMap map;
        float scale = 0.0f;  // 1 / (π r² · photons emitted)
    };

    PathIntegrator path_;
    CausticSettings settings_;
    PhotonEmitter emitter_;
    float r0_;
    // The maps of the samples last prepared (built by prepare, read by radiance): sample indices
    // [prepared_.begin, prepared_.end) under prepared_.seed.
    mutable std::vector<SampleMap> maps_;
    mutable SampleRange prepared_{-1, -1, 0, 0, nullptr};
    mutable PhotonPassStats stats_;
};

}  // namespace whitted
