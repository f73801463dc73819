#pragma once
// Any-hit traversal of the 4-wide BVH, as Embree's rtcOccluded with an intersection filter: every
// instance the ray crosses within (t_min, t_max) is offered to a visitor, in no particular order,
// until the visitor says stop. Occlusion stops at the first; coloured-glass shadows multiply
// colours and stop at the first opaque one (integrator/glass_transmittance.h). A template, so the
// visitor is inlined into the loop.
#include <cstdint>
#include <vector>

#include "accel/bvh.h"
#include "accel/bvh_box_test.h"
#include "accel/bvh_ray.h"

namespace whitted {

// Calls visit(instance index, crossings) for every instance whose surface the ray crosses within
// (t_min, t_max), crossings being 1 or 2 (a closed shape entered and left). visit returns false to
// stop. Returns false if it was stopped, true if every crossing was visited.
template <class Visit>
bool for_each_crossing(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min,
                       float t_max, Visit&& visit) {
    if (bvh.nodes.empty()) return true;
    const bvh_detail::BoxRay box_ray(ray);
    const bvh_detail::BoxTester tester(box_ray);
    const Bvh4Node* nodes = bvh.nodes.data();
    const Instance* inst = instances.data();

    std::uint32_t stack[bvh_detail::kStackSize];
    int top = 0;
    std::uint32_t ref = 0;
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            float tn[4];
            const Bvh4Node& n = nodes[ref];
            int mask = tester.test(n, t_min, t_max, tn);
            if (mask != 0) {
                // Any order will do: go into the first, push the others.
                ref = n.child[bvh_detail::lowest_bit(mask)];
                mask &= mask - 1;
                while (mask != 0) {
                    stack[top++] = n.child[bvh_detail::lowest_bit(mask)];
                    mask &= mask - 1;
                }
                continue;
            }
        } else {
            const std::uint32_t first = Bvh4Node::leaf_first(ref), end = first + Bvh4Node::leaf_count(ref);
            for (std::uint32_t i = first; i < end; ++i) {
                const auto s = bvh_detail::intersect_instance(inst[i], ray);
                if (s.count == 0) continue;
                const int crossings = (s.t[0] > t_min && s.t[0] < t_max) + (s.t[1] > t_min && s.t[1] < t_max);
                if (crossings != 0 && !visit(i, crossings)) return false;
            }
        }
        if (top == 0) return true;
        ref = stack[--top];
    }
}

// The same, testing every instance (the reference for the tests).
template <class Visit>
bool for_each_crossing_brute_force(const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                                   Visit&& visit) {
    for (std::uint32_t i = 0; i < instances.size(); ++i) {
        const auto s = bvh_detail::intersect_instance(instances[i], ray);
        if (s.count == 0) continue;
        const int crossings = (s.t[0] > t_min && s.t[0] < t_max) + (s.t[1] > t_min && s.t[1] < t_max);
        if (crossings != 0 && !visit(i, crossings)) return false;
    }
    return true;
}

}  // namespace whitted
