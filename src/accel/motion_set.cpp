#include "accel/motion_set.h"

#include <algorithm>
#include <cmath>

#include "accel/instance_geometry.h"

namespace whitted {

Instance MotionSet::at(std::uint32_t k, const Instance& placed, float time) const {
    const glm::dmat4 inv = motions[chain[k]].world_to_object(shutter.at(time));
    Instance inst = placed;  // kind, material, mesh and rescale: a motion neither scales nor shears over time
    for (int r = 0; r < 3; ++r)
        inst.world_to_object[r] = glm::vec4(float(inv[0][r]), float(inv[1][r]), float(inv[2][r]), float(inv[3][r]));
    return inst;
}

Bounds swept_bounds(const Motion& motion, const Instance& inst, const Bounds* mesh_box, const Shutter& shutter) {
    // Every unit shape lies within radius 1 of its origin (the ellipsoid's 1 along x and z).
    double radius = 1.0;
    if (mesh_box) {
        if (mesh_box->empty()) return {};
        radius = glm::length(glm::max(glm::abs(glm::dvec3(mesh_box->lo)), glm::abs(glm::dvec3(mesh_box->hi))));
    }
    constexpr int kSteps = 32;
    const double span = shutter.close - shutter.open;
    const double speed = motion.speed_bound(radius, std::max(std::abs(shutter.open), std::abs(shutter.close)));
    Bounds box;
    for (int j = 0; j <= kSteps; ++j) {
        const glm::dmat4 m = motion.object_to_world(shutter.open + span * j / kSteps);
        if (mesh_box) {
            for (int c = 0; c < 8; ++c) {
                const glm::dvec3 corner((c & 1) ? mesh_box->hi.x : mesh_box->lo.x,
                                        (c & 2) ? mesh_box->hi.y : mesh_box->lo.y,
                                        (c & 4) ? mesh_box->hi.z : mesh_box->lo.z);
                box.grow(glm::vec3(m * glm::dvec4(corner, 1.0)));
            }
        } else {
            box.grow(unit_shape_world_bounds(inst.kind, glm::mat4(m)));
        }
    }
    // Between two sampled times no point moves further than speed × half their spacing from
    // where it was at the nearer one; then room for float rounding.
    const float grow = float(speed * std::abs(span) / (2.0 * kSteps));
    box.lo -= glm::vec3(grow);
    box.hi += glm::vec3(grow);
    return box.padded(1e-5f);
}

std::vector<std::uint32_t> build_motion_tree(MotionSet& set, int threads, const std::atomic<bool>* cancel) {
    std::vector<std::uint32_t> order;
    // A moving instance's test evaluates its transform (a few 4×4 products) before the shape's:
    // dear next to a box test, so small leaves.
    const BvhBuildCosts costs{0.5f, 4};
    static_cast<BasicBvh<Bvh4Node>&>(set.tree) = build_bvh_over_boxes(
        set.count(), [&](std::uint32_t k) { return set.swept[k]; }, costs, threads, order, cancel);
    if (cancel && cancel->load(std::memory_order_relaxed)) return {};
    std::vector<std::uint32_t> chain(order.size());
    std::vector<Bounds> swept(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        chain[k] = set.chain[order[k]];
        swept[k] = set.swept[order[k]];
    }
    set.chain = std::move(chain);
    set.swept = std::move(swept);
    return order;
}

bool ray_crosses_box(const Ray& ray, const Bounds& box, float t_min, float t_max) {
    float lo = t_min, hi = t_max;
    for (int a = 0; a < 3; ++a) {
        const float inv = 1.0f / ray.direction[a];
        float t0 = (box.lo[a] - ray.origin[a]) * inv, t1 = (box.hi[a] - ray.origin[a]) * inv;
        if (t0 > t1) std::swap(t0, t1);
        // A ray lying in a slab plane gives NaN: it is kept (the box test only culls).
        if (t0 > lo) lo = t0;
        if (t1 < hi) hi = t1;
    }
    return !(lo > hi);
}

}  // namespace whitted
