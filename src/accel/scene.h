#pragma once
// The renderable scene: the render-ready data and the acceleration structure behind one narrow
// interface of ray queries (as Embree's rtcIntersect / rtcOccluded, pbrt's Intersect /
// IntersectP). Integrators ask it; they never pair the BVH with the instance array themselves.
#include <limits>

#include "accel/bvh.h"
#include "accel/bvh_any_hit.h"
#include "accel/bvh_packet.h"
#include "accel/mesh_bvh.h"
#include "data/scene_data.h"

namespace whitted {

struct Scene {
    SceneData data;
    Bvh bvh;                         // over data.instances
    std::vector<MeshBvh> mesh_bvhs;  // one per data.meshes

    static constexpr float kInfinity = std::numeric_limits<float>::infinity();

    // The nearest hit along the ray with t in (0, t_max); of equal distances, the lowest instance.
    bool intersect(const Ray& ray, Hit& hit, float t_max = kInfinity) const {
        return intersect_nearest(bvh, data.instances, ray, 0.0f, t_max, hit, &mesh_bvhs);
    }
    // The same for the lanes of a packet set in `active`, exactly as one by one; bit l of the
    // result says whether lane l hit (hits[l] is written only then).
    unsigned intersect(const Ray (&rays)[kPacketSize], unsigned active, Hit (&hits)[kPacketSize],
                       float t_max = kInfinity) const {
        return intersect_nearest_packet(bvh, data.instances, rays, active, 0.0f, t_max, hits, &mesh_bvhs);
    }
    // Whether anything lies along the ray with t in (0, t_max).
    bool occluded(const Ray& ray, float t_max) const {
        return !for_each_crossing(bvh, data.instances, &mesh_bvhs, ray, 0.0f, t_max,
                                  [](std::uint32_t, int) { return false; });
    }
    // The same for the lanes of a packet set in `active`: bit l of the result says lane l is blocked.
    unsigned occluded(const Ray (&rays)[kPacketSize], unsigned active, float t_max) const {
        Hit hits[kPacketSize];
        return intersect(rays, active, hits, t_max);
    }
    // Every instance the ray crosses with t in (0, t_max), offered to visit(instance, crossings)
    // until it returns false (an intersection filter; a mesh once per triangle crossed); returns
    // false if it stopped.
    template <class Visit>
    bool visit_crossings(const Ray& ray, float t_max, Visit&& visit) const {
        return for_each_crossing(bvh, data.instances, &mesh_bvhs, ray, 0.0f, t_max, visit);
    }

    const Material& material(std::uint32_t instance) const { return data.materials[data.instances[instance].material]; }
    const Material& material(const Hit& hit) const { return material(hit.instance); }
};

// Builds the BVH of every mesh (reordering its triangles), then the BVH over the instances
// (reordering data.instances to match it), on `threads` threads (0 = all). With `cancel` set
// (another thread, a signal handler) it stops within a fraction of a second, leaving a scene that
// must not be used.
Scene accelerate(SceneData data, int threads = 0, const std::atomic<bool>* cancel = nullptr);

}  // namespace whitted
