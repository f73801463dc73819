#pragma once
// What turns camera rays into colours: the interface every rendering method implements (Whitted
// ray tracing, path tracing, the debug views), each in a file of its own. The renderer hands an integrator batches
// of camera samples, a packet at a time, so that it can trace them together; each sample names
// its pixel and index, from which the integrator draws any further numbers it needs (a point on
// an area light, a glossy direction) through the render's Sampler.
#include <atomic>
#include <cstdint>
#include <memory>

#include <glm/glm.hpp>

#include "base/ray.h"
#include "camera/camera.h"
#include "integrator/integrator_settings.h"
#include "integrator/ray_counts.h"
#include "sampler/sampler.h"

namespace whitted {

struct Scene;  // accel/scene.h: what an integrator asks its rays of

// The samples about to be rendered, for work an integrator does once before them (a photon pass).
struct SampleRange {
    int begin = 0, end = 0;  // sample indices [begin, end) of every pixel
    std::uint32_t seed = 0;  // the sampler's seed
    int threads = 0;         // 0 = all hardware threads
    const std::atomic<bool>* cancel = nullptr;
};

// Camera samples traced together: the lanes set in `active`.
struct CameraBatch {
    Ray rays[kPacketSize];
    SampleKey keys[kPacketSize];
    unsigned active = 0;
};

class Integrator {
public:
    Integrator(const Scene& scene, const Camera& camera) : scene_(scene), camera_(camera) {}
    virtual ~Integrator() = default;

    // The colour arriving along each active lane's camera ray (linear, unclamped) into out[lane].
    virtual void radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                          RayCounts& counts) const = 0;

    // Whether a pixel's samples are clamped to [0, 1] before their mean is taken: anti-aliasing
    // of displayed colours (§7), as the Whitted model always did. A radiance estimator keeps them.
    virtual bool clamps_samples() const { return true; }

    // Called by the renderer before the tiles of `range` are rendered, from one thread, never while
    // radiance() runs: what it prepares (mutable state) is then read by every tile. Returns false
    // when range.cancel stopped it (nothing may be rendered then).
    virtual bool prepare(const SampleRange& range) const {
        (void)range;
        return true;
    }

    const Scene& scene() const { return scene_; }
    const Camera& camera() const { return camera_; }

protected:
    const Scene& scene_;
    Camera camera_;
};

// The integrator for `settings.mode`, rendering `scene` as seen by `camera`.
std::unique_ptr<Integrator> make_integrator(const Scene& scene, const Camera& camera,
                                            const IntegratorSettings& settings);

}  // namespace whitted
