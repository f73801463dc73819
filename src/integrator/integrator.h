#pragma once
// What turns camera rays into colours: the interface every rendering method implements (Whitted
// ray tracing, the debug views; a path tracer next). The renderer hands an integrator batches
// of camera samples, a packet at a time, so that it can trace them together; each sample names
// its pixel and index, from which the integrator draws any further numbers it needs (a point on
// an area light, a glossy direction) through the render's Sampler.
#include <memory>

#include <glm/glm.hpp>

#include "accel/scene.h"
#include "camera/camera.h"
#include "cs1230/stage.h"
#include "integrator/ray_counts.h"
#include "integrator/render_mode.h"
#include "sampler/sampler.h"

namespace whitted {

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

struct IntegratorSettings {
    RenderMode mode = RenderMode::Whitted;
    int max_depth = 5;  // camera ray = depth 0; no ray deeper than this is traced (path: bounces)
    // Which of the course's projects draws a CSCI 1230 scene in Whitted mode (§9.5).
    cs1230::Stage cs1230_stage = cs1230::Stage::Illuminate;
};

// The integrator for `settings.mode`, rendering `scene` as seen by `camera`.
std::unique_ptr<Integrator> make_integrator(const Scene& scene, const Camera& camera,
                                            const IntegratorSettings& settings);

}  // namespace whitted
