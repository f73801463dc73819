#pragma once
// Texture mapping as the course's renderer does it (scene-format.md §9.5): its own (u, v) for each
// surface of the unit shapes, and the nearest texel, not a filtered one.
#include <glm/glm.hpp>

#include "data/shape_kind.h"
#include "data/texture_image.h"
#include "shapes/unit_shapes.h"

namespace whitted::cs1230 {

// (u, v) in [0, 1]² at object-space point p on `part` of a unit shape, v pointing up the image.
// With θ = atan2(z, x) and u_round = −θ/2π where θ < 0, else 1 − θ/2π:
//   sphere: u_round (0.5 at the poles), v = 0.5 + asin(y / 0.5)/π;
//   cylinder and cone sides: u_round (the cone's apex: 0.5), v = y + 0.5;
//   cylinder top: (x + 0.5, 0.5 − z); cylinder bottom, cone base: (x + 0.5, z + 0.5);
//   cube +x: (0.5 − z, y + 0.5), −x: (z + 0.5, y + 0.5), +y: (x + 0.5, 0.5 − z),
//   −y: (x + 0.5, z + 0.5), +z: (x + 0.5, y + 0.5), −z: (0.5 − x, y + 0.5).
glm::vec2 shape_uv(ShapeKind kind, ShapePart part, const glm::vec3& p);

// The texel at (u, v) repeated repeat_u × repeat_v times: column ⌊u·U·w⌋ mod w, row
// ⌊(1 − v)·V·h⌋ mod h (row 0 at the top), u and v clamped to [0, 1]; where u (or 1 − v) is 1 the
// last column (row) of the last repeat, not the first.
glm::vec3 nearest_texel(const TextureImage& image, glm::vec2 uv, float repeat_u, float repeat_v);

}  // namespace whitted::cs1230
