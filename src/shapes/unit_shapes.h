#pragma once
// The four unit shapes in object space (scene-format.md §4): all inside [-0.5, 0.5]³.
//   cube: faces at ±0.5; sphere: radius 0.5; cylinder: axis +Y, radius 0.5, capped;
//   cone: apex (0, 0.5, 0), base disc radius 0.5 at y = -0.5, capped.
//   ellipsoid (§9.4): x² + 4y² + z² = 1, reaching x, z = ±1.
// Every shape is convex, so a line meets it in at most one interval [t_in, t_out].
#include <glm/glm.hpp>

#include "data/shape_kind.h"
#include "base/bounds.h"
#include "base/ray.h"

namespace whitted {

// Which part of a shape a hit lies on; it selects the normal and the (u, v) formula.
enum ShapePart : unsigned char {
    kPartSide = 0,      // sphere surface, cylinder/cone side
    kPartTopCap = 1,    // cylinder top (y = +0.5)
    kPartBottomCap = 2, // cylinder bottom, cone base (y = -0.5)
    // cube faces
    kPartPosX = 3, kPartNegX = 4, kPartPosY = 5, kPartNegY = 6, kPartPosZ = 7, kPartNegZ = 8,
};

// The interval where the line origin + t·direction is inside the shape, with the parts it
// enters and leaves through. count = 0 (missed), or 2 with t[0] <= t[1] (t[0] may be negative:
// the origin is inside or beyond). A tangent touch counts as a zero-length interval.
struct ShapeSpan {
    int count = 0;
    float t[2] = {0, 0};
    ShapePart part[2] = {kPartSide, kPartSide};
};

// Any direction length (shape_math::intersect_rescaled): the reference the BVH walks are checked against.
ShapeSpan intersect_unit_shape(ShapeKind kind, const Ray& object_ray);

// The nearest hit with t in (t_min, t_max); returns false if none.
inline bool nearest_hit(const ShapeSpan& s, float t_min, float t_max, float& t, ShapePart& part) {
    if (s.count == 0) return false;
    if (s.t[0] > t_min && s.t[0] < t_max) { t = s.t[0]; part = s.part[0]; return true; }
    if (s.t[1] > t_min && s.t[1] < t_max) { t = s.t[1]; part = s.part[1]; return true; }
    return false;
}

// Outward unit normal at object-space point p on `part`.
glm::vec3 unit_shape_normal(ShapeKind kind, ShapePart part, const glm::vec3& p);

// Texture coordinates in [0,1)² at object-space point p on `part` (scene-format.md §8).
glm::vec2 unit_shape_uv(ShapeKind kind, ShapePart part, const glm::vec3& p);

// World-space bounds of the shape under the affine object-to-world matrix, tight for every
// shape (the cone's is the box of its base disc and apex).
Bounds unit_shape_world_bounds(ShapeKind kind, const glm::mat4& object_to_world);

}  // namespace whitted
