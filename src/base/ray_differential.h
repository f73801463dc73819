#pragma once
// A ray's two auxiliary rays: the rays of the image positions one pixel to the right (x) and one
// pixel down (y), with the same lens point. Where they meet a surface, next to where the ray
// does, tells how much of the surface (and of its texture) a pixel covers.
#include "base/ray.h"

namespace whitted {

struct RayDifferential {
    Ray x, y;  // unit directions
};

}  // namespace whitted
