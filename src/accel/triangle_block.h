#pragma once
// Four triangles of a leaf of a mesh's BVH with their corners copied side by side, as the
// four-lane test (watertight_triangle4.h) loads them: one aligned load per corner and axis, where
// reading the corners through the index array costs twelve dependent loads and nine gathers. The
// leaf order of a mesh's triangles (mesh_bvh.h) makes a leaf's blocks consecutive, as Embree's
// Triangle4 leaves are.
#include <cstdint>

namespace whitted {

struct alignas(16) TriangleBlock {
    float p[3][3][4];  // [corner][axis][lane]; lanes past the leaf's triangles repeat its last one
};
static_assert(sizeof(TriangleBlock) == 144);

}  // namespace whitted
