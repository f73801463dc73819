#pragma once
// Any-hit traversal of the top-level BVH (8-wide where the CPU has AVX2, else 4-wide in a scene of
// unit shapes: accel/bvh_node.h),
// as Embree's rtcOccluded with an intersection filter: every
// instance the ray crosses within (t_min, t_max) is offered to a visitor, in no particular order,
// until the visitor says stop. Occlusion stops at the first; coloured-glass shadows multiply
// colours and stop at the first opaque one (integrator/glass_transmittance.h). A template, so the
// visitor is inlined into the loop.
#include <cstdint>
#include <vector>

#include "accel/bvh.h"
#include "accel/bvh_mesh_leaf.h"
#include "accel/bvh_walk.h"

namespace whitted {
namespace bvh_detail {

// Offers unit-shape instance i's crossings within (t_min, t_max) to visit; false if it said stop.
template <class Visit>
WHITTED_BVH_INLINE bool visit_unit_instance(const Instance& inst, std::uint32_t i, const Ray& ray, float t_min,
                                            float t_max, Visit& visit) {
    const auto s = intersect_instance(inst, ray);
    if (s.count == 0) return true;
    const int crossings = (s.t[0] > t_min && s.t[0] < t_max) + (s.t[1] > t_min && s.t[1] < t_max);
    return crossings == 0 || visit(i, crossings);
}

// The same for any instance: a mesh instance offers each triangle it crosses.
template <class Visit>
WHITTED_BVH_INLINE bool visit_instance(const Instance& inst, std::uint32_t i, const std::vector<MeshBvh>* meshes,
                                       const Ray& ray, float t_min, float t_max, Visit& visit) {
    if (inst.kind == ShapeKind::Mesh)
        return mesh_for_each_crossing((*meshes)[inst.mesh], to_object_space(inst, ray), t_min, t_max,
                                      [&](std::uint32_t) { return visit(i, 1); });
    return visit_unit_instance(inst, i, ray, t_min, t_max, visit);
}

// for_each_crossing's walk over `tree` (4- or 8-wide) with box tester Tester; kMeshes: the scene
// has mesh instances (else no instance's kind is tested against Mesh).
template <bool kMeshes, class Tester, class Node, class Visit>
WHITTED_BVH_INLINE bool walk_crossings_on(const BasicBvh<Node>& tree, const Instance* inst,
                                          const std::vector<MeshBvh>* meshes, const Ray& ray, float t_min,
                                          float t_max, Visit& visit) {
    const BoxRay box_ray(ray);
    return walk_any_with<false>(Tester(box_ray), tree, t_min, t_max,
                                [&](std::uint32_t first, std::uint32_t end) WHITTED_BVH_LAMBDA_INLINE {
                                    for (std::uint32_t i = first; i < end; ++i) {
                                        if constexpr (kMeshes) {
                                            if (!visit_instance(inst[i], i, meshes, ray, t_min, t_max, visit))
                                                return false;
                                        } else {
                                            if (!visit_unit_instance(inst[i], i, ray, t_min, t_max, visit))
                                                return false;
                                        }
                                    }
                                    return true;
                                });
}

#ifdef WHITTED_BVH_AVX2
// A scene of unit shapes on a CPU with AVX2: the tree's 8-wide copy in AVX2 steps.
template <class Visit>
[[gnu::target("avx2"), gnu::flatten]] bool walk_unit_crossings_avx2(const Bvh8& tree, const Instance* inst,
                                                                    const Ray& ray, float t_min, float t_max,
                                                                    Visit& visit) {
    return walk_crossings_on<false, BoxTesterAvx2>(tree, inst, nullptr, ray, t_min, t_max, visit);
}
#endif

// A scene of unit shapes: the 8-wide copy where the CPU has AVX2, else the 4-wide tree.
template <class Visit>
bool walk_unit_crossings(const Bvh& bvh, const Instance* inst, const Ray& ray, float t_min, float t_max,
                         Visit& visit) {
#ifdef WHITTED_BVH_AVX2
    if (mesh_detail::use_avx2 && !bvh.wide.nodes.empty())
        return walk_unit_crossings_avx2(bvh.wide, inst, ray, t_min, t_max, visit);
#endif
    return walk_crossings_on<false, BoxTester>(static_cast<const BasicBvh<Bvh4Node>&>(bvh), inst, nullptr, ray, t_min,
                                               t_max, visit);
}

template <class Tester, class Node, class Visit>
bool walk_mesh_crossings(const BasicBvh<Node>& tree, const Instance* inst, const std::vector<MeshBvh>* meshes,
                         const Ray& ray, float t_min, float t_max, Visit& visit) {
    return walk_crossings_on<true, Tester>(tree, inst, meshes, ray, t_min, t_max, visit);
}

#ifdef WHITTED_BVH_AVX2
// A scene with meshes on a CPU with AVX2: the 8-wide tree in AVX2 steps, the meshes' walks inlined.
template <class Visit>
[[gnu::target("avx2"), gnu::flatten]] bool walk_mesh_crossings_avx2(const Bvh8& tree, const Instance* inst,
                                                                    const std::vector<MeshBvh>* meshes,
                                                                    const Ray& ray, float t_min, float t_max,
                                                                    Visit& visit) {
    return walk_crossings_on<true, BoxTesterAvx2>(tree, inst, meshes, ray, t_min, t_max, visit);
}
#endif

// A scene with meshes: its 8-wide tree (the 4-wide one for a tree built without it).
template <class Visit>
bool walk_crossings_with_meshes(const Bvh& bvh, const Instance* inst, const std::vector<MeshBvh>* meshes,
                                const Ray& ray, float t_min, float t_max, Visit& visit) {
    if (bvh.wide.nodes.empty())
        return walk_mesh_crossings<BoxTester>(static_cast<const BasicBvh<Bvh4Node>&>(bvh), inst, meshes, ray, t_min,
                                              t_max, visit);
#ifdef WHITTED_BVH_AVX2
    if (mesh_detail::use_avx2) return walk_mesh_crossings_avx2(bvh.wide, inst, meshes, ray, t_min, t_max, visit);
#endif
    return walk_mesh_crossings<BoxTester>(bvh.wide, inst, meshes, ray, t_min, t_max, visit);
}

}  // namespace bvh_detail

// Calls visit(instance index, crossings) for every instance whose surface the ray crosses within
// (t_min, t_max), crossings being 1 or 2 (a closed shape entered and left); a mesh instance is
// offered once per triangle crossed, with 1. visit returns false to stop. Returns false if it was
// stopped, true if every crossing was visited. Mesh instances need `meshes`.
template <class Visit>
bool for_each_crossing(const Bvh& bvh, const std::vector<Instance>& instances, const std::vector<MeshBvh>* meshes,
                       const Ray& ray, float t_min, float t_max, Visit&& visit) {
    if (bvh_detail::has_meshes(meshes))
        return bvh_detail::walk_crossings_with_meshes(bvh, instances.data(), meshes, ray, t_min, t_max, visit);
    return bvh_detail::walk_unit_crossings(bvh, instances.data(), ray, t_min, t_max, visit);
}

template <class Visit>
bool for_each_crossing(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min,
                       float t_max, Visit&& visit) {
    return for_each_crossing(bvh, instances, nullptr, ray, t_min, t_max, visit);
}

// The same, testing every instance (the reference for the tests).
template <class Visit>
bool for_each_crossing_brute_force(const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                                   Visit&& visit, const std::vector<MeshBvh>* meshes = nullptr) {
    for (std::uint32_t i = 0; i < instances.size(); ++i)
        if (!bvh_detail::visit_instance(instances[i], i, meshes, ray, t_min, t_max, visit)) return false;
    return true;
}

}  // namespace whitted
