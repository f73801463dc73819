#pragma once
// The classic mistakes of the lab that live inside the Whitted shading, as switches: what `whitted
// explain` (compare/explain_variants.h) renders to name the mistake a student's image shows. All
// off is scene-format.md §7. The integrator reads them once when it is made; a render with any of
// them set traces its camera rays one at a time (where the switches are read), so the normal
// render's packet path never looks at them. The mistakes outside the shading (the camera's field of
// view, pixel corners, attenuation, η, texture rows, gamma, the depth) are made on a copy of the
// scene, camera or image instead and need no switch here.
#include <cstdint>

#include <glm/glm.hpp>

#include "data/instance.h"

namespace whitted {

struct Conventions {
    bool blinn_phong = false;           // specular (N·H)^shine instead of (R·V)^shine
    bool opaque_shadows = false;        // a transparent blocker blocks a light fully instead of tinting it
    bool shadows_beyond_light = false;  // objects beyond a point or spot light shadow it too
    bool no_total_internal_reflection = false;  // on TIR the transparent weight is lost, not reflected
    bool normals_by_m = false;          // normals taken to world space by M instead of (M⁻¹)ᵀ
    bool no_offset = false;             // secondary and shadow rays start on the surface (acne)
    std::uint32_t unshadowed_lights = 0;  // bit k: light k casts no shadows (lights 0 to 31)

    bool any() const {
        return blinn_phong || opaque_shadows || shadows_beyond_light || no_total_internal_reflection ||
               normals_by_m || no_offset || unshadowed_lights != 0;
    }
    bool operator==(const Conventions&) const = default;
};

// The `normals_by_m` mistake: the object-space normal taken to world space by M itself (unit).
glm::vec3 normal_by_m(const Instance& inst, const glm::vec3& object_normal);

}  // namespace whitted
