#pragma once
// The pixel inspector: what made one pixel of a render. The object its camera ray hit and where
// the file says it (the `object` keyword, the mastersubgraph / trans / subgraph lines above it),
// its material, the hit, every light's share and what shadows it, where the reflected and
// refracted rays went, and the pixel's colour split into the parts of the Whitted model that
// add up to it.
//
// The colour is never recomputed by a second shading: the pixel is rendered by the renderer
// itself (a one-pixel region of the same job), and the parts are recorded by the Whitted
// integrator's own shading code as it runs (integrator/shading_record.h), averaged over the
// pixel's samples as the film averages them.
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "accel/scene.h"
#include "data/provenance.h"
#include "inspect/ray_tree.h"
#include "integrator/shading_record.h"
#include "render/render_job.h"

namespace whitted {

// A drawn object: which instance, its shape, where its `object` keyword is, the chain above it.
struct ObjectInfo {
    std::uint32_t instance = 0;
    ShapeKind kind = ShapeKind::Cube;
    std::uint32_t material = 0;
    SourceLoc loc;                 // the `object` keyword (line 0: not recorded, a scene built in code)
    std::vector<ChainLink> chain;  // root first, down to the trans block holding the object
};

struct HitInfo {
    ObjectInfo object;
    float t = 0;  // along the ray, whose direction is a unit vector for camera rays
    glm::vec3 point{0.0f}, normal{0.0f};  // world space; the outward normal of the shape
    glm::vec2 uv{0.0f};
    bool outside = true;  // the ray came from outside the shape
};

// Something between a shaded point and a light.
struct Blocker {
    ObjectInfo object;
    float t = 0;               // distance from the shaded point
    bool transparent = false;  // glass: tints the light, lets it through
};

struct LightInfo {
    LightTerm term;  // what the shading computed for it
    LightType type = LightType::Point;
    SourceLoc loc;   // its `light` block
    std::vector<Blocker> blockers;  // from the point toward the light, up to the first opaque one
};

// A reflected or refracted ray of the camera ray's hit.
struct SecondaryInfo {
    SecondaryRecord record;  // outcome, ray, weight, what it brought back and added
    std::optional<HitInfo> next;  // its hit; none when it left the scene (or was not traced)
};

// The pixel's colour in parts: their sum is `value` of the report (up to float rounding).
struct ColourParts {
    glm::vec3 ambient{0.0f}, diffuse{0.0f}, specular{0.0f}, reflect{0.0f}, transparent{0.0f}, emit{0.0f};
    glm::vec3 background{0.0f};  // samples whose camera ray hit nothing
    glm::vec3 clamp{0.0f};       // what clamping each sample to [0, 1] took away (§7), ≤ 0
    glm::vec3 sum() const { return ambient + diffuse + specular + reflect + transparent + emit + background + clamp; }
};

// What the camera rays of the pixel's samples hit.
struct SeenCount {
    bool background = false;
    ObjectInfo object;  // unless background
    int samples = 0;
};

struct PixelReport {
    int x = 0, y = 0, width = 0, height = 0;
    RenderMode mode = RenderMode::Whitted;
    int max_depth = 0;
    SamplingSettings sampling;
    int samples = 0;  // the samples the film averaged for this pixel (adaptive: 1 or all)
    bool cancelled = false;  // the job's cancel flag was set: the report is incomplete, not to be shown

    glm::vec3 value{0.0f};  // the film's value of the pixel (linear; the mean of its samples)
    glm::u8vec3 bytes{0};   // its 8-bit value

    bool decomposed = false;  // `parts` hold the split (Whitted mode); otherwise see `note`
    ColourParts parts;
    std::vector<SeenCount> seen;
    std::string note;  // what is and is not decomposed, when not everything is

    // One sample in detail: the one nearest the pixel's centre.
    int detail_sample = 0;
    Ray camera_ray{};
    glm::vec3 background{0.0f};  // the scene's background colour
    std::optional<HitInfo> hit;   // none: the camera ray sees only the background
    Material material;            // of the hit object
    SourceLoc material_loc;       // its object block
    std::string texture_file;     // as written in the scene; "" = none
    glm::vec3 diffuse_at_hit{0.0f}, ambient_at_hit{0.0f};  // the material's with the texel applied
    std::vector<LightInfo> lights;
    bool total_internal_reflection = false, depth_limit = false;
    SecondaryInfo reflected, refracted;
    RayTree ray_tree;  // the detail sample's rays, every bounce, in world space (ray_tree.h)
};

// What the inspector needs to know about the render: the job the image was rendered with (its
// size, camera, mode and depth, sampling). Its region, sample range, threads, cancel flag and
// callbacks are ignored: the whole pixel is inspected, stopped only by `cancel` (looked at every
// packet of samples as it is rendered and every sample as it is traced again).
// Pixel (x, y): column x, row y, row 0 at the top; it must lie inside the job's image.
PixelReport inspect_pixel(const Scene& scene, const RenderJob& job, int x, int y,
                          const std::atomic<bool>* cancel = nullptr);

// The object behind instance `instance` of the scene.
ObjectInfo describe_object(const Scene& scene, std::uint32_t instance);

}  // namespace whitted
