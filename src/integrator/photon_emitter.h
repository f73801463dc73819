#pragma once
// Where photons start: the scene's point, spot and directional lights (scene-format.md §6, §9.1)
// and its emissive shapes and meshes (§9.2), each chosen in proportion to its power. The flux a
// photon carries makes a density estimate agree with §9.2's next-event term π · f · C · att · spot · cos θ
// and with an emitter's radiance:
// - point: directions uniform over the sphere, radiant intensity π · C (power 4π · π · C);
// - spot: directions uniform over its cone, intensity π · C · cos^exponent θ;
// - directional: parallel rays from a disc of the scene's bounding sphere, irradiance π · C across
//   it (power π · C · π R²), directions spread over the §9.1 cone when it has an `angle`;
// - a point or spot light with `radius` starts each photon at a uniform point of the disc facing
//   the photon's direction (the disc §9.1 turns toward every shaded point);
// - an emissive shape: a point uniform by area (as the path tracer samples it), a cosine-weighted
//   direction, power emit · area · π. The unit shapes are closed and emit outward; a mesh may be
//   open, and the path tracer sees its emission from either side, so it emits from both (2π).
// The attenuation of §6 (att = 1 / (c + l d + q d²), not a physical 1/d²) is the tracer's to apply,
// as att(d) · d² times the flux with d the length of the photon's path (the photons' own density
// falls as 1/d²): 1 for `function 0 0 1`.
//
// Aiming (a projection map, as Jensen's): a photon counts only if the first surface it meets has
// an ideal mirror or refraction lobe, so every useful direction from a light points into one of the
// cones the bounding spheres of those objects subtend from it. A point, spot or emissive light whose
// cones cover less solid angle than it emits into draws its directions from those cones alone: a
// cone chosen by its solid angle, a direction uniform in it; the density at a direction is the
// number of cones holding it over their total solid angle, and the photon's flux is the intensity
// there over that density. The expected flux in every direction that can reach such an object is
// that of unaimed emission; the other directions carried nothing. A light inside a bounding sphere,
// and directional lights, emit as above.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "base/bounds.h"
#include "base/ray.h"
#include "data/scene_data.h"
#include "integrator/mesh_area_sampler.h"

namespace whitted {

struct Scene;  // accel/scene.h

struct EmittedPhoton {
    Ray ray;                  // unit direction
    glm::vec3 power{0.0f};    // flux / the probability of this light and direction
    glm::vec3 falloff{1, 0, 0};
    bool attenuated = false;  // a point or spot light: §6's attenuation applies
};

// The numbers one photon's start is drawn from, each in [0, 1).
struct EmissionNumbers {
    float light = 0.0f;     // which light
    glm::vec2 point{0.0f};  // a point of a disc or of an emitter's surface
    glm::vec2 dir{0.0f};    // a direction
    float cone = 0.0f;      // an aimed photon's cone
    float triangle = 0.0f;  // a mesh's triangle
    float side = 0.0f;      // a mesh's side
};

// A sphere that holds an object with an ideal mirror or refraction lobe.
struct PhotonTarget {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

// Whether a material has an ideal (delta) mirror or refraction lobe: what a photon must meet first.
bool has_delta_lobe(const Material& m);

class PhotonEmitter {
public:
    // More targets than this are aimed at as one sphere holding them all.
    static constexpr std::size_t kMaxTargets = 32;

    // aim: emit toward the targets (the default); false: over each light's whole distribution.
    explicit PhotonEmitter(const Scene& scene, bool aim = true);

    bool empty() const { return sources_.empty(); }
    EmittedPhoton emit(const EmissionNumbers& u) const;
    // Sources: scene.lights in order, then the emissive instances. A source's power as the choice
    // weighs it (the luminance of its flux; 0 if it emits no photons).
    std::size_t sources() const { return power_.size(); }
    float power(std::size_t source) const { return power_[source]; }
    const std::vector<PhotonTarget>& targets() const { return targets_; }

private:
    struct Source {
        std::int32_t light = -1;     // into scene.lights, or -1
        std::int32_t instance = -1;  // an emissive instance, or -1
        std::int32_t mesh = -1;      // into meshes_, for a mesh instance
        bool aimed = false;          // a point or spot light whose directions come from cones_
        std::uint32_t cones_begin = 0, cones_end = 0;
        float cone_solid_angle = 0.0f;  // their total
    };
    struct Cone {
        glm::vec3 axis;
        float sin2_max;     // sin² of its half-angle
        float solid_angle;  // 2π (1 − cos of its half-angle)
    };
    // The cones the targets subtend from `origin`, each target grown by `margin`, written to `out`
    // (room for kMaxTargets); their count, or 0 if the origin is inside one or they cover `limit`
    // or more of the sphere of directions. `total`: their solid angle.
    std::size_t cones_from(const glm::vec3& origin, float margin, float limit, Cone* out, float& total) const;
    // A direction from `count` cones of total solid angle `total`, and its density per unit solid angle.
    static glm::vec3 sample_cones(const Cone* cones, std::size_t count, float total, float pick, glm::vec2 u,
                                  float& pdf);
    EmittedPhoton emit_light(const Source& src, float prob, const EmissionNumbers& u) const;
    EmittedPhoton emit_shape(const Source& src, float prob, const EmissionNumbers& u) const;

    const Scene& scene_;
    glm::vec3 centre_{0.0f};
    float radius_ = 1.0f;
    bool aim_ = true;
    std::vector<Source> sources_;  // those that emit
    std::vector<float> power_, cdf_;
    std::vector<MeshAreaSampler> meshes_;
    std::vector<PhotonTarget> targets_;
    std::vector<Cone> cones_;  // the point and spot lights' aimed cones
};

// The flux a light sends out, per unit of its colour (π · the solid-angle integral of its
// intensity profile; a directional light's through the disc of radius `radius`).
float light_flux_scale(const Light& light, float radius);

}  // namespace whitted
