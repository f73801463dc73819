// Nearest-hit traversal of the top-level BVH (the walk itself: bvh_walk.h; any-hit queries:
// bvh_any_hit.h). Unit shapes are intersected in the leaves, mesh instances go down their own BVH.
#include <algorithm>
#include <cmath>
#include <limits>

#include "accel/bvh.h"
#include "accel/bvh_mesh_leaf.h"
#include "accel/bvh_walk.h"

namespace whitted {

namespace {

// The walk over `tree` (4- or 8-wide) with box tester Tester. kMeshes: the scene has mesh
// instances, whose own BVHs the leaves go down (else no instance's kind is tested against Mesh).
template <bool kMeshes, class Tester, class Node>
WHITTED_BVH_INLINE bool nearest_on(const BasicBvh<Node>& tree, const Instance* inst, const MeshBvh* mesh,
                                   const Ray& ray, float t_min, float t_max, Hit& hit) {
    bool found = false;
    float best = t_max;
    std::uint32_t best_index = 0;
    ShapePart best_part = kPartSide;
    bvh_detail::TriangleState tri;
    const auto leaf = [&](std::uint32_t first, std::uint32_t end) WHITTED_BVH_LAMBDA_INLINE {
        for (std::uint32_t i = first; i < end; ++i) {
            if constexpr (kMeshes) {
                if (inst[i].kind == ShapeKind::Mesh) {
                    bvh_detail::offer_mesh_nearest(mesh[inst[i].mesh], inst[i], ray, i, t_min, t_max, best,
                                                   best_index, best_part, found, tri);
                    continue;
                }
            }
            bvh_detail::offer_nearest(bvh_detail::intersect_instance(inst[i], ray), i, t_min, t_max, best, best_index,
                                      best_part, found);
        }
    };
    const bvh_detail::BoxRay box_ray(ray);
    bvh_detail::walk_nearest_with(Tester(box_ray), tree, t_min, best, leaf);
    if (!found) return false;
    hit = kMeshes ? bvh_detail::make_hit(inst, best, best_index, best_part, tri) : Hit{best, best_index, best_part};
    return true;
}

#ifdef WHITTED_BVH_AVX2
[[gnu::target("avx2"), gnu::flatten]] bool nearest_with_meshes_avx2(const Bvh8& tree, const Instance* inst,
                                                                    const MeshBvh* mesh, const Ray& ray,
                                                                    float t_min, float t_max, Hit& hit) {
    return nearest_on<true, bvh_detail::BoxTesterAvx2>(tree, inst, mesh, ray, t_min, t_max, hit);
}

// A scene of unit shapes on a CPU with AVX2: single rays take the tree's 8-wide copy, 1.1-1.3x
// the rays per second of the 4-wide walk below (bench/RESULTS.md).
[[gnu::target("avx2"), gnu::flatten]] bool nearest_unit_shapes_avx2(const Bvh8& tree, const Instance* inst,
                                                                    const Ray& ray, float t_min, float t_max,
                                                                    Hit& hit) {
    return nearest_on<false, bvh_detail::BoxTesterAvx2>(tree, inst, nullptr, ray, t_min, t_max, hit);
}
#endif

bool nearest_with_meshes(const Bvh& bvh, const Instance* inst, const MeshBvh* mesh, const Ray& ray, float t_min,
                         float t_max, Hit& hit) {
    if (bvh.wide.nodes.empty())  // a tree built without its 8-wide copy
        return nearest_on<true, bvh_detail::BoxTester>(static_cast<const BasicBvh<Bvh4Node>&>(bvh), inst, mesh, ray,
                                                       t_min, t_max, hit);
#ifdef WHITTED_BVH_AVX2
    if (mesh_detail::use_avx2) return nearest_with_meshes_avx2(bvh.wide, inst, mesh, ray, t_min, t_max, hit);
#endif
    return nearest_on<true, bvh_detail::BoxTester>(bvh.wide, inst, mesh, ray, t_min, t_max, hit);
}

// The walk of a scene of unit shapes alone over its 4-wide tree (where the CPU lacks AVX2, or the
// tests turn it off), written out by hand as before the mesh-capable walk
// rather than through walk_nearest: the same order, pruning and tie rule (so the same
// hits), but GCC keeps the box test's per-ray row offsets in registers here and not in the
// template (about 100 M instructions of the one-sample 1080p render, bench/RESULTS.md).
bool nearest_unit_shapes(const Bvh& bvh, const Instance* inst, const Ray& ray, float t_min, float t_max, Hit& hit) {
    using bvh_detail::lowest_bit;
    struct StackEntry {
        std::uint32_t ref;
        float t;  // entry distance of its box, to skip it once a nearer hit is known
    };
    if (bvh.nodes.empty()) return false;
    const bvh_detail::BoxRay box_ray(ray);
    if (!box_ray.finite) return false;
    const bvh_detail::BoxTester tester(box_ray);
    const Bvh4Node* nodes = bvh.nodes.data();
    bool found = false;
    float best = t_max;
    std::uint32_t best_index = 0;
    ShapePart best_part = kPartSide;

    StackEntry stack[bvh_detail::kStackSize];
    int top = 0;
    std::uint32_t ref = 0;  // the root (an inner node)
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            float tn[4];
            int mask = tester.test(nodes[ref], bvh_detail::box_limit(t_min), bvh_detail::box_limit(best), tn);
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
                bvh_detail::offer_nearest(bvh_detail::intersect_instance(inst[i], ray), i, t_min, t_max, best,
                                          best_index, best_part, found);
        }
        // Pop, skipping boxes that a nearer hit found meanwhile has made irrelevant.
        for (;;) {
            if (top == 0) {
                if (found) hit = Hit{best, best_index, best_part};
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

}  // namespace

bool intersect_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                       Hit& hit, const std::vector<MeshBvh>* meshes) {
    if (bvh_detail::has_meshes(meshes))
        return nearest_with_meshes(bvh, instances.data(), meshes->data(), ray, t_min, t_max, hit);
#ifdef WHITTED_BVH_AVX2
    if (mesh_detail::use_avx2 && !bvh.wide.nodes.empty())
        return nearest_unit_shapes_avx2(bvh.wide, instances.data(), ray, t_min, t_max, hit);
#endif
    return nearest_unit_shapes(bvh, instances.data(), ray, t_min, t_max, hit);
}

bool intersect_nearest_brute_force(const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                                   Hit& hit, const std::vector<TriangleMesh>* meshes) {
    bool found = false;
    float best = t_max;
    for (std::uint32_t i = 0; i < instances.size(); ++i) {
        if (instances[i].kind == ShapeKind::Mesh) {
            MeshHit h;
            if (mesh_intersect_nearest_brute_force((*meshes)[instances[i].mesh], to_object_space(instances[i], ray),
                                                   t_min, best, h)) {
                best = h.t;
                hit = {h.t, i, kPartSide, h.triangle, h.u, h.v};
                found = true;
            }
            continue;
        }
        float t;
        ShapePart part;
        if (nearest_hit(intersect_unit_shape(instances[i].kind, to_object_space(instances[i], ray)), t_min, best, t, part)) {
            best = t;
            hit = {t, i, part, 0, 0.0f, 0.0f};
            found = true;
        }
    }
    return found;
}

}  // namespace whitted
