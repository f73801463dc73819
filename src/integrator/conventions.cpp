#include "integrator/conventions.h"

#include "accel/instance_geometry.h"

namespace whitted {

glm::vec3 normal_by_m(const Instance& inst, const glm::vec3& object_normal) {
    return glm::normalize(glm::vec3(object_to_world(inst) * glm::vec4(object_normal, 0.0f)));
}

}  // namespace whitted
