#pragma once
// What the Whitted shading did for one camera sample, step by step: the tree of rays (camera ray,
// reflected and refracted rays below each hit), every light's terms, and what each secondary ray
// brought back. Filled by WhittedIntegrator's own shading code as it runs, so that the parts it
// lists are the ones the renderer added up (the pixel inspector reads them); the renderer runs
// the same code with a recorder whose every call is empty and compiles away.
#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "accel/bvh.h"
#include "integrator/light_sample.h"
#include "integrator/surface.h"
#include "base/ray.h"

namespace whitted {

// One light's share at a hit.
struct LightTerm {
    std::size_t light = 0;
    LightSample sample{};
    bool faces = false;      // the point faces the light (and is inside its cone)
    float n_dot_l = 0.0f;
    glm::vec3 shadow{0.0f};  // what reaches the point: 1 unshadowed, 0 blocked, a tint through glass
    glm::vec3 diffuse{0.0f}, specular{0.0f};  // the terms added (shadow · intensity · …)
};

enum class SecondaryKind : unsigned char { Reflect, Refract };

// A reflected or refracted ray leaving a hit.
struct SecondaryRecord {
    enum class Outcome : unsigned char {
        NoRay,        // the material has no such ray (or the depth limit stopped it)
        Traced,       // traced: `node` is its hit (-1: it left the scene, `color` is the background)
        TooWeak,      // its weight fell below 1/256 (scene-format.md §7): not traced
        OffSurface,   // a glossy direction drawn on the wrong side of the surface: carries nothing
        RayLimit,     // the camera sample had traced kMaxSecondaryRays already: not traced
    };
    Outcome outcome = Outcome::NoRay;
    Ray ray{};
    glm::vec3 weight{0.0f};        // the path's weight after this ray
    glm::vec3 color{0.0f};         // what the ray brought back
    glm::vec3 contribution{0.0f};  // what it added to the hit's colour (material weight · color)
    int node = -1;                 // its hit in ShadingRecorder::nodes, -1 = none
};

// One hit and its shading.
struct ShadeNode {
    int depth = 0;
    Ray ray{};
    Hit hit{};
    Surface surface{};
    glm::vec3 facing_normal{0.0f};  // the normal turned toward the viewer (what lighting uses)
    bool outside = true;            // the ray arrived from outside the shape
    glm::vec3 emit{0.0f}, ambient{0.0f};
    std::vector<LightTerm> lights;
    bool depth_limit = false;              // max depth reached: no reflected or refracted ray
    bool total_internal_reflection = false;  // transparent weight moved to the mirror ray
    SecondaryRecord reflect, refract;
    glm::vec3 color{0.0f};  // the hit's colour, as the shading returned it
};

// The recorder the renderer uses: does nothing, costs nothing.
struct NoShadingRecorder {
    void hit(const Ray&, const Hit&, const Surface&, const glm::vec3&, bool, int) {}
    void miss(const glm::vec3&) {}
    void base(const glm::vec3&, const glm::vec3&) {}
    void light(const LightTerm&) {}
    void depth_limit() {}
    void total_internal_reflection() {}
    void secondary(SecondaryKind, SecondaryRecord::Outcome, const Ray&, const glm::vec3&) {}
    void secondary_color(const glm::vec3&, const glm::vec3&) {}
    void done(const glm::vec3&) {}
    static constexpr bool kRecords = false;
    static constexpr bool kReadsUv = false;  // whether hit() reads the surface's uv
};

// The recorder the inspector uses: one ShadeNode per hit, nodes[0] the camera ray's (if it hit),
// each with its lights' terms (the ray tree draws every bounce's shadow rays). Bounded: a glass
// tree of 2^depth hits, or thousands of lights at every hit, would take gigabytes; past
// kMaxNodes hits, or kMaxLightTerms terms below the camera ray's hit, the rest is not kept.
class ShadingRecorder {
public:
    static constexpr std::size_t kMaxNodes = 4096;
    static constexpr std::size_t kMaxLightTerms = std::size_t(1) << 16;
    std::vector<ShadeNode> nodes;
    bool camera_ray_missed = false;
    glm::vec3 background{0.0f};  // the camera ray's colour when it missed

    void hit(const Ray& ray, const Hit& hit, const Surface& s, const glm::vec3& n, bool outside, int depth);
    void miss(const glm::vec3& background);
    void base(const glm::vec3& emit, const glm::vec3& ambient) {
        if (!recording()) return;
        open().emit = emit;
        open().ambient = ambient;
    }
    void light(const LightTerm& term) {
        if (!recording()) return;
        if (open().depth > 0 && light_terms_ >= kMaxLightTerms) return;
        if (open().depth > 0) ++light_terms_;
        open().lights.push_back(term);
    }
    void depth_limit() {
        if (recording()) open().depth_limit = true;
    }
    void total_internal_reflection() {
        if (recording()) open().total_internal_reflection = true;
    }
    // A secondary ray of the open hit: traced next when outcome is Traced.
    void secondary(SecondaryKind kind, SecondaryRecord::Outcome outcome, const Ray& ray, const glm::vec3& weight);
    // What the secondary ray traced last brought back and added.
    void secondary_color(const glm::vec3& color, const glm::vec3& contribution);
    void done(const glm::vec3& color);
    static constexpr bool kRecords = true;
    static constexpr bool kReadsUv = true;  // the report gives every hit its uv, textured or not

private:
    std::vector<int> open_;  // the hits being shaded, innermost last (-1: one past the bound, not kept)
    struct Pending {
        int node;  // whose ray
        SecondaryKind kind;
    };
    std::vector<Pending> pending_;  // secondary rays being traced, innermost last
    std::size_t light_terms_ = 0;   // kept below the camera ray's hit
    SecondaryRecord& record(const Pending& p);
    bool recording() const { return open_.back() >= 0; }
    ShadeNode& open() { return nodes[std::size_t(open_.back())]; }
};

}  // namespace whitted
