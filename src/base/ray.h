#pragma once
#include <glm/glm.hpp>

namespace whitted {

// A ray p(t) = origin + t·direction. The direction need not be unit length: object-space rays
// keep the world ray's t, so hit distances compare across instances without conversion.
struct Ray {
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f, 0.0f, -1.0f};
    // Where in the shutter interval the ray's camera sample was taken: 0 as it opens, 1 as it
    // closes. Only a render with a shutter over a moving scene reads it (accel/motion_set.h); every
    // ray a sample spawns carries its camera ray's.
    float time = 0.0f;
    glm::vec3 at(float t) const { return origin + t * direction; }
};

// Rays traced together as a packet: 4×4 pixels of a camera tile. Measured on the 1,000-sphere
// benchmark: 8 rays (4×2) 12% slower, 32 (8×4) no faster and slower on mixed shapes.
constexpr int kPacketSize = 16;

}  // namespace whitted
