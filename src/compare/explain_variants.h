#pragma once
// The renders `whitted explain` compares a student's image with: the reference itself, the lab's
// classic mistakes (each a named variant: the wrong field of view, rays through pixel corners, …)
// and the reference with one term taken out (no specular, no shadows from light k, …), whose
// difference from the reference is that term's image. A mistake inside the Whitted shading is a
// switch of integrator/conventions.h; the others are made on a copy of the scene's data, the
// camera or the finished image, so a normal render never sees them.
#include <string>
#include <vector>

#include "accel/scene.h"
#include "film/image.h"
#include "render/render_job.h"

namespace whitted {

enum class VariantId {
    HorizontalFov, PixelCorners, UpsideDown, NormalsByM, BlinnPhong, NoAttenuation, OpaqueShadows,
    ShadowsBeyondLight, DepthMinusOne, DepthPlusOne, NoTotalInternalReflection, EtaInverted, TextureVFlipped,
    NoOffset, Gamma,
    // Removals: the reference without one term.
    NoSpecular, NoDiffuse, NoAmbient, NoReflection, NoTransmission, NoShadowsFromLight,
};

struct Variant {
    VariantId id;
    int light = -1;  // NoShadowsFromLight: which light (0-based)
    std::string name;   // "horizontal-fov", "no-shadows-light-2" (1-based, as the words)
    std::string words;  // "horizontal field of view", "no shadows from light 2"
    bool removal = false;  // a term taken out (its image is the reference minus this render)
    std::string term;      // removal: the term's name ("specular", "shadows of light 2")
};

// The variants worth rendering for this scene and job: every mistake, the removals, and the
// shadows of each of the first kMaxShadowLights lights. The mistakes inside the §7 shading are
// left out for a scene the course's model (§9.5) draws, which has no such switches.
constexpr int kMaxShadowLights = 8;
std::vector<Variant> explain_variants(const Scene& scene, const RenderJob& job);

// The job's render of the scene (its linear values, each pixel the mean of its clamped samples as
// the film keeps them) with `variant`'s mistake made, or the reference when `variant` is null.
// `quantize`: rounded to 8 bits, as a PNG of it would hold. Null `cancel` in the job: runs to the end.
LinearImage render_variant(const Scene& scene, const RenderJob& job, const Variant* variant, bool quantize);

}  // namespace whitted
