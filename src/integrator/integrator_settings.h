#pragma once
// How to render: the method and its recursion limit. Settings only, so that whatever describes a
// render (render/render_job.h) names them without pulling in an integrator.
#include "cs1230/stage.h"
#include "integrator/conventions.h"
#include "integrator/render_mode.h"
#include "texture/texture_filter.h"

namespace whitted {

struct IntegratorSettings {
    RenderMode mode = RenderMode::Whitted;
    int max_depth = 5;  // camera ray = depth 0; no ray deeper than this is traced (path: bounces)
    // Which of the course's projects draws a CSCI 1230 scene in Whitted mode (§9.5).
    cs1230::Stage cs1230_stage = cs1230::Stage::Illuminate;
    // The lab's classic mistakes, made on purpose (whitted explain); §7 Whitted shading only.
    Conventions conventions{};
    // Path mode's caustics from point, spot and directional lights (integrator/caustic_integrator.h):
    // photons emitted per sample index (0 = none), and the gather radius of the first sample in
    // world units (0 = from the scene's size).
    int photons = 1 << 16;
    float photon_radius = 0.0f;
    // How textures are read, and for trilinear and ewa the footprint of a camera sample: the
    // image's rows times the samples' spacing within a pixel (√ of the samples per pixel, at most
    // 8); 0 = no footprint (textures are read from their image, bilinearly).
    TextureFilter texture_filter = TextureFilter::Bilinear;
    float texture_sample_rows = 0.0f;
    bool operator==(const IntegratorSettings&) const = default;
};

}  // namespace whitted
