#pragma once
// One placed shape, as ray traversal reads it: 60 bytes, nothing else on the hot path.
#include <cstdint>

#include <glm/glm.hpp>

#include "data/shape_kind.h"

namespace whitted {

// One shape placed in the world. Only the world→object affine map is kept (three rows of
// [R | t]): rays go into object space through it and normals come back through its
// transpose, which is exactly (M⁻¹)ᵀ.
struct Instance {
    glm::vec4 world_to_object[3];
    ShapeKind kind;
    // Set for an instance scaled so far (by more than about 2^20 either way) that the object-space
    // direction of a ray can leave float's range when squared (a sphere scaled by 1e23 sees a unit
    // ray as 1e-23, whose square is 0): its rays are intersected with the direction scaled by a
    // power of two (shape_math::intersect_rescaled: exact, the same bits where nothing underflowed).
    std::uint8_t rescale = 0;
    std::uint32_t material;
    std::uint32_t mesh = 0;  // kind == Mesh: index into SceneData::meshes
};

static_assert(sizeof(Instance) == 60, "rescale sits in the padding after kind");

}  // namespace whitted
