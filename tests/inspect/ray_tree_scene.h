#pragma once
// A scene whose ray tree is known by hand: a mirror turned 45° about y, and a glass sphere beside
// it. The camera ray of the image's middle pixel (the image is 201 × 151, so that pixel 100, 75 has
// its centre on the axis) goes straight down -z, meets the mirror at P0, is reflected to +x, enters
// the sphere at P1 head on, crosses it undeviated to P2 and leaves it to +x. The light is in front.
#include <cmath>

#include <glm/glm.hpp>

namespace whitted::test {

inline const char* kRayTreeScene = R"(# a mirror and a glass sphere
camera [ eye 0 0 10 focus 0 0 0 angle 60 ]
light [ position -2 6 4 ]
background [ color 0.1 0.1 0.1 ]
mastersubgraph root [
  trans [ rotate 0 1 0 45 scale 6 6 0.1
    object cube [ diffuse 0.1 0.1 0.1 reflect 0.9 0.9 0.9 ] ]
  trans [ translate 3 0 0.0707106781 scale 2 2 2
    object sphere [ diffuse 0 0 0 transparent 0.9 0.9 0.9 ior 1.5 ] ]
]
)";

constexpr int kRayTreeWidth = 201, kRayTreeHeight = 151, kRayTreeX = 100, kRayTreeY = 75;

// The mirror: the unit cube scaled to 0.1 thick, then turned so that its front face's normal is
// (1, 0, 1)/√2; that face is the plane n·p = 0.05, which the z axis meets at z = 0.05·√2. The
// mirror direction of (0, 0, -1) about n is (1, 0, 0).
inline const float kZ0 = 0.05f * std::sqrt(2.0f);
inline const glm::vec3 kMirrorHit{0, 0, kZ0};
// The sphere (radius 1, centre (3, 0, z0)): entered at x = 2, left at x = 4 (normal incidence: no bend).
inline const glm::vec3 kGlassEntry{2, 0, kZ0}, kGlassExit{4, 0, kZ0};
inline const glm::vec3 kRayTreeLight{-2, 6, 4};

// Where world point p appears in the 201 × 151 image (pixel coordinates, centre of pixel i at i + 0.5),
// by the pinhole's closed form: eye (0, 0, 10) looking down -z, up +y, 60° vertical field of view.
inline glm::vec2 ray_tree_project(const glm::vec3& p) {
    const float depth = 10.0f - p.z, tan_half = std::tan(glm::radians(30.0f));
    const float aspect = float(kRayTreeWidth) / float(kRayTreeHeight);
    const float sx = p.x / depth / (tan_half * aspect), sy = p.y / depth / tan_half;
    return {(sx + 1.0f) * 0.5f * float(kRayTreeWidth), (1.0f - sy) * 0.5f * float(kRayTreeHeight)};
}

}  // namespace whitted::test
