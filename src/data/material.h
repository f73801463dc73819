#pragma once
// A surface's material as the integrators read it (scene-format.md §7, §8, §9.1).
#include <glm/glm.hpp>

namespace whitted {

struct Material {
    glm::vec3 ambient{0.0f}, diffuse{1.0f}, specular{0.0f};
    glm::vec3 reflect{0.0f}, transparent{0.0f}, emit{0.0f};
    float shine = 1.0f;
    float ior = 1.0f;
    float gloss = 0.0f;  // > 0: reflect and transparent rays drawn from a cos^gloss lobe (§9.1)
    int texture = -1;  // index into SceneData::textures, -1 = none
    float repeat_u = 1.0f, repeat_v = 1.0f;
    // Brown/Tufts `blend` in [0, 1]: diffuse = (1 − b)·diffuse + b·texel, ambient untouched;
    // negative: no blend, the texel multiplies diffuse and ambient (scene-format.md §8, §9.4).
    float blend = -1.0f;
    bool is_transparent() const { return transparent != glm::vec3(0.0f); }
};

}  // namespace whitted
