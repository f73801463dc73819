#pragma once
// The lights of the path tracer (scene-format.md §9.2): every instance whose material has `emit` is
// an area light, sampled by area in object space with the density converted through the
// instance's matrix (exact under any affine map: an object-space area element dA becomes
// |det M| · |M⁻ᵀ n| dA in the world); a cube only on the faces the shading point can see
// (integrator/cube_light.h); a round sphere by the cone it subtends (integrator/sphere_light.h); point, spot and directional lights by next-event estimation only. An emissive mesh (§9.3) is sampled by world triangle area, with the density 1 / its world
// area everywhere on it (mesh/mesh_area_sampler.h, one table per emissive mesh instance). One light
// is chosen per estimate, in proportion to its power. An emitter that moves during the shutter is
// not one of them: the path tracer meets it by its sampled directions alone.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "accel/scene.h"
#include "integrator/cube_light.h"
#include "integrator/mesh_area_sampler.h"
#include "integrator/sphere_light.h"

namespace whitted {

struct PathLight {
    std::int32_t instance = -1;  // an area light: the emissive instance; -1: flat.lights[light]
    std::int32_t light = -1;
};

struct AreaLightSample {
    glm::vec3 point;   // on the light, world space
    glm::vec3 normal;  // its unit outward normal
    float pdf_area;    // density per unit of world area, given this light was chosen
};

class PathLights {
public:
    explicit PathLights(const Scene& scene);

    bool empty() const { return lights_.empty(); }
    // Picks a light with probability in proportion to its power; `prob` is that probability.
    const PathLight& choose(float u, float& prob) const;
    // The probability of choosing the area light on `instance` (0 if it emits nothing).
    float choice_probability(std::uint32_t instance) const;

    // A point of the instance's shape to light the shading point x with, and its world-area
    // density: on a cube, on the faces x can see, in the solid angle of each (CubeLight); on a round sphere, in the cone x
    // sees it in (SphereLight); on the other unit shapes, uniform by
    // object-space area (the ellipsoid's, uniform on the sphere it is mapped from); on a mesh,
    // uniform by world area (u_triangle picks the triangle, u the point in it).
    AreaLightSample sample_area(std::uint32_t instance, const glm::vec3& x, glm::vec2 u, float u_triangle = 0.0f) const;
    // The world-area density of sample_area from x at the point p (world space) of the instance,
    // whose object-space normal there is n_object (the same density it samples with; only a cube's
    // depends on x and p).
    float pdf_area(std::uint32_t instance, const glm::vec3& x, const glm::vec3& p, const glm::vec3& n_object) const;
    // The instance's world surface area (by quadrature of the area element: exact for flat parts).
    static float world_area(const Instance& inst);

private:
    const Scene& scene_;
    std::vector<PathLight> lights_;
    std::vector<float> cdf_;              // running sum of the choice probabilities
    std::vector<float> instance_choice_;  // per instance: the probability of choosing it (0 = not a light)
    std::vector<MeshAreaSampler> mesh_samplers_;
    std::vector<std::int32_t> mesh_sampler_of_;  // per instance: into mesh_samplers_, or -1
    std::vector<CubeLight> cubes_;
    std::vector<std::int32_t> cube_of_;  // per instance: into cubes_, or -1
    std::vector<SphereLight> spheres_;
    std::vector<std::int32_t> sphere_of_;  // per instance: into spheres_, or -1
};

}  // namespace whitted
