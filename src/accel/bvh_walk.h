#pragma once
// The single-ray walks through a wide BVH, whatever its leaves hold: the top level's instances
// (4-wide; bvh_traverse.cpp, bvh_any_hit.h) and a mesh's triangles (8-wide; mesh/mesh_bvh.h).
// Templates on the node, the box tester and the leaf handler, so all are inlined into the loop.
#include <cstdint>

#include "accel/bvh_box_test.h"
#include "accel/bvh_node.h"
#include "accel/bvh_ray.h"

namespace whitted::bvh_detail {

// The stack a walk of W-wide nodes needs: binary depth is at most 96 (kStackSize, bvh_ray.h) and
// a wide level consumes at least one binary level and pushes at most W − 1 entries.
constexpr int walk_stack_size(int W) { return (W - 1) * (kStackSize / 3); }

// Nearest-hit walk: the hit children are visited nearest first with a small fixed stack, and
// boxes entered beyond `best` are skipped. leaf(first, end) tests the leaf's primitives
// [first, end) and may lower `best` (which starts at the query's t_max).
// walk_nearest with the box tester given.
template <class Tester, class Node, class Leaf>
WHITTED_BVH_INLINE void walk_nearest_with(const Tester& tester, const BasicBvh<Node>& bvh, float t_min, float& best,
                                          Leaf&& leaf) {
    if (bvh.nodes.empty() || !tester.r.finite) return;
    constexpr int W = Node::kWidth;
    struct StackEntry {
        std::uint32_t ref;
        float t;  // entry distance of its box, to skip it once a nearer hit is known
    };
    const typename Tester::Limit lo = tester.limit(t_min);
    const Node* nodes = bvh.nodes.data();
    StackEntry stack[walk_stack_size(W)];
    int top = 0;
    std::uint32_t ref = 0;  // the root (an inner node)
    for (;;) {
        if (!Node::is_leaf(ref)) {
            float tn[W];
            int mask = tester.test(nodes[ref], lo, tester.limit(best), tn);
            const Node& n = nodes[ref];
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
                StackEntry hits[W];
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
            const std::uint32_t first = Node::leaf_first(ref);
            leaf(first, first + Node::leaf_count(ref));
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

template <class Node, class Leaf>
WHITTED_BVH_INLINE void walk_nearest(const BasicBvh<Node>& bvh, const Ray& ray, float t_min, float& best, Leaf&& leaf) {
    const BoxRay box_ray(ray);
    walk_nearest_with(BoxTester(box_ray), bvh, t_min, best, leaf);
}

// Any-hit walk: every leaf whose box the ray enters within (t_min, t_max) is handed to
// leaf(first, end), in no particular order, until it returns false. Returns false if stopped.
// kNearFirst: of two or more children hit, the nearest box is entered first (a mesh's triangles:
// a shadow ray from a surface meets the nearby surface it is blocked by sooner; the order of the
// leaves is still unspecified).
template <bool kNearFirst, class Tester, class Node, class Leaf>
WHITTED_BVH_INLINE bool walk_any_with(const Tester& tester, const BasicBvh<Node>& bvh, float t_min, float t_max,
                                      Leaf&& leaf) {
    if (bvh.nodes.empty() || !tester.r.finite) return true;
    constexpr int W = Node::kWidth;
    const typename Tester::Limit lo = tester.limit(t_min), hi = tester.limit(t_max);
    const Node* nodes = bvh.nodes.data();
    std::uint32_t stack[walk_stack_size(W)];
    int top = 0;
    std::uint32_t ref = 0;
    for (;;) {
        if (!Node::is_leaf(ref)) {
            float tn[W];
            const Node& n = nodes[ref];
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
            const std::uint32_t first = Node::leaf_first(ref);
            if (!leaf(first, first + Node::leaf_count(ref))) return false;
        }
        if (top == 0) return true;
        ref = stack[--top];
    }
}

template <bool kNearFirst = false, class Node, class Leaf>
WHITTED_BVH_INLINE bool walk_any(const BasicBvh<Node>& bvh, const Ray& ray, float t_min, float t_max, Leaf&& leaf) {
    const BoxRay box_ray(ray);
    return walk_any_with<kNearFirst>(BoxTester(box_ray), bvh, t_min, t_max, leaf);
}

}  // namespace whitted::bvh_detail
