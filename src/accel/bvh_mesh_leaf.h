#pragma once
// A mesh instance met in a leaf of the top-level BVH: the ray goes into the mesh's object space
// and down its own BVH (mesh/mesh_bvh.h). Shared by the single-ray, packet and any-hit walks,
// which must agree bit for bit.
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "accel/bvh_ray.h"
#include "accel/mesh_bvh.h"

namespace whitted::bvh_detail {

// Whether a query may meet mesh instances: only then do the walks test each instance's kind (a
// mesh instance's index points into a non-empty `meshes`). Queries pick their walk once with it.
inline bool has_meshes(const std::vector<MeshBvh>* meshes) { return meshes != nullptr && !meshes->empty(); }

// What a ray's nearest hit so far says about triangles (unit shapes leave it alone; the hit's
// fields are cleared for them at the end).
struct TriangleState {
    std::uint32_t triangle = 0;
    float u = 0.0f, v = 0.0f;
};

// offer_nearest (bvh_ray.h) for mesh instance `index`: its nearest triangle with t in
// (t_min, t_max), searched only up to the nearest hit so far (inclusive, for the tie rule).
WHITTED_BVH_INLINE void offer_mesh_nearest(const MeshBvh& mesh, const Instance& inst, const Ray& ray,
                                           std::uint32_t index, float t_min, float t_max, float& best,
                                           std::uint32_t& best_index, ShapePart& best_part, bool& found,
                                           TriangleState& tri) {
    const float limit = found ? std::nextafter(best, std::numeric_limits<float>::infinity()) : t_max;
    MeshHit h;
    if (!mesh_intersect_nearest(mesh, to_object_space(inst, ray), t_min, limit, h)) return;
    if (!(h.t < t_max)) return;
    if (h.t < best || (h.t == best && found && index < best_index)) {
        best = h.t;
        best_index = index;
        best_part = kPartSide;
        found = true;
        tri = {h.triangle, h.u, h.v};
    }
}

// The Hit for the state above: triangle fields only for a mesh instance.
inline Hit make_hit(const Instance* instances, float t, std::uint32_t index, ShapePart part, const TriangleState& tri) {
    if (instances[index].kind == ShapeKind::Mesh) return Hit{t, index, part, tri.triangle, tri.u, tri.v};
    return Hit{t, index, part, 0, 0.0f, 0.0f};
}

}  // namespace whitted::bvh_detail
