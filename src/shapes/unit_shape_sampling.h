#pragma once
// Points spread uniformly by area over a unit shape's surface, in object space: how an emissive
// shape is sampled as an area light (the path tracer converts the density through the instance's
// matrix, integrator/area_lights.h).
#include <glm/glm.hpp>

#include "data/shape_kind.h"
#include "shapes/unit_shapes.h"

namespace whitted {

struct ShapeSample {
    glm::vec3 p;  // object space, on the surface
    ShapePart part;
};

// The area of the domain sample_unit_shape spreads its points uniformly over: the unit shape's
// surface (cube 6, sphere π, cylinder 3π/2, cone π/4·(1 + √5)); for the ellipsoid, whose area has
// no closed form to invert, the unit sphere of radius 1 (4π), mapped onto it by (x, y/2, z).
float unit_shape_area(ShapeKind kind);

// A point of the shape, from u in [0, 1)²: uniform by area over the domain above. u.x first picks
// the part (by its share of the area) and is then stretched back to [0, 1) within it, so
// stratified u stay stratified.
ShapeSample sample_unit_shape(ShapeKind kind, glm::vec2 u);

// The object-space area that a unit of the sampling domain becomes at the point of the shape whose
// outward unit normal is n, as a vector along n: n itself for the four shapes sampled on their own
// surface; for the ellipsoid, at p = (q.x, q.y/2, q.z), |det E|·E⁻ᵀq = (q.x, 2q.y, q.z)/2 with
// E = diag(1, 1/2, 1). Its length under a matrix's |det M|·|M⁻ᵀ ·| is the world area per unit of
// the domain: the density conversion of an instanced area light.
glm::vec3 unit_shape_area_normal(ShapeKind kind, const glm::vec3& n);

}  // namespace whitted
