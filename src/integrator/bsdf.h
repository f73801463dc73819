#pragma once
// The path tracer's BSDF (scene-format.md §9.2): the sum of the material's lobes with the file's
// weights, no Fresnel term. Lambertian `diffuse` (diffuse · texel / π); normalised Phong `specular`
// (specular · (shine + 2)/(2π) · cos^shine α, α between the mirror direction of the outgoing ray
// and the incoming one); the mirror `reflect` and the refraction `transparent` lobes, ideal (delta)
// or blurred by `gloss` (the cos^gloss lobe around the ideal direction, so that a sample drawn from
// it carries exactly the lobe's weight, as in the Whitted model). Total internal reflection sends
// the refraction lobe to the mirror direction. A lobe is sampled in proportion to its weight.
#include <glm/glm.hpp>

#include "data/scene_data.h"

namespace whitted {

// The factor by which a material's four weights are scaled so that no channel's sum exceeds 1
// (energy is never created): 1, or 1 / the largest sum.
float energy_scale(const Material& m);

struct BsdfSample {
    glm::vec3 wi{0.0f};      // unit, toward where the light comes from
    glm::vec3 weight{0.0f};  // f · |cos θi| / pdf (delta lobes: the lobe's weight / its probability)
    float pdf = 0.0f;        // of the non-delta lobes together (0 for a delta lobe)
    bool delta = false;
    bool valid = false;      // a direction was drawn (its weight may still be 0)
};

class Bsdf {
public:
    // At a surface with outward unit normal `outward`, seen along unit direction `wo` (toward the
    // viewer), with `diffuse` already multiplied by the texel.
    Bsdf(const Material& m, const glm::vec3& diffuse, const glm::vec3& outward, const glm::vec3& wo);

    // f(wo, wi) of the non-delta lobes.
    glm::vec3 f(const glm::vec3& wi) const;
    // The density sample() draws wi with, over the non-delta lobes (per unit solid angle).
    float pdf(const glm::vec3& wi) const;
    // Draws a lobe with u_lobe and a direction with u.
    BsdfSample sample(float u_lobe, glm::vec2 u) const;

    bool has_non_delta() const { return non_delta_probability() > 0.0f; }
    // The probability that sample() draws a non-delta lobe (the delta lobes come after them).
    float non_delta_probability() const { return p_[0] + p_[1] + (gloss_ > 0 ? p_[2] + p_[3] : 0.0f); }
    bool black() const { return p_[0] + p_[1] + p_[2] + p_[3] <= 0.0f; }
    const glm::vec3& normal() const { return n_; }  // faces the viewer

private:
    float lobe_pdf(int lobe, const glm::vec3& wi) const;

    glm::vec3 weight_[4];  // diffuse, specular, reflect, transparent (energy-scaled)
    float p_[4];           // the probability of sampling each lobe
    float shine_, gloss_, eta_;
    glm::vec3 n_, mirror_;
    glm::vec3 refracted_;  // the refraction lobe's ideal direction (the mirror one on total internal reflection or without the lobe)
    bool tir_;
    bool specular_, transparent_;  // those lobes' weights are not zero (else their terms are skipped)
};

}  // namespace whitted
