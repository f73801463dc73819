#pragma once
// The render-ready scene: flat arrays of instances, materials and lights that the
// acceleration structure and the integrator read. No pointers, no per-ray allocation.
#include <vector>

#include <glm/glm.hpp>

#include "camera/camera.h"
#include "data/instance.h"
#include "data/light.h"
#include "data/lighting_model.h"
#include "data/material.h"
#include "data/motion.h"
#include "data/provenance.h"
#include "data/texture_image.h"
#include "data/triangle_mesh.h"

namespace whitted {

struct SceneData {
    std::vector<Instance> instances;
    std::vector<Material> materials;
    std::vector<Light> lights;
    std::vector<TextureImage> textures;
    // Per texture, its mip-map pyramid below the image (texture/texture_filter.h): only when the
    // render's texture filter reads one (--texture-filter trilinear or ewa), else empty.
    std::vector<std::vector<TextureImage>> texture_levels;
    std::vector<TriangleMesh> meshes;  // one per OBJ file, however many instances draw it
    Camera camera;  // the file's camera: what a render uses unless it is given another
    glm::vec3 background{0.0f};
    glm::vec3 ambient_intensity{1.0f};
    LightingModel lighting = LightingModel::Labs;  // §7, or §9.5 (integrator/cs1230_integrator.h)
    Provenance provenance;  // where each instance, material and light came from (the inspector's)
    // The instances that move (`velocity`, `angularrate` in their chain of trans blocks): each
    // one's object→world map as a function of time, shared by the objects of one chain. Their
    // Instance above is placed at the load's time, as for a render without a shutter.
    struct Moving {
        std::uint32_t instance;  // index into instances
        std::uint32_t motion;    // index into motions
    };
    std::vector<Motion> motions;
    std::vector<Moving> moving;
};

}  // namespace whitted
