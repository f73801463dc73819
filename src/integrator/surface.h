#pragma once
// What the integrator needs to know about a hit: built once from the BVH's Hit record.
#include <glm/glm.hpp>

#include "accel/scene.h"

namespace whitted {

struct Surface {
    glm::vec3 point;      // world space
    glm::vec3 normal;     // world space, unit, outward
    glm::vec3 object_normal;  // the outward normal there in object space (a mesh: the triangle's geometric one)
    glm::vec2 uv;         // texture coordinates (spec §8; a mesh's vt, §9.3): (0, 0) unless textured
    const Material* material;
    glm::vec3 diffuse;    // material diffuse × texel (or blended with it, §9.4)
    glm::vec3 ambient;    // material ambient × texel (as is under blend)
};

Surface surface_at(const Scene& scene, const Ray& ray, const Hit& hit);
// The texture coordinates of the hit whether its material has a texture or not (surface_at leaves
// an untextured surface's at (0, 0)): what the pixel inspector reports.
glm::vec2 surface_uv(const Scene& scene, const Ray& ray, const Hit& hit);

// Mixes a texel of the surface's texture into its material's diffuse and ambient (spec §8, §9.4).
void mix_texel(Surface& s, const glm::vec3& texel);

}  // namespace whitted
