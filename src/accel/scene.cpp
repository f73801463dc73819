#include "accel/scene.h"

namespace whitted {

Scene accelerate(FlatScene flat, int threads) {
    Scene scene;
    scene.flat = std::move(flat);
    scene.bvh = build_bvh(scene.flat.instances, threads);
    return scene;
}

}  // namespace whitted
