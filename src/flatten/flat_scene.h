#pragma once
// The render-ready scene: flat arrays of instances, materials and lights that the
// acceleration structure and the integrator read. No pointers, no per-ray allocation.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "camera/camera.h"
#include "mesh/triangle_mesh.h"
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
    std::uint32_t mesh = 0;  // kind == Mesh: index into FlatScene::meshes
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

// A texture image as 8-bit RGB, row 0 at the top: 3 bytes a texel (what the decoder gives; floats
// would take four times the memory for no more precision). A texel's value is byte / 255, linear.
struct TextureImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgb;  // width·height·3 bytes, row-major
    glm::vec3 texel(std::size_t i) const { return glm::vec3(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]) / 255.0f; }
    void push_back(glm::u8vec3 c) { rgb.insert(rgb.end(), {c.x, c.y, c.z}); }
};

struct FlatScene {
    std::vector<Instance> instances;
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<TextureImage> textures;
    std::vector<TriangleMesh> meshes;  // one per OBJ file, however many instances draw it
    Camera camera;  // the file's camera: what a render uses unless it is given another
    glm::vec3 background{0.0f};
    glm::vec3 ambient_intensity{1.0f};
    Provenance provenance;  // where each instance, material and light came from (the inspector's)
};

}  // namespace whitted
