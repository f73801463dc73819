#pragma once
#include <chrono>
#include <cstdint>

namespace whitted {

enum class RayKind { Camera, Reflected, Refracted, Shadow };
constexpr int kRayKinds = 4;

// Rays traced, by kind; each render thread keeps its own and they are summed at the end.
struct RayCounts {
    std::uint64_t camera = 0, reflected = 0, refracted = 0, shadow = 0;
    std::uint64_t rejected = 0;  // samples whose colour was not finite (NaN, inf), counted as black
    // With `timing` on (--stats), one traversal in kTimeEvery of each kind is timed: the rays it
    // carried and its nanoseconds, from which each kind's rays per second through the acceleration
    // structure (the shading between them not counted). Off, nothing is timed.
    struct Timed {
        std::uint64_t calls = 0, rays = 0, nanos = 0;
    };
    // Two clock reads (about 50 ns) per 32 traversals: under 2 ns a traversal, against 15-100 ns.
    static constexpr std::uint64_t kTimeEvery = 32;
    bool timing = false;
    Timed timed[kRayKinds];

    std::uint64_t total() const { return camera + reflected + refracted + shadow; }
    // Rays of `kind` per second through the acceleration structure (0 when none was timed).
    double rays_per_second(RayKind kind) const {
        const Timed& t = timed[int(kind)];
        return t.nanos > 0 ? double(t.rays) / double(t.nanos) * 1e9 : 0.0;
    }
    RayCounts& operator+=(const RayCounts& o) {
        camera += o.camera; reflected += o.reflected; refracted += o.refracted; shadow += o.shadow;
        rejected += o.rejected;
        timing = timing || o.timing;
        for (int k = 0; k < kRayKinds; ++k) {
            timed[k].calls += o.timed[k].calls;
            timed[k].rays += o.timed[k].rays;
            timed[k].nanos += o.timed[k].nanos;
        }
        return *this;
    }
};

// What reading the clock twice adds to an interval timed between the reads (the shortest of
// many back-to-back reads, measured once): 20-30 ns, a fifth of a single ray's traversal.
std::int64_t clock_read_nanos();

// What trace() returns, timed into counts when counts.timing is on and this is the kTimeEvery-th
// traversal of its kind: `rays` of that kind (a packet's active lanes) traced by one call.
template <class Trace>
[[gnu::always_inline]] inline auto timed_trace(RayCounts& counts, RayKind kind, int rays, Trace&& trace)
    -> decltype(trace()) {
    if (!counts.timing) [[likely]]
        return trace();
    RayCounts::Timed& t = counts.timed[int(kind)];
    if (t.calls++ % RayCounts::kTimeEvery != 0) return trace();
    const auto start = std::chrono::steady_clock::now();
    auto result = trace();
    const auto nanos = std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - start);
    const std::int64_t clock = clock_read_nanos();
    t.nanos += std::uint64_t(nanos.count() > clock ? nanos.count() - clock : 0);
    t.rays += std::uint64_t(rays);
    return result;
}

}  // namespace whitted
