#pragma once
// The flattened scene together with its acceleration structure: what the integrator renders.
#include "accel/bvh.h"
#include "flatten/flat_scene.h"

namespace whitted {

struct Scene {
    FlatScene flat;
    Bvh bvh;
};

// Builds the BVH (reordering flat.instances to match it) on `threads` threads (0 = all).
Scene accelerate(FlatScene flat, int threads = 0);

}  // namespace whitted
