#pragma once
// Bounding volume hierarchy over the instances' world bounds. Built as a binary tree with the
// binned surface area heuristic, then collapsed into 4- and/or 8-wide trees whose nodes hold their
// children's boxes side by side, so that one SIMD test checks them all (bvh_node.h says which a
// scene gets). Instances are reordered so that every leaf is a contiguous range.
#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

#include "accel/bvh_node.h"
#include "data/scene_data.h"
#include "base/bounds.h"
#include "base/ray.h"
#include "shapes/unit_shapes.h"

namespace whitted {

struct MeshBvh;  // accel/mesh_bvh.h

// Builds the hierarchy and reorders `instances` to match it, on `threads` threads (0 = all
// hardware threads; the tree is the same for any count). Throws std::length_error beyond
// Bvh4Node::kMaxInstances instances. Mesh instances take their bounds from `meshes`. With
// `leaf_order`: the instance now at place i was at (*leaf_order)[i] (for side tables that follow
// the instances).
// With `cancel` set (by another thread or a signal handler) the build stops within a few nodes and
// leaves an empty tree, the instances in their order and `leaf_order` empty.
Bvh build_bvh(std::vector<Instance>& instances, int threads = 0, const std::vector<TriangleMesh>* meshes = nullptr,
              std::vector<std::uint32_t>* leaf_order = nullptr, const std::atomic<bool>* cancel = nullptr);

// The same tree over any n boxes (box_of(i), i < n); order[k] gets the primitive that leaf slot k
// holds (leaves refer to slots). The BVH of instances and of a mesh's triangles are both this.
Bvh build_bvh_over_boxes(std::size_t n, const std::function<Bounds(std::uint32_t)>& box_of, const BvhBuildCosts& costs,
                         int threads, std::vector<std::uint32_t>& order, const std::atomic<bool>* cancel = nullptr);
// The same collapsed into 8-wide nodes (a mesh's BVH).
Bvh8 build_bvh8_over_boxes(std::size_t n, const std::function<Bounds(std::uint32_t)>& box_of,
                           const BvhBuildCosts& costs, int threads, std::vector<std::uint32_t>& order,
                           const std::atomic<bool>* cancel = nullptr);

struct Hit {
    float t;
    std::uint32_t instance;
    ShapePart part;
    // Mesh instances: the triangle (in the mesh's order) and the barycentric weights of its
    // second and third vertices at the hit (the first has 1 - u - v). Zero for unit shapes.
    std::uint32_t triangle = 0;
    float u = 0.0f, v = 0.0f;
};

// Nearest hit with t in (t_min, t_max); of hits at the same t, the lowest instance index (and in
// a mesh, the lowest triangle). Mesh instances need `meshes`, the BVHs of the scene's meshes.
bool intersect_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                       Hit& hit, const std::vector<MeshBvh>* meshes = nullptr);

// The nearest-hit query done by testing every instance (and every triangle of a mesh): the
// reference the BVH is tested against.
bool intersect_nearest_brute_force(const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                                   Hit& hit, const std::vector<TriangleMesh>* meshes = nullptr);

}  // namespace whitted
