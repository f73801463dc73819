#pragma once
// Geometry of one placed instance: the object-space ray, its world bounds, its world normal.
#include <glm/glm.hpp>

#include "data/scene_data.h"
#include "shapes/unit_shapes.h"

namespace whitted {

inline Ray to_object_space(const Instance& inst, const Ray& r) {
    const glm::vec4* w = inst.world_to_object;
    Ray o;
    o.origin = glm::vec3(glm::dot(glm::vec3(w[0]), r.origin) + w[0].w, glm::dot(glm::vec3(w[1]), r.origin) + w[1].w,
                         glm::dot(glm::vec3(w[2]), r.origin) + w[2].w);
    o.direction = glm::vec3(glm::dot(glm::vec3(w[0]), r.direction), glm::dot(glm::vec3(w[1]), r.direction),
                            glm::dot(glm::vec3(w[2]), r.direction));
    return o;
}

// (M⁻¹)ᵀ·n: the rows of world_to_object are the columns of its transpose.
inline glm::vec3 normal_to_world(const Instance& inst, const glm::vec3& n) {
    const glm::vec4* w = inst.world_to_object;
    return glm::normalize(n.x * glm::vec3(w[0]) + n.y * glm::vec3(w[1]) + n.z * glm::vec3(w[2]));
}

// The object→world matrix M, recovered from the stored inverse.
glm::mat4 object_to_world(const Instance& inst);

// World bounds of a unit-shape instance.
Bounds world_bounds(const Instance& inst);
// World bounds of a mesh instance: the box of its object-space box's corners under the matrix.
Bounds mesh_world_bounds(const TriangleMesh& mesh, const Instance& inst);

}  // namespace whitted
