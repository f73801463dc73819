#pragma once
// An emissive sphere seen from a shading point (path tracing, scene-format.md §9.2), when its matrix
// keeps it round (rotation, uniform scale, translation). From outside, a direction is drawn
// uniformly in the cone the sphere subtends (pbrt-v4's Sphere::Sample): every sample lands on the
// part of the sphere x can see, with the same density per solid angle, where sampling by area
// wastes the half behind and weighs near points far more than far ones. From inside, by area. The
// density depends on x: next-event estimation and a BSDF ray that hits the sphere ask for it at the
// same point, so multiple importance sampling stays consistent. Stretched spheres are sampled by
// area (PathLights).
#include <optional>

#include <glm/glm.hpp>

#include "data/scene_data.h"

namespace whitted {

class SphereLight {
public:
    // The sphere of `inst` (a unit sphere of radius 0.5 under its matrix) if the matrix keeps it round.
    static std::optional<SphereLight> of(const Instance& inst);

    struct Sample {
        glm::vec3 point;   // world space, on the sphere
        glm::vec3 normal;  // its unit outward normal
        float pdf_area;    // per unit of world area, given x
    };
    // A point of the sphere for the shading point x, from u in [0, 1)².
    Sample sample(const glm::vec3& x, glm::vec2 u) const;
    // The density per unit world area sample() draws the point with outward normal n with, from x.
    float pdf_area(const glm::vec3& x, const glm::vec3& n) const;

    glm::vec3 centre() const { return centre_; }
    float radius() const { return radius_; }

private:
    SphereLight(const glm::vec3& centre, float radius) : centre_(centre), radius_(radius) {}
    bool inside(const glm::vec3& x) const;
    // 1 − cos of the cone's half-angle from x (outside only), exact for small cones too.
    float one_minus_cos_max(const glm::vec3& x) const;

    glm::vec3 centre_;
    float radius_;
};

}  // namespace whitted
