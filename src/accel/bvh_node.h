#pragma once
// The 4-wide BVH's nodes, as plain data: the top level over instances (accel/bvh.h) and the
// bottom level over a mesh's triangles (mesh/mesh_bvh.h) are both made of them.
#include <cstdint>
#include <vector>

#include "base/big_vector.h"

#include "base/bounds.h"

namespace whitted {

// A node of `W` children (4: 128 bytes, two cache lines; 8: 256 bytes). box[row][slot]: rows
// lo.x, lo.y, lo.z, hi.x, hi.y, hi.z. An unused slot has an empty box (lo = +inf, hi = -inf) that
// no ray enters. The top level is 4-wide (tested with SSE); a mesh's BVH is 8-wide, tested in one
// AVX2 step where the CPU has it (mesh/mesh_walk8.h), as Embree's BVH8.
template <int W>
struct alignas(64) BvhNode {
    static constexpr int kWidth = W;
    float box[6][W];
    // Per slot: inner child = its node index; leaf = kLeafBit | first primitive << 4 | (count - 1).
    std::uint32_t child[W];
    std::uint32_t pad[W];

    static constexpr std::uint32_t kLeafBit = 0x80000000u;
    static constexpr std::uint32_t kMaxLeafSize = 16;
    static constexpr std::uint32_t kMaxInstances = 1u << 27;
    static bool is_leaf(std::uint32_t ref) { return (ref & kLeafBit) != 0; }
    static std::uint32_t leaf_first(std::uint32_t ref) { return (ref & ~kLeafBit) >> 4; }
    static std::uint32_t leaf_count(std::uint32_t ref) { return (ref & 15u) + 1; }
};
using Bvh4Node = BvhNode<4>;
using Bvh8Node = BvhNode<8>;
static_assert(sizeof(Bvh4Node) == 128);
static_assert(sizeof(Bvh8Node) == 256);

template <class Node>
struct BasicBvh {
    BigVector<Node> nodes;  // nodes[0] is the root; empty for an empty scene
    Bounds box;               // of the whole scene
    Bounds bounds() const { return box; }
};
using Bvh8 = BasicBvh<Bvh8Node>;  // a mesh's, over its triangles

// The top level, over instances. A scene of unit shapes has it 4-wide (`nodes`: the packet walk
// reads it, and single rays where the CPU lacks AVX2) and, where the CPU has AVX2, also the same
// tree collapsed 8-wide (`wide`) for single rays, tested in AVX2 steps. A scene with mesh instances
// has it 8-wide only (`wide`, `nodes` empty): with the meshes' own 8-wide BVHs a ray runs AVX2
// box tests all the way down, and its packets go one ray at a time (bvh_packet.cpp).
struct Bvh : BasicBvh<Bvh4Node> {
    Bvh8 wide;
    bool empty() const { return nodes.empty() && wide.nodes.empty(); }
};

// The costs the binned SAH build weighs: a traversal step against one primitive test, and the
// most primitives a leaf may hold (<= Bvh4Node::kMaxLeafSize); `block` primitives are tested at
// once (a mesh's four-lane triangle test), so a leaf costs its count rounded up to whole blocks.
struct BvhBuildCosts {
    float traversal_cost;
    std::uint32_t max_leaf;
    std::uint32_t block = 1;
};

}  // namespace whitted
