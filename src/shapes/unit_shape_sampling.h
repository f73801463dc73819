#pragma once
// Points spread uniformly by area over a unit shape's surface, in object space: how an emissive
// shape is sampled as an area light (the path tracer converts the density through the instance's
// matrix, integrator/area_lights.h).
#include <glm/glm.hpp>

#include "scene/scene_description.h"
#include "shapes/unit_shapes.h"

namespace whitted {

struct ShapeSample {
    glm::vec3 p;  // object space, on the surface
    ShapePart part;
};

// The surface area of the unit shape (cube 6, sphere π, cylinder 3π/2, cone π/4·(1 + √5)).
float unit_shape_area(ShapeKind kind);

// A point uniform by area, from u in [0, 1)²: u.x first picks the part (by its share of the area)
// and is then stretched back to [0, 1) within it, so stratified u stay stratified.
ShapeSample sample_unit_shape(ShapeKind kind, glm::vec2 u);

}  // namespace whitted
