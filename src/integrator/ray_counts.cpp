#include "integrator/ray_counts.h"

#include <algorithm>
#include <cstdint>

namespace whitted {

std::int64_t clock_read_nanos() {
    static const std::int64_t nanos = [] {
        std::int64_t shortest = INT64_MAX;
        for (int i = 0; i < 1000; ++i) {
            const auto a = std::chrono::steady_clock::now();
            const auto b = std::chrono::steady_clock::now();
            shortest = std::min<std::int64_t>(shortest, std::chrono::duration_cast<std::chrono::nanoseconds>(b - a).count());
        }
        return shortest;
    }();
    return nanos;
}

}  // namespace whitted
