// Traversal of the 4-wide BVH: one SSE test gives a ray's entry distance into all four child
// boxes, the hit children are visited nearest first (nearest-hit queries) with a small fixed
// stack, and a nearer hit found meanwhile prunes what is left on the stack. (Any-hit queries:
// bvh_any_hit.h.)
#include <algorithm>
#include <cmath>
#include <limits>

#include "accel/bvh.h"
#include "accel/bvh_box_test.h"
#include "accel/bvh_ray.h"

namespace whitted {
namespace {

using bvh_detail::BoxRay;
using bvh_detail::BoxTester;
using bvh_detail::intersect_instance;
using bvh_detail::lowest_bit;
using bvh_detail::kStackSize;

struct StackEntry {
    std::uint32_t ref;
    float t;  // entry distance of its box, to skip it once a nearer hit is known
};

}  // namespace

bool intersect_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                       Hit& hit) {
    if (bvh.nodes.empty()) return false;
    const BoxRay box_ray(ray);
    const BoxTester tester(box_ray);
    const Bvh4Node* nodes = bvh.nodes.data();
    const Instance* inst = instances.data();
    bool found = false;
    float best = t_max;
    std::uint32_t best_index = 0;
    ShapePart best_part = kPartSide;

    StackEntry stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;  // the root (an inner node)
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            float tn[4];
            int mask = tester.test(nodes[ref], t_min, best, tn);
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
            const std::uint32_t first = Bvh4Node::leaf_first(ref), end = first + Bvh4Node::leaf_count(ref);
            for (std::uint32_t i = first; i < end; ++i)
                bvh_detail::offer_nearest(intersect_instance(inst[i], ray), i, t_min, t_max, best, best_index, best_part,
                                          found);
        }
        // Pop, skipping boxes that a nearer hit found meanwhile has made irrelevant.
        for (;;) {
            if (top == 0) {
                if (found) hit = {best, best_index, best_part};
                return found;
            }
            const StackEntry& e = stack[--top];
            if (e.t <= best) {
                ref = e.ref;
                break;
            }
        }
    }
}

bool intersect_nearest_brute_force(const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                                   Hit& hit) {
    bool found = false;
    float best = t_max;
    for (std::uint32_t i = 0; i < instances.size(); ++i) {
        float t;
        ShapePart part;
        if (nearest_hit(intersect_unit_shape(instances[i].kind, to_object_space(instances[i], ray)), t_min, best, t, part)) {
            best = t;
            hit = {t, i, part};
            found = true;
        }
    }
    return found;
}

}  // namespace whitted
