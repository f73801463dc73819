#pragma once
// The render-ready scene: flat arrays of instances, materials and lights that the
// acceleration structure and the integrator read. No pointers, no per-ray allocation.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "camera/camera.h"
#include "flatten/provenance.h"
#include "scene/scene_description.h"

namespace whitted {

// One shape placed in the world. Only the world→object affine map is kept (three rows of
// [R | t]): rays go into object space through it and normals come back through its
// transpose, which is exactly (M⁻¹)ᵀ.
struct Instance {
    glm::vec4 world_to_object[3];
    ShapeKind kind;
    std::uint32_t material;
};

struct Material {
    glm::vec3 ambient{0.0f}, diffuse{1.0f}, specular{0.0f};
    glm::vec3 reflect{0.0f}, transparent{0.0f}, emit{0.0f};
    float shine = 1.0f;
    float ior = 1.0f;
    float gloss = 0.0f;  // > 0: reflect and transparent rays drawn from a cos^gloss lobe (§9.1)
    int texture = -1;  // index into FlatScene::textures, -1 = none
    float repeat_u = 1.0f, repeat_v = 1.0f;
    // Brown/Tufts `blend` in [0, 1]: diffuse = (1 − b)·diffuse + b·texel, ambient untouched;
    // negative: no blend, the texel multiplies diffuse and ambient (scene-format.md §8, §9.4).
    float blend = -1.0f;
    bool is_transparent() const { return transparent != glm::vec3(0.0f); }
};

struct Light {
    LightType type = LightType::Point;
    glm::vec3 position{0.0f};
    glm::vec3 direction{0, -1, 0};  // unit, the way the light travels
    glm::vec3 color{0.5f};
    glm::vec3 falloff{1, 0, 0};
    float cos_aperture = -1.0f;  // spot: cos of the half-angle
    float exponent = 1.0f;
    float radius = 0.0f;   // point/spot: a disc facing the shaded point (§9.1)
    float cos_half_angle = 1.0f;  // directional: its directions fill this cone (§9.1)
};

// A texture image as linear RGB floats, row 0 at the top.
struct TextureImage {
    int width = 0, height = 0;
    std::vector<glm::vec3> texels;
};

struct FlatScene {
    std::vector<Instance> instances;
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<TextureImage> textures;
    Camera camera;  // the file's camera: what a render uses unless it is given another
    glm::vec3 background{0.0f};
    glm::vec3 ambient_intensity{1.0f};
    Provenance provenance;  // where each instance, material and light came from (the inspector's)
};

}  // namespace whitted
