// Nearest-hit traversal of the top-level BVH (the walk itself: bvh_walk.h; any-hit queries:
// bvh_any_hit.h). Unit shapes are intersected in the leaves, mesh instances go down their own BVH.
#include <algorithm>
#include <cmath>
#include <limits>

#include "accel/bvh.h"
#include "accel/bvh_mesh_leaf.h"
#include "accel/bvh_walk.h"

namespace whitted {

bool intersect_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                       Hit& hit, const std::vector<TriangleMesh>* meshes) {
    const Instance* inst = instances.data();
    const TriangleMesh* mesh = meshes ? meshes->data() : nullptr;
    bool found = false;
    float best = t_max;
    std::uint32_t best_index = 0;
    ShapePart best_part = kPartSide;
    bvh_detail::TriangleState tri;
    bvh_detail::walk_nearest(bvh, ray, t_min, best, [&](std::uint32_t first, std::uint32_t end) {
        for (std::uint32_t i = first; i < end; ++i) {
            if (inst[i].kind == ShapeKind::Mesh)
                bvh_detail::offer_mesh_nearest(mesh[inst[i].mesh], inst[i], ray, i, t_min, t_max, best, best_index,
                                               best_part, found, tri);
            else
                bvh_detail::offer_nearest(bvh_detail::intersect_instance(inst[i], ray), i, t_min, t_max, best,
                                          best_index, best_part, found);
        }
    });
    if (found) hit = bvh_detail::make_hit(inst, best, best_index, best_part, tri);
    return found;
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
