#pragma once
// The moving instances of a render with a shutter (motion blur): kept out of the static BVH, each
// with its transform as a function of time (data/motion.h) and a box bounding it over the whole
// shutter interval, and a small BVH over those boxes. A ray meets each one where it is at the
// ray's own time (Ray::time). A scene without them, or a render without a shutter, has an empty
// set and pays nothing for it.
#include <cstdint>
#include <vector>

#include "accel/bvh.h"
#include "base/bounds.h"
#include "base/ray.h"
#include "data/scene_data.h"

namespace whitted {

// The scene-time interval the camera's shutter is open.
struct Shutter {
    double open = 0, close = 0;
    double at(float fraction) const { return open + double(fraction) * (close - open); }
};

struct MotionSet {
    Shutter shutter;
    std::uint32_t first = 0;        // the moving instances are data.instances[first, first + count)
    std::vector<Motion> motions;       // per chain of trans blocks that moves (SceneData::motions)
    std::vector<std::uint32_t> chain;  // per moving instance: its index in motions
    std::vector<Bounds> swept;         // per moving instance: its world box over the whole shutter
    Bvh tree;                          // 4-wide, over `swept`: its leaves name moving instances k (first + k)

    bool empty() const { return chain.empty(); }
    std::uint32_t count() const { return std::uint32_t(chain.size()); }
    // One compare (below `first` the difference wraps around to more than any count).
    bool contains(std::uint32_t instance) const { return instance - first < count(); }
    // `placed` (the moving instance at the load's time) moved to where it is at shutter fraction `time`.
    Instance at(std::uint32_t k, const Instance& placed, float time) const;
};

// The world box of `inst` (a unit shape, or a mesh with box `mesh_box`) swept by `motion` over the
// shutter: boxes at evenly spaced times, grown by the motion's speed bound times half their spacing.
Bounds swept_bounds(const Motion& motion, const Instance& inst, const Bounds* mesh_box, const Shutter& shutter);

// The tree over the swept boxes of `set` (set.chain and set.swept filled): reorders chain and
// swept to its leaf order and returns that order (new place → old place), for the instances and
// their side tables to follow. Empty if `cancel` was set meanwhile.
std::vector<std::uint32_t> build_motion_tree(MotionSet& set, int threads, const std::atomic<bool>* cancel);

// Whether the ray crosses `box` with t in (t_min, t_max) (a slab test; an empty box never).
bool ray_crosses_box(const Ray& ray, const Bounds& box, float t_min, float t_max);

}  // namespace whitted
