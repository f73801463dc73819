#include "accel/instance_geometry.h"

namespace whitted {

glm::mat4 object_to_world(const Instance& inst) {
    glm::dmat4 w(1.0);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) w[c][r] = inst.world_to_object[r][c];
    return glm::mat4(glm::inverse(w));
}

Bounds world_bounds(const Instance& inst) { return unit_shape_world_bounds(inst.kind, object_to_world(inst)); }

}  // namespace whitted
