#pragma once
// Brown CSCI 1230's lighting model (scene-format.md §9.5), as the course's TA renderer draws its
// JSON scenes (BrownCSCI1230/projects_ray, raytracer/RayTracer.cpp): for the scenes its reader
// marks (SceneData::lighting), in place of §7's model. Per hit, with the materials already
// holding the global coefficients (ambient = ka·Oa, diffuse = kd·Od, …: cs1230/scene_reader.h):
//
//   C = ka·Oa;  D = kd·Od, or (1 − blend)·kd·Od + blend·texel (nearest texel, the course's u, v)
//   for each light: I = colour · f_att · spot (f_att = min(1, 1/(c1 + c2·d + c3·d²)); spot: 1
//       inside the inner cone, 1 − (3r² − 2r³) across the penumbra, 0 outside), skipped when the
//       shadow ray from P + 0.001·L meets anything before the light (every object is opaque);
//       C += I·D·max(0, N·L) + I·ks·Os·max(0, R·V)^n   (R the mirror of L; no highlight at n = 0)
//   C += kt·Ot · (the ray refracted into the shape and out of it again), C += ks·Or · (the mirror
//   ray, where the viewer is outside), each traced colour clamped to [0, 1]; return clamp(C).
//
// N is the shape's outward normal, not turned toward the viewer (a mesh's is: its triangles are
// two-sided). Secondary rays start 0.001 along their direction, as the TA renderer's do. The Intersect
// stage draws directional lights only, without shadows, textures, reflection or refraction.
// The colour returned is the one the course's renderer writes: clamped, then truncated to a
// step of 1/255 (its bytes are ⌊255·C⌋, not rounded), so that whitted's rounding to bytes keeps it.
#include <glm/glm.hpp>

#include "cs1230/stage.h"
#include "integrator/integrator.h"
#include "integrator/light_sample.h"
#include "integrator/shading_record.h"
#include "integrator/surface.h"

namespace whitted {

class Cs1230Integrator final : public Integrator {
public:
    Cs1230Integrator(const Scene& scene, const Camera& camera, int max_depth, cs1230::Stage stage);

    void radiance(const CameraBatch& batch, const Sampler& sampler, glm::vec3 (&out)[kPacketSize],
                  RayCounts& counts) const override;
    // One camera ray, telling `recorder` every step (the pixel inspector); the same colour.
    glm::vec3 radiance(const Ray& ray, const SampleKey& key, const Sampler& sampler, RayCounts& counts,
                       ShadingRecorder& recorder) const;

    // The light arriving at `point` from `light` before shadows, as the course computes it.
    static LightSample light_at(const Light& light, const glm::vec3& point);
    // How the course's renderer writes a colour: ⌊255·clamp(c)⌋ / 255.
    static glm::vec3 truncate_to_bytes(const glm::vec3& c);

private:
    template <class Recorder>
    glm::vec3 trace(RayKind kind, const Ray& ray, int depth, RayCounts& counts, Recorder& rec) const;
    template <class Recorder>
    glm::vec3 shade(const Ray& ray, const Hit& hit, int depth, RayCounts& counts, Recorder& rec) const;
    Surface surface(const Ray& ray, const Hit& hit) const;
    // The nearest hit of the ray on instance `instance` alone (where a refracted ray leaves it).
    bool intersect_instance(std::uint32_t instance, const Ray& ray, Hit& hit) const;
    template <class Recorder>
    glm::vec3 refraction(const Surface& s, const glm::vec3& dir, std::uint32_t instance, int depth,
                         RayCounts& counts, Recorder& rec) const;

    int max_depth_;
    cs1230::Stage stage_;
};

}  // namespace whitted
