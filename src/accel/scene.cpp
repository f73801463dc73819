#include "accel/scene.h"

namespace whitted {

Scene accelerate(FlatScene flat) {
    Scene scene;
    scene.flat = std::move(flat);
    scene.bvh = build_bvh(scene.flat.instances);
    return scene;
}

}  // namespace whitted
