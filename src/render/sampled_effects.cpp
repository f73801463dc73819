#include "render/sampled_effects.h"

#include <vector>

#include "data/scene_data.h"

namespace whitted {

SampledEffects sampled_effects(const SceneData& scene, const CameraDesc& camera) {
    SampledEffects e;
    e.depth_of_field = camera.aperture > 0.0f;
    for (const Light& l : scene.lights) e.soft_shadows = e.soft_shadows || l.radius > 0.0f || l.cos_half_angle < 1.0f;
    for (const Material& m : scene.materials) e.gloss = e.gloss || m.gloss > 0.0f;
    return e;
}

std::string sampled_effects_hint(const SampledEffects& effects, const SamplingSettings& sampling, RenderMode mode) {
    if (mode != RenderMode::Whitted || sampling.samples_per_pixel() > 1 || !effects.any()) return "";
    std::vector<std::string> names;
    if (effects.soft_shadows) names.push_back("soft shadows");
    if (effects.depth_of_field) names.push_back("depth of field");
    if (effects.gloss) names.push_back("glossy reflections");
    std::string list = names[0];
    for (std::size_t i = 1; i < names.size(); ++i) list += (i + 1 == names.size() ? " and " : ", ") + names[i];
    return "this scene has " + list + ": raise SPP to see " + (names.size() == 1 && !effects.soft_shadows ? "it" : "them") +
           " (one sample per pixel takes the lens and light centres)";
}

}  // namespace whitted
