#pragma once
// What one camera sample contributes to the per-term images (AOVs): the Whitted terms of the camera
// ray's hit (emit, ambient, each light's diffuse and specular, what the reflected and refracted
// rays added; the background when it hit nothing), each light's visibility there, and the hit's
// object, normal, distance and albedo. Filled by WhittedIntegrator's own shading as it runs (the
// recorder interface of shading_record.h), so that the terms are the very ones the colour is the
// sum of. The per-light arrays are sized once per render: recording a sample allocates nothing.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "accel/bvh.h"
#include "base/ray.h"
#include "integrator/shading_record.h"
#include "integrator/surface.h"

namespace whitted {

struct AovSample {
    // The camera ray's hit (hit = false: it saw the background).
    bool hit = false;
    std::uint32_t instance = 0;
    glm::vec3 normal{0.0f};  // the shape's outward normal, world space
    glm::vec3 albedo{0.0f};  // the diffuse colour with the texel applied
    float depth = 0.0f;      // distance from the camera ray's origin
    // The terms: their sum is the sample's colour (before the film clamps it).
    glm::vec3 emit{0.0f}, ambient{0.0f}, diffuse{0.0f}, specular{0.0f}, reflect{0.0f}, transmit{0.0f};
    glm::vec3 background{0.0f};
    // Per light, in the scene's order: its diffuse and specular terms and what reaches the point from
    // it (1 lit, 0 blocked or facing away, a tint through glass).
    std::vector<glm::vec3> light_diffuse, light_specular, light_shadow;
    // Path mode: light that reached the camera in at most one bounce, and the rest.
    glm::vec3 direct{0.0f}, indirect{0.0f};

    void size_lights(std::size_t lights) {
        light_diffuse.assign(lights, glm::vec3(0.0f));
        light_specular.assign(lights, glm::vec3(0.0f));
        light_shadow.assign(lights, glm::vec3(0.0f));
    }
    // Back to nothing recorded, keeping the arrays' memory.
    void clear() {
        hit = false;
        instance = 0;
        normal = albedo = emit = ambient = diffuse = specular = reflect = transmit = background = direct = indirect =
            glm::vec3(0.0f);
        depth = 0.0f;
        for (auto* v : {&light_diffuse, &light_specular, &light_shadow}) std::fill(v->begin(), v->end(), glm::vec3(0.0f));
    }
};

// The recorder: keeps only what happens at the camera ray's hit (depth 0); a deeper hit's terms
// are inside what its reflected or refracted ray brought back.
class AovRecorder {
public:
    explicit AovRecorder(AovSample& out) : out_(out) {}

    void hit(const Ray& ray, const Hit& hit, const Surface& s, const glm::vec3&, bool, int depth) {
        open_ = depth;
        if (depth != 0) return;
        out_.hit = true;
        out_.instance = hit.instance;
        out_.normal = s.normal;
        out_.albedo = s.diffuse;
        out_.depth = hit.t * glm::length(ray.direction);
    }
    void miss(const glm::vec3& background) {
        if (open_ < 0) out_.background = background;  // the camera ray's own miss
    }
    void base(const glm::vec3& emit, const glm::vec3& ambient) {
        if (open_ != 0) return;
        out_.emit = emit;
        out_.ambient = ambient;
    }
    void light(const LightTerm& t) {
        if (open_ != 0 || t.light >= out_.light_shadow.size()) return;
        out_.diffuse += t.diffuse;
        out_.specular += t.specular;
        out_.light_diffuse[t.light] = t.diffuse;
        out_.light_specular[t.light] = t.specular;
        out_.light_shadow[t.light] = t.shadow;
    }
    void depth_limit() {}
    void total_internal_reflection() {}
    void secondary(SecondaryKind kind, SecondaryRecord::Outcome, const Ray&, const glm::vec3&) {
        if (open_ == 0) kind_ = kind;
    }
    void secondary_color(const glm::vec3&, const glm::vec3& contribution) {
        if (open_ != 0) return;
        // Under total internal reflection the mirror ray carries the transparent weight too: reflect.
        (kind_ == SecondaryKind::Reflect ? out_.reflect : out_.transmit) += contribution;
    }
    void done(const glm::vec3&) { --open_; }
    static constexpr bool kRecords = true;
    static constexpr bool kReadsUv = false;

private:
    AovSample& out_;
    int open_ = -1;  // the depth of the hit being shaded (-1: none yet, or the camera ray's is done)
    SecondaryKind kind_ = SecondaryKind::Reflect;  // of the camera hit's secondary ray being traced
};

}  // namespace whitted
