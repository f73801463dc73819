// Monte Carlo renders are deterministic: the same bytes for any thread count, tile size, or split
// of the samples into passes; and the §9.1 keywords at their "off" values change no byte.
#include <string>

#include <gtest/gtest.h>

#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted {
namespace {

// Every effect at once: a disc light, a spotlight disc, a directional cone, a lens, gloss on a
// mirror and on glass.
const char* kEffects = R"(
camera [ eye 0 1.5 6 focus 0 0.5 0 angle 45 aperture %APERTURE% ]
light [ position 3 5 4 color 0.8 0.8 0.8 radius %RADIUS% ]
light [ type spotlight position -3 4 2 direction 3 -4 -2 aperture 40 color 0.5 0.5 0.6 radius %RADIUS% ]
light [ type directional direction -1 -2 -1 color 0.3 0.3 0.3 angle %ANGLE% ]
mastersubgraph root [
  trans [ translate 0 -0.5 0 scale 12 1 12 object cube [ diffuse 0.8 0.8 0.8 ] ]
  trans [ translate -1.2 0.5 0 object sphere [ diffuse 0.2 0.2 0.2 reflect 0.7 0.7 0.7 %GLOSS% ] ]
  trans [ translate 1.2 0.5 0.5 object sphere [ diffuse 0.1 0.1 0.1 transparent 0.8 0.8 0.8 ior 1.4 %GLOSS% ] ]
  trans [ translate 0 0.6 -1.5 scale 0.6 1.2 0.6 object cylinder [ diffuse 0.9 0.3 0.2 specular 0.5 0.5 0.5 shine 30 ] ]
  trans [ translate 0.2 0.4 2 scale 0.5 0.8 0.5 object cone [ diffuse 0.2 0.6 0.9 ] ]
]
)";

std::string effects(const std::string& aperture, const std::string& radius, const std::string& angle,
                    const std::string& gloss) {
    std::string s = kEffects;
    auto put = [&](const std::string& key, const std::string& v) {
        for (std::size_t at; (at = s.find(key)) != std::string::npos;) s.replace(at, key.size(), v);
    };
    put("%APERTURE%", aperture);
    put("%RADIUS%", radius);
    put("%ANGLE%", angle);
    put("%GLOSS%", gloss);
    return s;
}

Image render_text(const std::string& text, RenderJob job) {
    LoadResult r = load_scene_text(text, "effects.sc");
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].str());
    if (!r.ok()) return {};
    Image image(job.width, job.height);
    render(*r.scene, job, image);
    return image;
}

RenderJob job_at(int spp) {
    RenderJob job;
    job.width = 80;
    job.height = 60;
    job.sampling.spp = spp;
    return job;
}

const std::string kAllOn = effects("0.15", "0.4", "6", "gloss 80");

TEST(SamplingDeterminism, SameBytesForAnyThreadCountAndTileSize) {
    RenderJob job = job_at(16);
    job.threads = 1;
    const Image one = render_text(kAllOn, job);
    job.threads = 2;
    const Image two = render_text(kAllOn, job);
    job.tile_size = 7;
    const Image small_tiles = render_text(kAllOn, job);
    job.threads = 3;
    job.tile_size = 64;
    const Image big_tiles = render_text(kAllOn, job);
    EXPECT_EQ(one.rgb, two.rgb);
    EXPECT_EQ(one.rgb, small_tiles.rgb);
    EXPECT_EQ(one.rgb, big_tiles.rgb);
    // And the effects really are on: the image differs from the one without them.
    EXPECT_NE(one.rgb, render_text(effects("0", "0", "0", ""), job_at(16)).rgb);
}

TEST(SamplingDeterminism, PassesAddUpToTheSameBytesAsOneGo) {
    LoadResult r = load_scene_text(kAllOn, "effects.sc");
    ASSERT_TRUE(r.ok());
    RenderJob job = job_at(16);
    job.sampling.aa = 2;  // 64 samples a pixel, in cells
    const auto integrator = make_integrator(*r.scene, job.camera_for(*r.scene), job.integrator);
    Film once(job.width, job.height), passes(job.width, job.height);
    render(*integrator, job, once);
    for (auto [b, e] : {std::pair{0, 1}, std::pair{1, 4}, std::pair{4, 20}, std::pair{20, 64}}) {
        job.sample_begin = b;
        job.sample_end = e;
        render(*integrator, job, passes);
    }
    EXPECT_EQ(once.to_image().rgb, passes.to_image().rgb);
    for (int y = 0; y < job.height; ++y)
        for (int x = 0; x < job.width; ++x) {
            ASSERT_EQ(once.at(x, y).sum, passes.at(x, y).sum) << x << "," << y;
            ASSERT_EQ(passes.at(x, y).weight, 64.0f);
        }
}

TEST(SamplingDeterminism, OffValuesOfTheNewKeywordsChangeNoByte) {
    const std::string without = effects("0", "0", "0", "");
    // The camera line without aperture, the lights without radius/angle: the file as before §9.1.
    std::string plain = without;
    for (const std::string k : {" aperture 0 ]", " radius 0 ]", " angle 0 ]"})
        for (std::size_t at; (at = plain.find(k)) != std::string::npos;) plain.replace(at, k.size(), " ]");
    ASSERT_EQ(plain.find("radius"), std::string::npos);
    for (int spp : {1, 16}) {
        EXPECT_EQ(render_text(without, job_at(spp)).rgb, render_text(plain, job_at(spp)).rgb) << spp;
    }
}

TEST(SamplingDeterminism, OneSampleUsesEveryCentre) {
    // With one sample per pixel the lens, the lights and the glossy lobes are at their centres:
    // the image of the file without them (§9.1).
    const std::string without = effects("0", "0", "0", "");
    EXPECT_EQ(render_text(kAllOn, job_at(1)).rgb, render_text(without, job_at(1)).rgb);
}

}  // namespace
}  // namespace whitted
