#pragma once
// The single-ray walks through a 4-wide BVH, whatever its leaves hold: the top level's instances
// (bvh_traverse.cpp, bvh_any_hit.h) and a mesh's triangles (mesh/mesh_bvh.h). Templates on the
// leaf handler, so it is inlined into the loop.
#include <cstdint>

#include "accel/bvh_box_test.h"
#include "accel/bvh_node.h"
#include "accel/bvh_ray.h"

namespace whitted::bvh_detail {

// Nearest-hit walk: the hit children are visited nearest first with a small fixed stack, and
// boxes entered beyond `best` are skipped. leaf(first, end) tests the leaf's primitives
// [first, end) and may lower `best` (which starts at the query's t_max).
template <class Leaf>
WHITTED_BVH_INLINE void walk_nearest(const Bvh& bvh, const Ray& ray, float t_min, float& best, Leaf&& leaf) {
    if (bvh.nodes.empty()) return;
    struct StackEntry {
        std::uint32_t ref;
        float t;  // entry distance of its box, to skip it once a nearer hit is known
    };
    const BoxRay box_ray(ray);
    const BoxTester tester(box_ray);
    const BoxLimit lo = box_limit(t_min);
    const Bvh4Node* nodes = bvh.nodes.data();
    StackEntry stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;  // the root (an inner node)
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            float tn[4];
            int mask = tester.test(nodes[ref], lo, box_limit(best), tn);
            const Bvh4Node& n = nodes[ref];
            if (mask != 0) {
                int i = lowest_bit(mask);
                mask &= mask - 1;
                if (mask == 0) {  // one child: go straight on
                    ref = n.child[i];
                    continue;
                }
                const int j = lowest_bit(mask);
                mask &= mask - 1;
                if (mask == 0) {  // two: the common case, no sorting loop
                    const bool swap = tn[j] < tn[i];
                    const int near = swap ? j : i, far = swap ? i : j;
                    stack[top++] = {n.child[far], tn[far]};
                    ref = n.child[near];
                    continue;
                }
                mask |= 1 << j;
                // Several: push all but the nearest, farthest first (insertion by distance).
                StackEntry hits[4];
                int count = 0;
                hits[count++] = {n.child[i], tn[i]};
                do {
                    i = lowest_bit(mask);
                    mask &= mask - 1;
                    StackEntry e{n.child[i], tn[i]};
                    int k = count++;
                    while (k > 0 && hits[k - 1].t < e.t) { hits[k] = hits[k - 1]; --k; }
                    hits[k] = e;
                } while (mask != 0);
                for (int k = 0; k < count - 1; ++k) stack[top++] = hits[k];
                ref = hits[count - 1].ref;
                continue;
            }
        } else {
            const std::uint32_t first = Bvh4Node::leaf_first(ref);
            leaf(first, first + Bvh4Node::leaf_count(ref));
        }
        // Pop, skipping boxes that a nearer hit found meanwhile has made irrelevant.
        for (;;) {
            if (top == 0) return;
            const StackEntry& e = stack[--top];
            if (e.t <= best) {
                ref = e.ref;
                break;
            }
        }
    }
}

// Any-hit walk: every leaf whose box the ray enters within (t_min, t_max) is handed to
// leaf(first, end), in no particular order, until it returns false. Returns false if stopped.
// kNearFirst: of two or more children hit, the nearest box is entered first (a mesh's triangles:
// a shadow ray from a surface meets the nearby surface it is blocked by sooner; the order of the
// leaves is still unspecified).
template <bool kNearFirst = false, class Leaf>
WHITTED_BVH_INLINE bool walk_any(const Bvh& bvh, const Ray& ray, float t_min, float t_max, Leaf&& leaf) {
    if (bvh.nodes.empty()) return true;
    const BoxRay box_ray(ray);
    const BoxTester tester(box_ray);
    const BoxLimit lo = box_limit(t_min), hi = box_limit(t_max);
    const Bvh4Node* nodes = bvh.nodes.data();
    std::uint32_t stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            float tn[4];
            const Bvh4Node& n = nodes[ref];
            int mask = tester.test(n, lo, hi, tn);
            if (mask != 0) {
                if constexpr (kNearFirst) {
                    int i = lowest_bit(mask);
                    mask &= mask - 1;
                    // The nearest goes on; the others are pushed in the order found.
                    while (mask != 0) {
                        const int j = lowest_bit(mask);
                        mask &= mask - 1;
                        const bool nearer = tn[j] < tn[i];
                        stack[top++] = n.child[nearer ? i : j];
                        if (nearer) i = j;
                    }
                    ref = n.child[i];
                    continue;
                }
                // Any order will do: go into the first, push the others.
                ref = n.child[lowest_bit(mask)];
                mask &= mask - 1;
                while (mask != 0) {
                    stack[top++] = n.child[lowest_bit(mask)];
                    mask &= mask - 1;
                }
                continue;
            }
        } else {
            const std::uint32_t first = Bvh4Node::leaf_first(ref);
            if (!leaf(first, first + Bvh4Node::leaf_count(ref))) return false;
        }
        if (top == 0) return true;
        ref = stack[--top];
    }
}

}  // namespace whitted::bvh_detail
