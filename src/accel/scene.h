#pragma once
// The renderable scene: the render-ready data and the acceleration structure behind one narrow
// interface of ray queries (as Embree's rtcIntersect / rtcOccluded, pbrt's Intersect /
// IntersectP). Integrators ask it; they never pair the BVH with the instance array themselves.
#include <limits>

#include "accel/bvh.h"
#include "accel/bvh_any_hit.h"
#include "accel/bvh_packet.h"
#include "accel/mesh_bvh.h"
#include "accel/motion_set.h"
#include "data/scene_data.h"

namespace whitted {

struct Scene {
    SceneData data;
    Bvh bvh;                         // over data.instances
    std::vector<MeshBvh> mesh_bvhs;  // one per data.meshes
    // With a shutter over a moving scene: the moving instances, after the static ones and outside
    // `bvh`, met at each ray's time (motion blur). Empty otherwise.
    MotionSet motion;

    static constexpr float kInfinity = std::numeric_limits<float>::infinity();

    // The nearest hit along the ray with t in (0, t_max); of equal distances, the lowest instance.
    bool intersect(const Ray& ray, Hit& hit, float t_max = kInfinity) const {
        const bool found = intersect_nearest(bvh, data.instances, ray, 0.0f, t_max, hit, &mesh_bvhs);
        if (motion.empty()) return found;
        return intersect_moving(ray, found ? hit.t : t_max, hit) || found;
    }
    // The same for the lanes of a packet set in `active`, exactly as one by one; bit l of the
    // result says whether lane l hit (hits[l] is written only then).
    unsigned intersect(const Ray (&rays)[kPacketSize], unsigned active, Hit (&hits)[kPacketSize],
                       float t_max = kInfinity) const {
        unsigned found = intersect_nearest_packet(bvh, data.instances, rays, active, 0.0f, t_max, hits, &mesh_bvhs);
        if (motion.empty()) return found;
        for (int l = 0; l < kPacketSize; ++l)
            if ((active >> l) & 1 && intersect_moving(rays[l], (found >> l) & 1 ? hits[l].t : t_max, hits[l]))
                found |= 1u << l;
        return found;
    }
    // Whether anything lies along the ray with t in (0, t_max).
    bool occluded(const Ray& ray, float t_max) const {
        return !visit_crossings(ray, t_max, [](std::uint32_t, int) { return false; });
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
        if (!for_each_crossing(bvh, data.instances, &mesh_bvhs, ray, 0.0f, t_max, visit)) return false;
        return motion.empty() || visit_moving_crossings(ray, t_max, visit);
    }

    // The moving instances' part of visit_crossings, out of line: a render without a shutter keeps
    // the walk of the static scene as small as it was (inlined where it is asked).
    template <class Visit>
    [[gnu::noinline]] bool visit_moving_crossings(const Ray& ray, float t_max, Visit& visit) const {
        return bvh_detail::walk_any(motion.tree, ray, 0.0f, t_max, [&](std::uint32_t first, std::uint32_t end) {
            for (std::uint32_t k = first; k < end; ++k) {
                if (!ray_crosses_box(ray, motion.swept[k], 0.0f, t_max)) continue;
                const Instance inst = motion.at(k, data.instances[motion.first + k], ray.time);
                if (!bvh_detail::visit_instance(inst, motion.first + k, &mesh_bvhs, ray, 0.0f, t_max, visit))
                    return false;
            }
            return true;
        });
    }

    // Instance i as the ray at shutter fraction `time` meets it: where a moving one is then.
    Instance instance_at(std::uint32_t i, float time) const {
        return motion.contains(i) ? motion.at(i - motion.first, data.instances[i], time) : data.instances[i];
    }

    // Everything a ray can meet: the static BVH's box and, with a shutter, the moving instances'
    // boxes swept over it.
    Bounds bounds() const {
        Bounds b = bvh.bounds();
        if (!motion.empty()) b.grow(motion.tree.bounds());
        return b;
    }

    const Material& material(std::uint32_t instance) const { return data.materials[data.instances[instance].material]; }
    const Material& material(const Hit& hit) const { return material(hit.instance); }

private:
    // The nearest moving instance hit before t_max (strictly: a static hit at the same distance,
    // with its lower index, stays), into `hit`.
    bool intersect_moving(const Ray& ray, float t_max, Hit& hit) const;
};

// Builds the BVH of every mesh (reordering its triangles), then the BVH over the instances
// (reordering data.instances to match it), on `threads` threads (0 = all). With `cancel` set
// (another thread, a signal handler) it stops within a fraction of a second, leaving a scene that
// must not be used.
// With `shutter` over a scene with moving instances (SceneData::moving): those go into
// Scene::motion, after the static instances, which alone make the BVH.
Scene accelerate(SceneData data, int threads = 0, const std::atomic<bool>* cancel = nullptr,
                 const Shutter* shutter = nullptr);

}  // namespace whitted
