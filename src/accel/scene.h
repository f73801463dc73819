#pragma once
// The renderable scene: the flattened arrays and the acceleration structure behind one narrow
// interface of ray queries (as Embree's rtcIntersect / rtcOccluded, pbrt's Intersect /
// IntersectP). Integrators ask it; they never pair the BVH with the instance array themselves.
#include <limits>

#include "accel/bvh.h"
#include "accel/bvh_any_hit.h"
#include "accel/bvh_packet.h"
#include "flatten/flat_scene.h"

namespace whitted {

struct Scene {
    FlatScene flat;
    Bvh bvh;

    static constexpr float kInfinity = std::numeric_limits<float>::infinity();

    // The nearest hit along the ray with t in (0, t_max); of equal distances, the lowest instance.
    bool intersect(const Ray& ray, Hit& hit, float t_max = kInfinity) const {
        return intersect_nearest(bvh, flat.instances, ray, 0.0f, t_max, hit, &flat.meshes);
    }
    // The same for the lanes of a packet set in `active`, exactly as one by one; bit l of the
    // result says whether lane l hit (hits[l] is written only then).
    unsigned intersect(const Ray (&rays)[kPacketSize], unsigned active, Hit (&hits)[kPacketSize],
                       float t_max = kInfinity) const {
        return intersect_nearest_packet(bvh, flat.instances, rays, active, 0.0f, t_max, hits, &flat.meshes);
    }
    // Whether anything lies along the ray with t in (0, t_max).
    bool occluded(const Ray& ray, float t_max) const {
        return !for_each_crossing(bvh, flat.instances, &flat.meshes, ray, 0.0f, t_max,
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
        return for_each_crossing(bvh, flat.instances, &flat.meshes, ray, 0.0f, t_max, visit);
    }

    const Material& material(std::uint32_t instance) const { return flat.materials[flat.instances[instance].material]; }
    const Material& material(const Hit& hit) const { return material(hit.instance); }
};

// Builds the BVH (reordering flat.instances to match it) on `threads` threads (0 = all), after
// the BVH of every mesh that has none yet (reordering its triangles).
Scene accelerate(FlatScene flat, int threads = 0);

}  // namespace whitted
