#pragma once
// One placed shape, as ray traversal reads it: 56 bytes, nothing else on the hot path.
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
    std::uint32_t material;
    std::uint32_t mesh = 0;  // kind == Mesh: index into SceneData::meshes
};

}  // namespace whitted
