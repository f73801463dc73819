#pragma once
// Bounding volume hierarchy over the instances' world bounds. Built as a binary tree with the
// binned surface area heuristic, then collapsed into a 4-wide tree whose nodes hold their four
// children's boxes side by side, so that one SIMD test checks all four. Instances are reordered
// so that every leaf is a contiguous range.
#include <cstdint>
#include <vector>

#include "flatten/flat_scene.h"
#include "shapes/bounds.h"
#include "shapes/ray.h"
#include "shapes/unit_shapes.h"

namespace whitted {

// 128 bytes, two cache lines. box[row][slot]: rows lo.x, lo.y, lo.z, hi.x, hi.y, hi.z. An unused
// slot has an empty box (lo = +inf, hi = -inf) that no ray enters.
struct alignas(64) Bvh4Node {
    float box[6][4];
    // Per slot: inner child = its node index; leaf = kLeafBit | first instance << 4 | (count - 1).
    std::uint32_t child[4];
    std::uint32_t pad[4];

    static constexpr std::uint32_t kLeafBit = 0x80000000u;
    static constexpr std::uint32_t kMaxLeafSize = 16;
    static constexpr std::uint32_t kMaxInstances = 1u << 27;
    static bool is_leaf(std::uint32_t ref) { return (ref & kLeafBit) != 0; }
    static std::uint32_t leaf_first(std::uint32_t ref) { return (ref & ~kLeafBit) >> 4; }
    static std::uint32_t leaf_count(std::uint32_t ref) { return (ref & 15u) + 1; }
};
static_assert(sizeof(Bvh4Node) == 128);

struct Bvh {
    std::vector<Bvh4Node> nodes;  // nodes[0] is the root; empty for an empty scene
    Bounds box;                   // of the whole scene
    Bounds bounds() const { return box; }
};

// Builds the hierarchy and reorders `instances` to match it, on `threads` threads (0 = all
// hardware threads; the tree is the same for any count). Throws std::length_error beyond
// Bvh4Node::kMaxInstances instances. With `leaf_order`: the instance now at place i was at
// (*leaf_order)[i] (for side tables that follow the instances).
Bvh build_bvh(std::vector<Instance>& instances, int threads = 0, std::vector<std::uint32_t>* leaf_order = nullptr);

struct Hit {
    float t;
    std::uint32_t instance;
    ShapePart part;
};

// Nearest hit with t in (t_min, t_max); of hits at the same t, the lowest instance index.
bool intersect_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                       Hit& hit);

// The nearest-hit query done by testing every instance: the reference the BVH is tested against.
bool intersect_nearest_brute_force(const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                                   Hit& hit);

}  // namespace whitted
