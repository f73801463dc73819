#pragma once
// Ray differentials at a hit (pbrt-v4's SurfaceInteraction::ComputeDifferentials): where the
// auxiliary rays meet the surface's tangent plane, the texture coordinates and normal there, the
// texture look-up over that footprint (--texture-filter trilinear or ewa), and the auxiliary rays
// of the mirror and refracted rays leaving the hit.
#include <glm/glm.hpp>

#include "accel/scene.h"
#include "base/ray_differential.h"
#include "integrator/surface.h"
#include "texture/texture_filter.h"

namespace whitted {

// How the surface changes from the hit to where the auxiliary rays meet its tangent plane.
// Uninitialised until surface_differentials fills it: one waits on the stack of every traced ray.
struct SurfaceDifferentials {
    glm::vec3 dpdx, dpdy;  // world space
    glm::vec3 dndx, dndy;  // of the (unit, outward) shading normal
    TextureFootprint uv;   // of the texture coordinates
};

// False when an auxiliary ray runs parallel to the tangent plane (or anything is not finite).
// `time`: the ray's shutter time (Ray::time), where a moving instance is met; the auxiliary rays
// are taken at the same instant.
bool surface_differentials(const Scene& scene, const Hit& hit, const Surface& s, const RayDifferential& rd,
                           SurfaceDifferentials& out, float time = 0.0f);

// The surface's texture read again with `filter` (over `footprint` for trilinear and ewa; null:
// none, the image's finest level), mixed into diffuse and ambient as surface_at mixes the bilinear
// texel. A surface without a texture is left as is.
void refilter_texture(const Scene& scene, Surface& s, TextureFilter filter, const TextureFootprint* footprint);

// The auxiliary rays of the mirror ray leaving point p: from the points on the tangent plane,
// each mirrored about the normal there. n faces the incoming ray; side = +1 when it is the
// outward normal, -1 when it is its opposite (the differentials are of the outward one).
RayDifferential reflected_differential(const glm::vec3& p, const glm::vec3& n, float side, const RayDifferential& in,
                                       const SurfaceDifferentials& d);
// The same for the refracted ray (eta = n_from / n_to); false when an auxiliary ray would be
// totally reflected.
bool refracted_differential(const glm::vec3& p, const glm::vec3& n, float side, float eta, const RayDifferential& in,
                            const SurfaceDifferentials& d, RayDifferential& out);

}  // namespace whitted
