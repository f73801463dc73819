#pragma once
// The debugging views, each a small integrator of its own: what the camera ray hits, unlit
// (raycast: the diffuse colour × texel, the background where nothing is hit), the world normal
// mapped to colour (normals: 0.5·(n + 1), black where nothing is hit), and the distance (depth:
// white at the nearest point of the scene's bounds, black at the farthest).
#include "accel/scene.h"
#include "integrator/integrator.h"

namespace whitted {

// The shared part: find the camera hits a packet at a time, colour each one on its own.
class HitViewIntegrator : public Integrator {
public:
    using Integrator::Integrator;
    void radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                  RayCounts& counts) const final;

protected:
    virtual glm::vec3 hit_color(const Ray& ray, const Hit& hit) const = 0;
    virtual glm::vec3 miss_color() const { return glm::vec3(0.0f); }
};

class RaycastIntegrator final : public HitViewIntegrator {
public:
    using HitViewIntegrator::HitViewIntegrator;

private:
    glm::vec3 hit_color(const Ray& ray, const Hit& hit) const override;
    glm::vec3 miss_color() const override { return scene_.data.background; }
};

class NormalsIntegrator final : public HitViewIntegrator {
public:
    using HitViewIntegrator::HitViewIntegrator;

private:
    glm::vec3 hit_color(const Ray& ray, const Hit& hit) const override;
};

class DepthIntegrator final : public HitViewIntegrator {
public:
    DepthIntegrator(const Scene& scene, const Camera& camera);

private:
    glm::vec3 hit_color(const Ray& ray, const Hit& hit) const override;
    float near_ = 0, far_ = 1;  // the scene's distance range from the eye
};

}  // namespace whitted
