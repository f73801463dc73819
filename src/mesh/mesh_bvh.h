#pragma once
// The bottom level of the two-level BVH: one SAH BVH over a mesh's triangles, in object space,
// built once per mesh file and shared by all its instances; and the ray queries against it. The
// top level (accel/) reaches these through a mesh instance, with the ray in object space.
#include <cstdint>

#include "accel/bvh_walk.h"
#include "mesh/triangle_mesh.h"
#include "mesh/watertight_triangle.h"
#include "mesh/watertight_triangle4.h"

namespace whitted {

// Builds mesh.bvh and reorders mesh.triangles (and their normal and uv corners) to its leaf
// order; sets mesh.box. On `threads` threads (0 = all); the result is the same for any count.
// Throws std::length_error beyond Bvh4Node::kMaxInstances triangles.
void build_mesh_bvh(TriangleMesh& mesh, int threads = 0);

struct MeshHit {
    float t, u, v;
    std::uint32_t triangle;
};

// The nearest triangle the object-space ray meets with t in (t_min, t_max); of equal distances the
// lowest triangle index, so the answer does not depend on the order the BVH visits them in.
bool mesh_intersect_nearest(const TriangleMesh& mesh, const Ray& ray, float t_min, float t_max, MeshHit& hit);

// The same by testing every triangle: the reference for the tests.
bool mesh_intersect_nearest_brute_force(const TriangleMesh& mesh, const Ray& ray, float t_min, float t_max,
                                        MeshHit& hit);

// Calls visit(triangle) for every triangle the ray crosses with t in (t_min, t_max), in no
// particular order, until it returns false; returns false if stopped.
template <class Visit>
bool mesh_for_each_crossing(const TriangleMesh& mesh, const Ray& ray, float t_min, float t_max, Visit&& visit) {
    const WatertightRay wr(ray);
    const WatertightRay4 wr4(wr);
    const TriangleBlock* blocks = mesh.blocks.data();
    return bvh_detail::walk_any<true>(mesh.bvh, ray, t_min, t_max, [&](std::uint32_t first, std::uint32_t end) {
        // `first` is the leaf's first block, end − first its number of triangles.
        for (std::uint32_t b = first, left = end - first; left > 0; ++b, left -= left < 4 ? left : 4) {
            Triangle4Hits h;
            int mask = intersect_triangles4(wr4, blocks[b], left < 4 ? left : 4, t_min, t_max, h);
            for (; mask != 0; mask &= mask - 1)
                if (!visit(mesh.block_first_triangle[b] + std::uint32_t(__builtin_ctz(unsigned(mask))))) return false;
        }
        return true;
    });
}

}  // namespace whitted
