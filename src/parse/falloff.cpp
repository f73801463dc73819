#include "parse/falloff.h"

namespace whitted {

bool falloff_can_be_nonpositive(const glm::vec3& clq) {
    const double c = clq.x, l = clq.y, q = clq.z;
    if (q < 0) return true;  // -q·d² wins for large d
    if (q == 0) {
        if (l < 0) return true;     // linear, decreasing to -inf
        if (l == 0) return c <= 0;  // constant
        return c < 0;               // increasing from c (at d -> 0+); c = 0 is positive for d > 0
    }
    // q > 0: a parabola. If l >= 0 it increases on d > 0 from c (not reached); otherwise its
    // minimum, at d* = -l / 2q > 0, is c - l² / 4q.
    if (l >= 0) return c < 0;
    return c - l * l / (4 * q) <= 0;
}

}  // namespace whitted
