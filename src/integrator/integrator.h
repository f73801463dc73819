#pragma once
// What turns camera rays into colours: the interface every rendering method implements (Whitted
// ray tracing, path tracing, the debug views), each in a file of its own. The renderer hands an integrator batches
// of camera samples, a packet at a time, so that it can trace them together; each sample names
// its pixel and index, from which the integrator draws any further numbers it needs (a point on
// an area light, a glossy direction) through the render's Sampler.
#include <memory>

#include <glm/glm.hpp>

#include "base/ray.h"
#include "camera/camera.h"
#include "integrator/integrator_settings.h"
#include "integrator/ray_counts.h"
#include "sampler/sampler.h"

namespace whitted {

struct Scene;  // accel/scene.h: what an integrator asks its rays of

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
