#pragma once
// Path mode with caustics: the path tracer's image plus the light that reaches a surface from a
// point, spot or directional light by way of an ideal mirror or refraction first (scene-format.md
// §9.2), which the path tracer cannot find (a delta light is reached only by next-event estimation,
// and a delta lobe cannot be connected to).
//
// The two estimators split the paths between them, so nothing is counted twice: the path tracer
// takes every path whose vertex next to a delta light scatters by a non-delta lobe (its next-event
// estimate); the photons take every path whose vertex next to the light scatters by a delta lobe.
// A photon leaves a light (integrator/photon_emitter.h), ends at its first surface unless a delta
// lobe is drawn there, then is stored at every later surface with a non-delta lobe, scattering on
// by the BSDF with Russian roulette. A camera sample follows delta lobes to the first vertex that
// draws a non-delta one and gathers there the photons within radius r: Σ f · Φ / (π r² N).
//
// Progressive photon mapping as Knaus and Zwicker's probabilistic formulation (2011): the samples
// of block b of sample indices ([0, 1), [1, 2), [2, 4), [4, 8) …) share one photon map of
// (samples in the block) · photons photons with the radius r² = r0² · (s + 1)^(α − 1), s the middle
// sample of the block and α = 2/3; each sample's estimate is an independent, slightly biased one
// whose bias and variance both vanish as the samples grow, so the mean the film keeps converges,
// with no per-pixel state. The blocks are fixed by the sample index, not by the passes: a render
// in passes, in one go or shared among MPI ranks draws every sample from the same map. Photon i of
// a block is traced from numbers hashed from (seed, block, i), never from a thread, and the map is
// built in photon order: the same bytes for any thread count, tile size or rank.
//
// Memory: at most max_stored photons a block (bytes_per_photon() each, measured by PhotonMap::bytes);
// a block that would store more emits fewer photons (whole chunks of them, decided in photon order).
// The maps of the blocks of the samples being rendered are kept: one or two for a session's pass
// (doubling passes are blocks unless aa² is no power of two), log2(spp) + 1 for a render in one go.
#include <atomic>
#include <cstdint>

#include "integrator/integrator.h"
#include "integrator/path_integrator.h"
#include "integrator/photon_emitter.h"
#include "integrator/photon_map.h"

namespace whitted {

// Whether photons carry any light in the scene: a point, spot or directional light, and a
// material with an ideal (delta) mirror or refraction lobe.
bool scene_has_caustic_paths(const SceneData& scene);

struct CausticSettings {
    int max_bounces = 64;
    int photons_per_sample = 1 << 16;  // emitted, per sample index
    float radius = 0.0f;               // r0 in world units; 0 = 1/500 of the scene's bounding diagonal
    std::size_t max_stored = std::size_t(1) << 21;  // photons a block may store
};

struct PhotonPassStats {
    std::size_t emitted = 0, stored = 0;
    std::size_t bytes = 0;  // the map's memory
    float radius = 0.0f;
    bool cut = false;  // the photon budget stopped the block early
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

    // The block of sample indices a sample belongs to, and the radius of its map.
    static int block_of(int index);
    float radius_of_block(int block) const;
    // The photons of the last block traced; the map sample `index` gathers from (empty if not prepared).
    const PhotonPassStats& last_pass() const { return stats_; }
    const PhotonMap& photon_map(int index = 0) const;
    // Photon, hash-grid bucket and build scratch: what a stored photon costs at most.
    static constexpr std::size_t bytes_per_photon() { return sizeof(Photon) + 4 * sizeof(std::uint32_t); }

private:
    // Traces photon `index` of the block keyed `block`, appending what it stores to `out`.
    void trace_photon(std::uint64_t block, std::uint64_t index, std::vector<Photon>& out) const;
    // Traces block b's photons into maps_[b]; false if cancelled.
    bool trace_block(int block, const SampleRange& range) const;

    static constexpr int kBlocks = 25;  // sample indices below 2^24 (Sampler::kMaxSpp · kMaxAa²)
    struct Block {
        PhotonMap map;
        float scale = 0.0f;  // 1 / (π r² · photons emitted)
        bool ready = false;
    };

    PathIntegrator path_;
    CausticSettings settings_;
    PhotonEmitter emitter_;
    float r0_;
    // The maps of the samples last prepared (built by prepare, read by radiance), under seed_.
    mutable Block maps_[kBlocks];
    mutable std::uint32_t seed_ = 0;
    mutable PhotonPassStats stats_;
};

}  // namespace whitted
