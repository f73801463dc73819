#include "accel/scene.h"

namespace whitted {

Scene accelerate(FlatScene flat, int threads) {
    Scene scene;
    scene.flat = std::move(flat);
    std::vector<std::uint32_t> order;
    scene.bvh = build_bvh(scene.flat.instances, threads, &order);
    scene.flat.provenance.reorder_instances(order);
    return scene;
}

}  // namespace whitted
