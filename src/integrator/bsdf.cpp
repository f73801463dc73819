#include "integrator/bsdf.h"

#include <algorithm>
#include <cmath>

#include "sampler/warp.h"

namespace whitted {
namespace {

float max_component(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }
float mean(const glm::vec3& v) { return (v.x + v.y + v.z) / 3.0f; }

// Density of the cos^e lobe around unit axis: (e + 1)/(2π) · cos^e α on the axis' hemisphere.
float cosine_power_pdf(const glm::vec3& axis, float e, const glm::vec3& w) {
    const float c = glm::dot(axis, w);
    return c > 0.0f ? (e + 1.0f) / (2.0f * kPi) * std::pow(c, e) : 0.0f;
}

}  // namespace

float energy_scale(const Material& m) {
    const glm::vec3 sum = m.diffuse + m.specular + m.reflect + m.transparent;
    const float largest = max_component(sum);
    return largest > 1.0f ? 1.0f / largest : 1.0f;
}

Bsdf::Bsdf(const Material& m, const glm::vec3& diffuse, const glm::vec3& outward, const glm::vec3& wo)
    : shine_(m.shine), gloss_(m.gloss) {
    const float s = energy_scale(m);
    weight_[0] = s * diffuse;
    weight_[1] = s * m.specular;
    weight_[2] = s * m.reflect;
    weight_[3] = s * m.transparent;
    specular_ = weight_[1] != glm::vec3(0.0f);
    transparent_ = weight_[3] != glm::vec3(0.0f);
    const bool outside = glm::dot(outward, wo) >= 0.0f;
    n_ = outside ? outward : -outward;
    eta_ = outside ? 1.0f / m.ior : m.ior;
    mirror_ = 2.0f * glm::dot(wo, n_) * n_ - wo;
    // Snell's law for the incoming direction −wo (§7), against an outside of ior 1.
    const float cos_i = glm::dot(n_, wo);
    const float k = 1.0f - eta_ * eta_ * (1.0f - cos_i * cos_i);
    tir_ = k < 0.0f;
    refracted_ = tir_ || !transparent_ ? mirror_ : glm::normalize(-eta_ * wo + (eta_ * cos_i - std::sqrt(std::max(k, 0.0f))) * n_);
    float total = 0.0f;
    for (int l = 0; l < 4; ++l) total += p_[l] = std::max(0.0f, mean(weight_[l]));
    for (float& p : p_) p = total > 0.0f ? p / total : 0.0f;
}

// The density lobe `lobe` draws directions with (0 for a delta lobe), on whichever side of the
// surface they fall: the one-sample combination of the lobes needs the true densities. Which side
// a lobe may light is f's business.
float Bsdf::lobe_pdf(int lobe, const glm::vec3& wi) const {
    switch (lobe) {
        case 0: return std::max(0.0f, glm::dot(n_, wi)) / kPi;
        case 1: return cosine_power_pdf(mirror_, shine_, wi);
        case 2: return gloss_ > 0.0f ? cosine_power_pdf(mirror_, gloss_, wi) : 0.0f;
        default: return gloss_ > 0.0f ? cosine_power_pdf(refracted_, gloss_, wi) : 0.0f;
    }
}

glm::vec3 Bsdf::f(const glm::vec3& wi) const {
    const float cos_i = std::abs(glm::dot(n_, wi));
    glm::vec3 f(0.0f);
    if (glm::dot(n_, wi) > 0.0f) {
        f += weight_[0] / kPi;
        // (A surface without the lobe skips its power: most of a diffuse scene's f.)
        const float c = glm::dot(mirror_, wi);
        if (c > 0.0f && specular_) f += weight_[1] * ((shine_ + 2.0f) / (2.0f * kPi) * std::pow(c, shine_));
    }
    // A glossy lobe's f is its weight × its density / |cos θi| on the side it lights: a sample drawn
    // from it there carries the weight; one that falls on the other side carries nothing (§9.1).
    if (gloss_ > 0.0f && cos_i > 0.0f) {
        const bool above = glm::dot(n_, wi) > 0.0f;
        if (above) f += weight_[2] * (lobe_pdf(2, wi) / cos_i);
        if (above == tir_ && transparent_) f += weight_[3] * (lobe_pdf(3, wi) / cos_i);
    }
    return f;
}

float Bsdf::pdf(const glm::vec3& wi) const {
    float pdf = 0.0f;
    for (int l = 0; l < 4; ++l)
        if (p_[l] > 0.0f) pdf += p_[l] * lobe_pdf(l, wi);
    return pdf;
}

BsdfSample Bsdf::sample(float u_lobe, glm::vec2 u) const {
    BsdfSample s;
    int lobe = 3;
    for (int l = 0; l < 3; ++l) {
        if (u_lobe < p_[l]) {
            lobe = l;
            break;
        }
        u_lobe -= p_[l];
    }
    while (lobe > 0 && p_[lobe] <= 0.0f) --lobe;  // rounding past the last lobe with weight
    if (p_[lobe] <= 0.0f) return s;
    if (lobe >= 2 && !(gloss_ > 0.0f)) {  // an ideal mirror or refraction: a delta lobe
        s.wi = lobe == 2 ? mirror_ : refracted_;
        s.weight = weight_[lobe] / p_[lobe];
        s.delta = s.valid = true;
        return s;
    }
    switch (lobe) {
        case 0: s.wi = cosine_hemisphere(n_, u); break;
        case 1: s.wi = cosine_power_lobe(mirror_, shine_, u); break;
        case 2: s.wi = cosine_power_lobe(mirror_, gloss_, u); break;
        default: s.wi = cosine_power_lobe(refracted_, gloss_, u); break;
    }
    s.pdf = pdf(s.wi);
    if (!(s.pdf > 0.0f)) return s;
    // A direction on a side no lobe lights carries nothing (the path ends there).
    s.weight = f(s.wi) * std::abs(glm::dot(n_, s.wi)) / s.pdf;
    s.valid = true;
    return s;
}

}  // namespace whitted
