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

// kMeshes: the scene has mesh instances. Without them the leaves test unit shapes alone, with no
// shape-kind branch and no triangle state (the query decides once which walk to take).
template <bool kMeshes>
bool nearest(const Bvh& bvh, const Instance* inst, const TriangleMesh* mesh, const Ray& ray, float t_min, float t_max,
             Hit& hit) {
    bool found = false;
    float best = t_max;
    std::uint32_t best_index = 0;
    ShapePart best_part = kPartSide;
    [[maybe_unused]] bvh_detail::TriangleState tri;
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
    bvh_detail::walk_nearest(bvh, ray, t_min, best, leaf);
    if (!found) return false;
    if constexpr (kMeshes)
        hit = bvh_detail::make_hit(inst, best, best_index, best_part, tri);
    else
        hit = Hit{best, best_index, best_part};
    return true;
}

}  // namespace

bool intersect_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                       Hit& hit, const std::vector<TriangleMesh>* meshes) {
    if (bvh_detail::has_meshes(meshes))
        return nearest<true>(bvh, instances.data(), meshes->data(), ray, t_min, t_max, hit);
    return nearest<false>(bvh, instances.data(), nullptr, ray, t_min, t_max, hit);
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
