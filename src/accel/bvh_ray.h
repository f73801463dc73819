#pragma once
// The per-ray pieces that the single-ray traversal (bvh_traverse.cpp) and the packet traversal
// (bvh_packet.cpp) share. Both must return bit-identical hits, so the reciprocal direction, the
// instance test and the rule that picks the nearest hit exist once, here, inlined into both.
#include <cmath>
#include <cstdint>
#include <vector>

#include "accel/instance_geometry.h"
#include "shapes/unit_shape_math.h"

namespace whitted::bvh_detail {

// Binary depth is at most 64 SAH levels plus 27 median levels (bvh_build.cpp); every wide level
// consumes at least one binary level and pushes at most three entries.
constexpr int kStackSize = 3 * 96;

// 1/d for the box test. A zero component becomes a huge finite reciprocal, so that a ray lying
// exactly in a slab plane gives 0·huge = 0 rather than 0·inf = NaN.
inline float safe_reciprocal(float d) { return 1.0f / (std::fabs(d) > 1e-30f ? d : std::copysign(1e-30f, d)); }

// Forced inline: shared by two files, GCC would otherwise call these out of line from the
// single-ray traversal (one call per instance test).
#define WHITTED_BVH_INLINE [[gnu::always_inline]] inline
// The same for a lambda (after its parameter list): a walk's leaf handler, which GCC would
// otherwise call once per leaf.
#define WHITTED_BVH_LAMBDA_INLINE __attribute__((always_inline))

// The object-space interval of instance `inst` along the world ray.
WHITTED_BVH_INLINE shape_math::Span<float> intersect_instance(const Instance& inst, const Ray& ray) {
    const Ray o = to_object_space(inst, ray);
    if (inst.rescale) [[unlikely]]
        return shape_math::intersect_rescaled<float>(inst.kind, o.origin, o.direction);
    return shape_math::intersect<float>(inst.kind, o.origin, o.direction);
}

// Offers instance `index`'s interval `s` to a ray's nearest hit so far (best, best_index,
// best_part, found; best starts at t_max). The nearest crossing in (t_min, t_max) wins; of equal
// distances the lowest index, as in the brute-force loop, so the visiting order never matters.
WHITTED_BVH_INLINE void offer_nearest(const shape_math::Span<float>& s, std::uint32_t index, float t_min, float t_max, float& best,
                          std::uint32_t& best_index, ShapePart& best_part, bool& found) {
    if (s.count == 0) return;
    const int k = s.t[0] > t_min ? 0 : 1;
    const float t = s.t[k];
    if (!(t > t_min && t < t_max)) return;
    if (t < best || (t == best && found && index < best_index)) {
        best = t;
        best_index = index;
        best_part = s.part[k];
        found = true;
    }
}

}  // namespace whitted::bvh_detail
