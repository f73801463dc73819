#pragma once
#include <glm/glm.hpp>

namespace whitted {

// A ray p(t) = origin + t·direction. The direction need not be unit length: object-space rays
// keep the world ray's t, so hit distances compare across instances without conversion.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    glm::vec3 at(float t) const { return origin + t * direction; }
};

}  // namespace whitted
