#pragma once
// The scene the inspector tests look at, and where its parts land in the image, found by
// projecting known 3D points with the camera's closed form (never by asking the program).
//
// Seen from (0, 0, 10) toward the origin: a floor, a mirror wall behind, a red sphere above the
// middle lit by a point light straight above it (so its shadow falls on the floor below it), and
// one green cylinder drawn twice, at x = -3 and x = +3, through two uses of subgraph `pillar`
// inside subgraph `pair`, itself used by root: two chains three subgraphs deep to one object line.
#include <cmath>
#include <sstream>
#include <string>

#include <glm/glm.hpp>

namespace whitted::test {

inline const char* kInspectScene = R"(# the pixel inspector's test scene
background [ color 0.1 0.2 0.3 ]
camera [ eye 0 0 10 focus 0 0 0 up 0 1 0 angle 60 ]
light [ position 0 10 0 color 1 1 1 ]
mastersubgraph pillar [
  trans [
    object cylinder [ ambient 0 0.1 0 diffuse 0 1 0 ]
  ]
]
mastersubgraph pair [
  trans [ translate -3 0 0
    subgraph pillar
  ]
  trans [ translate 3 0 0
    subgraph pillar
  ]
]
mastersubgraph root [
  trans [ translate 0 -2 0 scale 20 0.2 20
    object cube [ ambient 0.1 0.1 0.1 diffuse 0.6 0.6 0.6 ]
  ]
  trans [ translate 0 1 0
    subgraph pair
  ]
  trans [ translate 0 2 0
    object sphere [ ambient 0.5 0 0 diffuse 1 0 0 specular 0.5 0.5 0.5 shine 20 ]
  ]
  trans [ translate 0 0 -4 scale 8 5 0.2
    object cube [ ambient 0 0 0 diffuse 0 0 0 reflect 0.8 0.8 0.8 ]
  ]
]
)";

constexpr int kInspectWidth = 200, kInspectHeight = 150;

// 1-based line and column of the first occurrence of `needle` at or after line `from`.
struct TextPos {
    int line = 0, col = 0;
};
inline TextPos find_in_scene(const std::string& needle, int from = 1) {
    std::istringstream in(kInspectScene);
    std::string text;
    for (int line = 1; std::getline(in, text); ++line) {
        if (line < from) continue;
        if (const auto at = text.find(needle); at != std::string::npos) return {line, int(at) + 1};
    }
    return {};
}

// The pixel (column, row from the top) whose centre ray passes nearest world point p, for the
// scene's camera: eye (0, 0, 10) looking down -z, up +y, 60° vertical field of view.
inline glm::ivec2 project(const glm::vec3& p, int width = kInspectWidth, int height = kInspectHeight) {
    const glm::vec3 d = p - glm::vec3(0, 0, 10);
    const float depth = -d.z;  // along forward (0, 0, -1)
    const float tan_half = std::tan(glm::radians(30.0f)), aspect = float(width) / float(height);
    const float sx = d.x / depth / (tan_half * aspect), sy = d.y / depth / tan_half;
    return {int(std::floor((sx + 1.0f) * 0.5f * float(width))), int(std::floor((1.0f - sy) * 0.5f * float(height)))};
}

// Points of the scene, from its construction:
inline const glm::vec3 kLeftPillarFront{-3, 1, 0.5f};   // front of the cylinder at x = -3
inline const glm::vec3 kRightPillarFront{3, 1, 0.5f};   // and at x = +3
// On the sphere (centre (0, 2, 0), radius 0.5) where its normal is (0, 1, 1)/√2: lit at n·l ≈ 0.67,
// so red = ambient 0.5 + 0.67 > 1, clamped in the image.
inline const glm::vec3 kSphereUpperFront{0, 2 + 0.5f * 0.70710678f, 0.5f * 0.70710678f};
// On the floor's top (y = -1.9) under the sphere: the light at (0, 10, 0) is straight above, the
// sphere (radius 0.5 at height 2) hides it from every floor point within 0.74 of the axis.
inline const glm::vec3 kFloorInShadow{0, -1.9f, 0.3f};
// On the mirror's face (z = -3.9) on the line from the eye's mirror image (0, 0, -17.8) to the
// sphere's centre: the reflected ray of the camera ray through it heads for the sphere's centre.
inline const glm::vec3 kMirrorTowardSphere{0, 2.0f * 13.9f / 17.8f, -3.9f};
// Far to the upper left, beside the mirror (x in [-4, 4]) and above the floor: nothing there.
inline const glm::vec3 kEmptySky{-9, 6, -3.9f};

}  // namespace whitted::test
