#pragma once
// Splitting an OBJ polygon into triangles (scene-format.md §9.3), in time that stays near linear
// in the file whatever its faces: a quad along its shorter diagonal (as tinyobjloader does), a
// polygon of up to kEarClipCorners corners by ear clipping in the plane it lies in (right for
// concave ones), a larger one as a fan from its first corner (right for convex ones; ear clipping
// costs the square of the corners, and a face of 64,000 corners took minutes).
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace whitted {

constexpr std::uint32_t kEarClipCorners = 32;

// The n − 2 triangles of the polygon whose corners are `corners[0 .. n)` in order, appended to
// `out` as triples of corner numbers (0 .. n − 1), each wound as the polygon is. n >= 3.
void split_polygon(const glm::vec3* corners, std::uint32_t n, std::vector<std::array<std::uint32_t, 3>>& out);

}  // namespace whitted
