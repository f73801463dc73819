#include "accel/scene.h"

namespace whitted {
namespace {

// The moving instances to the end (in their order), out of the BVH: each gets its motion and its
// box swept over the shutter. Returns the instance order (new place → old place).
std::vector<std::uint32_t> split_moving(Scene& scene, const Shutter& shutter, int threads,
                                       const std::atomic<bool>* cancel) {
    SceneData& data = scene.data;
    std::vector<char> moves(data.instances.size(), 0);
    for (const SceneData::Moving& m : data.moving) moves[m.instance] = 1;
    std::vector<std::uint32_t> order;
    order.reserve(data.instances.size());
    for (std::uint32_t i = 0; i < data.instances.size(); ++i)
        if (!moves[i]) order.push_back(i);
    scene.motion.shutter = shutter;
    scene.motion.first = std::uint32_t(order.size());
    for (const SceneData::Moving& m : data.moving) {  // in instance order: flatten lists them so
        const Instance& inst = data.instances[m.instance];
        const Motion& motion = data.motions[m.motion];
        order.push_back(m.instance);
        scene.motion.chain.push_back(m.motion);
        scene.motion.swept.push_back(
            swept_bounds(motion, inst, inst.kind == ShapeKind::Mesh ? &data.meshes[inst.mesh].box : nullptr, shutter));
    }
    scene.motion.motions = std::move(data.motions);
    const std::vector<std::uint32_t> leaves = build_motion_tree(scene.motion, threads, cancel);
    if (leaves.size() != data.moving.size()) return {};  // cancelled
    const std::vector<std::uint32_t> moving(order.begin() + scene.motion.first, order.end());
    for (std::size_t k = 0; k < leaves.size(); ++k) order[scene.motion.first + k] = moving[leaves[k]];
    std::vector<Instance> reordered(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) reordered[i] = data.instances[order[i]];
    data.instances = std::move(reordered);
    data.moving.clear();  // Scene::motion says it now
    data.motions.clear();
    return order;
}

}  // namespace

Scene accelerate(SceneData data, int threads, const std::atomic<bool>* cancel, const Shutter* shutter) {
    Scene scene;
    scene.data = std::move(data);
    auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
    // The bottom level first: a mesh instance's world bounds come from its mesh's box.
    scene.mesh_bvhs.reserve(scene.data.meshes.size());
    for (TriangleMesh& mesh : scene.data.meshes) {
        if (cancelled()) return scene;
        scene.mesh_bvhs.push_back(build_mesh_bvh(mesh, threads, cancel));
    }
    if (cancelled()) return scene;
    if (!shutter || scene.data.moving.empty()) {  // every instance where the load's time put it
        // (The moving list names instances by their place before the BVH's reordering: dropped.)
        scene.data.moving.clear();
        scene.data.motions.clear();
        std::vector<std::uint32_t> order;
        scene.bvh = build_bvh(scene.data.instances, threads, &scene.data.meshes, &order, cancel);
        if (cancelled()) return scene;
        scene.data.provenance.reorder_instances(order);
        return scene;
    }
    std::vector<std::uint32_t> order = split_moving(scene, *shutter, threads, cancel);
    if (cancelled()) return scene;
    std::vector<Instance> still(scene.data.instances.begin(), scene.data.instances.begin() + scene.motion.first);
    std::vector<std::uint32_t> still_order;
    scene.bvh = build_bvh(still, threads, &scene.data.meshes, &still_order, cancel);
    if (cancelled()) return scene;
    std::copy(still.begin(), still.end(), scene.data.instances.begin());
    std::vector<std::uint32_t> full(order.size());
    for (std::size_t i = 0; i < still_order.size(); ++i) full[i] = order[still_order[i]];
    for (std::size_t i = still_order.size(); i < order.size(); ++i) full[i] = order[i];
    scene.data.provenance.reorder_instances(full);
    return scene;
}

bool Scene::intersect_moving(const Ray& ray, float t_max, Hit& hit) const {
    bool found = false;
    float best = t_max;
    std::uint32_t best_index = 0;
    ShapePart best_part = kPartSide;
    bvh_detail::TriangleState tri;
    bvh_detail::walk_nearest(motion.tree, ray, 0.0f, best, [&](std::uint32_t first, std::uint32_t end) {
        for (std::uint32_t k = first; k < end; ++k) {
            if (!ray_crosses_box(ray, motion.swept[k], 0.0f, best)) continue;
            const std::uint32_t i = motion.first + k;
            const Instance inst = motion.at(k, data.instances[i], ray.time);
            if (inst.kind == ShapeKind::Mesh)
                bvh_detail::offer_mesh_nearest(mesh_bvhs[inst.mesh], inst, ray, i, 0.0f, t_max, best, best_index,
                                               best_part, found, tri);
            else
                bvh_detail::offer_nearest(bvh_detail::intersect_instance(inst, ray), i, 0.0f, t_max, best,
                                          best_index, best_part, found);
        }
    });
    if (!found) return false;
    hit = bvh_detail::make_hit(data.instances.data(), best, best_index, best_part, tri);
    return true;
}

}  // namespace whitted
