#pragma once
// The bottom level of the two-level BVH: one SAH BVH over a mesh's triangles, in object space,
// built once per mesh file and shared by all its instances; and the ray queries against it. The
// top level (accel/bvh.h) reaches these through a mesh instance, with the ray in object space.
#include <atomic>
#include <cstdint>

#include "accel/bvh_box_test_avx2.h"
#include "accel/bvh_node.h"
#include "accel/bvh_walk.h"
#include "accel/triangle_block.h"
#include "base/big_vector.h"
#include "data/triangle_mesh.h"
#include "accel/watertight_triangle.h"
#include "accel/watertight_triangle4.h"

namespace whitted {

// A mesh's BVH: what a ray query reads, nothing of the mesh but its triangles' corners.
struct MeshBvh {
    Bvh8 bvh;  // over the mesh's triangles, whose order it set; its leaves index `blocks`
    // The leaves' triangles four to a block, in leaf order, and each block's first triangle (the
    // others follow it in the mesh's `triangles`).
    BigVector<TriangleBlock> blocks;
    BigVector<std::uint32_t> block_first_triangle;

    // Bytes of memory held (the mesh's own: TriangleMesh::memory_bytes).
    std::size_t memory_bytes() const;
};

// Builds the BVH of `mesh`, reordering mesh.triangles to its leaf order (and copying them into
// its blocks); sets mesh.box. On `threads` threads (0 = all); the result is the same for any count.
// Throws std::length_error beyond Bvh8Node::kMaxInstances triangles.
// With `cancel` set the build stops early and leaves an empty BVH.
MeshBvh build_mesh_bvh(TriangleMesh& mesh, int threads = 0, const std::atomic<bool>* cancel = nullptr);

struct MeshHit {
    float t, u, v;
    std::uint32_t triangle;
};

// The nearest triangle the object-space ray meets with t in (t_min, t_max); of equal distances the
// lowest triangle index, so the answer does not depend on the order the BVH visits them in.
bool mesh_intersect_nearest(const MeshBvh& mesh, const Ray& ray, float t_min, float t_max, MeshHit& hit);

// The same by testing every triangle: the reference for the tests.
bool mesh_intersect_nearest_brute_force(const TriangleMesh& mesh, const Ray& ray, float t_min, float t_max,
                                        MeshHit& hit);

// The walks test a node's eight boxes in one AVX2 step where the CPU has AVX2, else in two SSE
// steps; the answers are the same. Tests turn AVX2 off to check that; returns whether it is on
// (never where the CPU lacks it).
bool set_mesh_walks_use_avx2(bool on);

namespace mesh_detail {

inline bool cpu_allows_avx2() {
#ifdef WHITTED_BVH_AVX2
    return bvh_detail::cpu_has_avx2();
#else
    return false;
#endif
}
// Read once per mesh query (inline: no call for it).
inline bool use_avx2 = cpu_allows_avx2();

template <class Tester, class Visit>
WHITTED_BVH_INLINE bool for_each_crossing_with(const MeshBvh& mesh, const Ray& ray, float t_min, float t_max,
                                               Visit& visit) {
    // Set up at the first leaf: a shadow ray often crosses an instance's box without reaching one.
    WatertightRay4 wr4;
    bool ready = false;
    const TriangleBlock* blocks = mesh.blocks.data();
    const bvh_detail::BoxRay box_ray(ray);
    return bvh_detail::walk_any_with<true>(
        Tester(box_ray), mesh.bvh, t_min, t_max, [&](std::uint32_t first, std::uint32_t end) WHITTED_BVH_LAMBDA_INLINE {
            if (!ready) {
                wr4 = WatertightRay4(WatertightRay(ray));
                ready = true;
            }
            // `first` is the leaf's first block, end − first its number of triangles.
            for (std::uint32_t b = first, left = end - first; left > 0; ++b, left -= left < 4 ? left : 4) {
                Triangle4Hits h;
                int mask = intersect_triangles4(wr4, blocks[b], left < 4 ? left : 4, t_min, t_max, h);
                for (; mask != 0; mask &= mask - 1)
                    if (!visit(mesh.block_first_triangle[b] + std::uint32_t(__builtin_ctz(unsigned(mask)))))
                        return false;
            }
            return true;
        });
}

#ifdef WHITTED_BVH_AVX2
template <class Visit>
[[gnu::target("avx2"), gnu::flatten]] bool for_each_crossing_avx2(const MeshBvh& mesh, const Ray& ray,
                                                                  float t_min, float t_max, Visit& visit) {
    return for_each_crossing_with<bvh_detail::BoxTesterAvx2>(mesh, ray, t_min, t_max, visit);
}
#endif

}  // namespace mesh_detail

// Calls visit(triangle) for every triangle the ray crosses with t in (t_min, t_max), in no
// particular order, until it returns false; returns false if stopped.
template <class Visit>
bool mesh_for_each_crossing(const MeshBvh& mesh, const Ray& ray, float t_min, float t_max, Visit&& visit) {
#ifdef WHITTED_BVH_AVX2
    if (mesh_detail::use_avx2) return mesh_detail::for_each_crossing_avx2(mesh, ray, t_min, t_max, visit);
#endif
    return mesh_detail::for_each_crossing_with<bvh_detail::BoxTester>(mesh, ray, t_min, t_max, visit);
}

}  // namespace whitted
