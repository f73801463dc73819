#pragma once
#include <cstdint>

namespace whitted {

// Rays traced, by kind; each render thread keeps its own and they are summed at the end.
struct RayCounts {
    std::uint64_t camera = 0, reflected = 0, refracted = 0, shadow = 0;
    std::uint64_t rejected = 0;  // samples whose colour was not finite (NaN, inf), counted as black
    std::uint64_t total() const { return camera + reflected + refracted + shadow; }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera; reflected += o.reflected; refracted += o.refracted; shadow += o.shadow;
        rejected += o.rejected;
        return *this;
    }
};

}  // namespace whitted
