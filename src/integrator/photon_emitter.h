#pragma once
// Where photons start: the scene's point, spot and directional lights (scene-format.md §6, §9.1),
// each chosen in proportion to its power. The flux a photon carries makes a density estimate
// agree with §9.2's next-event term π · f · C · att · spot · cos θ:
// - point: directions uniform over the sphere, radiant intensity π · C (power 4π · π · C);
// - spot: directions uniform over its cone, intensity π · C · cos^exponent θ;
// - directional: parallel rays from a disc of the scene's bounding sphere, irradiance π · C across
//   it (power π · C · π R²), directions spread over the §9.1 cone when it has an `angle`;
// - a point or spot light with `radius` starts each photon at a uniform point of the disc facing
//   the photon's direction (the disc §9.1 turns toward every shaded point).
// The attenuation of §6 (att = 1 / (c + l d + q d²), not a physical 1/d²) is the tracer's to apply,
// as att(d) · d² times the flux with d the length of the photon's path (the photons' own density
// falls as 1/d²): 1 for `function 0 0 1`.
// Emissive shapes emit none: path tracing finds every path from them already.
#include <vector>

#include <glm/glm.hpp>

#include "base/bounds.h"
#include "base/ray.h"
#include "data/scene_data.h"

namespace whitted {

struct EmittedPhoton {
    Ray ray;                  // unit direction
    glm::vec3 power{0.0f};    // flux / the probability of this light and direction
    glm::vec3 falloff{1, 0, 0};
    bool attenuated = false;  // a point or spot light: §6's attenuation applies
};

class PhotonEmitter {
public:
    PhotonEmitter(const SceneData& scene, const Bounds& bounds);

    bool empty() const { return lights_.empty(); }
    // The photon for the numbers u (light choice), u_point (a point of a disc), u_dir (a direction).
    EmittedPhoton emit(float u, glm::vec2 u_point, glm::vec2 u_dir) const;
    // The power of light l as the choice weighs it (the luminance of its flux); 0 if it emits no photons.
    float power(std::size_t light) const;

private:
    const SceneData& scene_;
    glm::vec3 centre_{0.0f};
    float radius_ = 1.0f;
    std::vector<std::size_t> lights_;  // into scene.lights
    std::vector<float> power_, cdf_;
};

// The flux a light sends out, per unit of its colour (π · the solid-angle integral of its
// intensity profile; a directional light's through the disc of radius `radius`).
float light_flux_scale(const Light& light, float radius);

}  // namespace whitted
