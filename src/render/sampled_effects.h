#pragma once
// The effects of scene-format.md §9.1 that a scene has (a lens, disc or cone lights, gloss). They are
// integrals the image samples: with one sample per pixel the renderer takes the lens centre, the
// light centres and the ideal directions, and the image shows none of them. Worth saying so.
#include <string>

#include "description/scene_description.h"
#include "integrator/render_mode.h"
#include "render/render_job.h"

namespace whitted {

struct SceneData;

struct SampledEffects {
    bool depth_of_field = false;  // the camera has an aperture
    bool soft_shadows = false;    // a light with a radius (point, spot) or an angle (directional)
    bool gloss = false;           // a material with gloss
    bool any() const { return depth_of_field || soft_shadows || gloss; }
};

SampledEffects sampled_effects(const SceneData& scene, const CameraDesc& camera);

// "this scene has soft shadows and depth of field: raise SPP to see them" when a Whitted render
// takes one sample per pixel of a scene with such effects; else "".
std::string sampled_effects_hint(const SampledEffects& effects, const SamplingSettings& sampling, RenderMode mode);

}  // namespace whitted
