#pragma once
#include <algorithm>
#include <limits>

#include <glm/glm.hpp>

namespace whitted {

// Axis-aligned box; the default is empty (min > max) so that growing it by anything works.
struct Bounds {
    glm::vec3 lo{std::numeric_limits<float>::infinity()};
    glm::vec3 hi{-std::numeric_limits<float>::infinity()};

    void grow(const glm::vec3& p) { lo = glm::min(lo, p); hi = glm::max(hi, p); }
    void grow(const Bounds& b) { lo = glm::min(lo, b.lo); hi = glm::max(hi, b.hi); }
    glm::vec3 extent() const { return hi - lo; }
    glm::vec3 centre() const { return 0.5f * (lo + hi); }
    bool empty() const { return lo.x > hi.x || lo.y > hi.y || lo.z > hi.z; }
    // Grown on every side by `relative` times its largest coordinate magnitude (plus a tiny
    // absolute amount): room for the rounding of a hit computed another way than the box.
    Bounds padded(float relative) const {
        const glm::vec3 mag = glm::max(glm::abs(lo), glm::abs(hi));
        const glm::vec3 pad(relative * std::max(std::max(mag.x, mag.y), mag.z) + 1e-30f);
        return Bounds{lo - pad, hi + pad};
    }
    float surface_area() const {
        if (empty()) return 0.0f;
        glm::vec3 e = extent();
        return 2.0f * (e.x * e.y + e.y * e.z + e.z * e.x);
    }
};

}  // namespace whitted
