#include "accel/scene.h"

#include "mesh/mesh_bvh.h"

namespace whitted {

Scene accelerate(FlatScene flat, int threads) {
    Scene scene;
    scene.flat = std::move(flat);
    // The bottom level first: a mesh instance's world bounds come from its mesh's box.
    for (TriangleMesh& mesh : scene.flat.meshes)
        if (mesh.bvh.nodes.empty()) build_mesh_bvh(mesh, threads);
    std::vector<std::uint32_t> order;
    scene.bvh = build_bvh(scene.flat.instances, threads, &scene.flat.meshes, &order);
    scene.flat.provenance.reorder_instances(order);
    return scene;
}

}  // namespace whitted
