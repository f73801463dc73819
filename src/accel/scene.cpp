#include "accel/scene.h"

namespace whitted {

Scene accelerate(SceneData data, int threads, const std::atomic<bool>* cancel) {
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
    std::vector<std::uint32_t> order;
    scene.bvh = build_bvh(scene.data.instances, threads, &scene.data.meshes, &order, cancel);
    if (cancelled()) return scene;
    scene.data.provenance.reorder_instances(order);
    return scene;
}

}  // namespace whitted
