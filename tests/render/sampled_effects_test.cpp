// Which §9.1 effects a scene has, and the hint for a render that takes one sample per pixel.
#include <string>

#include <gtest/gtest.h>

#include "render/load_scene.h"

namespace whitted {
namespace {

SampledEffects effects_of(const std::string& text) {
    const LoadResult r = load_scene_text(text, "e.sc");
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].str());
    return r.stats.effects;
}

const char* kRoot = "mastersubgraph root [ trans [ object sphere [ ] ] ]\n";

TEST(SampledEffects, AreFoundWhereTheFileWritesThem) {
    const SampledEffects none = effects_of(std::string("camera [ eye 0 0 5 ]\nlight [ position 1 1 1 ]\n") + kRoot);
    EXPECT_FALSE(none.any());
    const SampledEffects lens = effects_of(std::string("camera [ eye 0 0 5 focus 0 0 0 aperture 0.2 ]\n") + kRoot);
    EXPECT_TRUE(lens.depth_of_field);
    EXPECT_FALSE(lens.soft_shadows || lens.gloss);
    EXPECT_TRUE(effects_of(std::string("light [ position 1 1 1 radius 0.5 ]\n") + kRoot).soft_shadows);
    EXPECT_TRUE(effects_of(std::string("light [ type directional direction 0 -1 0 angle 2 ]\n") + kRoot).soft_shadows);
    EXPECT_TRUE(effects_of("mastersubgraph root [ trans [ object sphere [ reflect 1 1 1 gloss 50 ] ] ]\n").gloss);
}

TEST(SampledEffects, OneSamplePerPixelOfAWhittedRenderIsTold) {
    SampledEffects e;
    e.soft_shadows = e.depth_of_field = true;
    SamplingSettings one;
    EXPECT_EQ(sampled_effects_hint(e, one, RenderMode::Whitted),
              "this scene has soft shadows and depth of field: raise SPP to see them (one sample per pixel takes the "
              "lens and light centres)");
    SampledEffects dof;
    dof.depth_of_field = true;
    EXPECT_EQ(sampled_effects_hint(dof, one, RenderMode::Whitted).rfind("this scene has depth of field: raise SPP to see it", 0),
              0u);
    SamplingSettings more = one;
    more.spp = 4;
    EXPECT_EQ(sampled_effects_hint(e, more, RenderMode::Whitted), "");
    SamplingSettings aa = one;
    aa.aa = 2;  // four samples, each with its own lens and light points
    EXPECT_EQ(sampled_effects_hint(e, aa, RenderMode::Whitted), "");
    EXPECT_EQ(sampled_effects_hint(e, one, RenderMode::Path), "");  // a path's one sample is random, not the centres
    EXPECT_EQ(sampled_effects_hint(SampledEffects{}, one, RenderMode::Whitted), "");
}

}  // namespace
}  // namespace whitted
