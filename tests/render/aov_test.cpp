// Per-term images (render/aov.h, render/aov_renderer.h, the session's layers): the Whitted terms
// add up to the image on every bundled scene, path mode's direct and indirect to its image; the
// object layer names the object the pixel inspector names; a light's visibility is 0 in its shadow
// and 1 in its light; depth is the closed-form distance to a plane; and asking for layers leaves
// the image's bytes as they were.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "inspect/inspect_scene.h"
#include "inspect/pixel_inspector.h"
#include "render/aov.h"
#include "render/load_scene.h"
#include "session/session.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

std::shared_ptr<const Scene> load_text(const std::string& text) {
    LoadResult r = load_scene_text(text, "scene.sc");
    EXPECT_TRUE(r.ok());
    return r.scene;
}

RenderJob small_job(int width, int height, std::vector<std::string> aovs = {}) {
    RenderJob job;
    job.width = width;
    job.height = height;
    job.tile_size = 16;
    job.threads = 2;
    job.aovs = std::move(aovs);
    return job;
}

// Renders every pass of the job; the layers by name (each with its values).
struct Rendered {
    std::unique_ptr<Session> session;
    std::map<std::string, ImageLayer> layers;
    const float* at(const std::string& name, int x, int y) const {
        const ImageLayer& l = layers.at(name);
        return &l.values[(std::size_t(y) * std::size_t(session->job().width) + std::size_t(x)) * l.channels.size()];
    }
    glm::vec3 rgb(const std::string& name, int x, int y) const {
        const float* v = at(name, x, y);
        return {v[0], v[1], v[2]};
    }
};

Rendered render_all(std::shared_ptr<const Scene> scene, const RenderJob& job) {
    Rendered r;
    EXPECT_EQ(aov_problem(*scene, job), "");
    r.session = std::make_unique<Session>(scene, job);
    while (!r.session->done()) EXPECT_FALSE(r.session->render_pass().render.cancelled);
    if (const AovPlan* plan = r.session->aov_plan()) {
        const std::vector<ImageLayer> layers = plan->resolve(r.session->aov_film(), r.session->film());
        for (std::size_t i = 0; i < layers.size(); ++i) r.layers[plan->layers()[i].name] = layers[i];
    }
    return r;
}

std::vector<fs::path> bundled_scenes() {
    std::vector<fs::path> out;
    for (const auto& e : fs::recursive_directory_iterator(fs::path(WHITTED_SOURCE_DIR) / "scenes"))
        if (e.is_regular_file() && e.path().extension() == ".sc") out.push_back(e.path());
    std::sort(out.begin(), out.end());
    return out;
}

glm::vec3 clamped(const glm::vec3& c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z)}; }

// The terms of one sample are exactly what the shading added up; the film clamps that sum (§7).
// At one sample per pixel the clamped sum of the term layers is the pixel, on every bundled scene
// (the regression scenes), and the lights' layers add up to the totals.
TEST(Aov, WhittedTermsAddUpToTheImageOnEveryBundledScene) {
    const std::vector<fs::path> scenes = bundled_scenes();
    ASSERT_GE(scenes.size(), 15u);
    for (const fs::path& path : scenes) {
        SCOPED_TRACE(path.string());
        LoadResult loaded = load_scene(path.string());
        ASSERT_TRUE(loaded.ok());
        const Rendered r = render_all(loaded.scene, small_job(160, 120, {"all"}));
        const std::size_t lights = loaded.scene->data.lights.size();
        int checked = 0;
        for (int y = 0; y < 120; ++y)
            for (int x = 0; x < 160; ++x) {
                glm::vec3 sum(0.0f), diffuse(0.0f), specular(0.0f);
                for (const char* term : {"ambient", "diffuse", "specular", "reflect", "transmit", "emit", "background"})
                    sum += r.rgb(term, x, y);
                for (std::size_t k = 1; k <= lights && k <= 64; ++k) {
                    diffuse += r.rgb("diffuse.L" + std::to_string(k), x, y);
                    specular += r.rgb("specular.L" + std::to_string(k), x, y);
                }
                const glm::vec3 pixel = r.session->film().at(x, y).value();
                const glm::vec3 d = glm::abs(clamped(sum) - pixel);
                ASSERT_LE(std::max(d.x, std::max(d.y, d.z)), 1e-5f) << "pixel " << x << "," << y;
                const glm::vec3 dl = glm::abs(diffuse - r.rgb("diffuse", x, y)) + glm::abs(specular - r.rgb("specular", x, y));
                ASSERT_LE(std::max(dl.x, std::max(dl.y, dl.z)), 1e-5f) << "pixel " << x << "," << y;
                ++checked;
            }
        EXPECT_EQ(checked, 160 * 120);
    }
}

// Path mode: the colour of every sample is its direct part plus the rest, so the two layers' means
// add up to the pixel (the film keeps path mode's samples unclamped).
TEST(Aov, PathDirectAndIndirectAddUpToTheImage) {
    LoadResult loaded = load_scene((fs::path(WHITTED_SOURCE_DIR) / "scenes/features/cornell_box.sc").string());
    ASSERT_TRUE(loaded.ok());
    RenderJob job = small_job(48, 36, {"direct", "indirect", "depth"});
    job.integrator.mode = RenderMode::Path;
    job.integrator.max_depth = 8;
    job.sampling.spp = 8;
    const Rendered r = render_all(loaded.scene, job);
    float indirect_total = 0.0f;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) {
            const glm::vec3 pixel = r.session->film().at(x, y).value();
            const glm::vec3 sum = r.rgb("direct", x, y) + r.rgb("indirect", x, y);
            const glm::vec3 d = glm::abs(sum - pixel);
            ASSERT_LE(std::max(d.x, std::max(d.y, d.z)), 1e-4f * (1.0f + std::max(pixel.x, std::max(pixel.y, pixel.z))))
                << "pixel " << x << "," << y;
            indirect_total += r.rgb("indirect", x, y).x;
        }
    // A closed box's walls light each other: the indirect layer is not empty.
    EXPECT_GT(indirect_total, 0.0f);
}

// The object layer holds, per pixel, the object of the sample nearest the pixel's centre: the one
// the inspector details. Checked on a grid of pixels of the inspector's scene, with one sample
// per pixel and with 3 x 3.
TEST(Aov, ObjectIdsAgreeWithTheInspector) {
    const auto scene = load_text(test::kInspectScene);
    for (int aa : {1, 3}) {
        SCOPED_TRACE("aa " + std::to_string(aa));
        RenderJob job = small_job(test::kInspectWidth, test::kInspectHeight, {"object"});
        job.sampling.aa = aa;
        const Rendered r = render_all(scene, job);
        std::map<std::uint32_t, int> seen;
        for (int y = 3; y < test::kInspectHeight; y += 6)
            for (int x = 5; x < test::kInspectWidth; x += 6) {
                const PixelReport report = inspect_pixel(*scene, job, x, y);
                const std::uint32_t expected = report.hit ? report.hit->object.instance + 1 : 0;
                EXPECT_EQ(AovPlan::object_id(r.session->aov_film(), x, y), expected) << "pixel " << x << "," << y;
                EXPECT_EQ(std::uint32_t(*r.at("object", x, y)), expected);
                ++seen[expected];
            }
        // The grid crosses the background and every object (floor, two pillars, sphere, mirror).
        EXPECT_EQ(seen.size(), 6u);
    }
}

// Two lights over a floor with a ball: light 1 straight above the ball (its shadow on the floor
// right below), light 2 low on the +x side (nothing between it and the floor).
constexpr const char* kTwoLights = R"(
camera [ eye 0 0 10 focus 0 0 0 up 0 1 0 angle 60 ]
light [ position 0 10 0 color 1 1 1 ]
light [ position 10 -1 0 color 1 1 1 ]
mastersubgraph root [
  trans [ translate 0 -2 0 scale 20 0.2 20 object cube [ diffuse 0.6 0.6 0.6 ] ]
  trans [ translate 0 2 0 object sphere [ diffuse 1 0 0 ] ]
]
)";

TEST(Aov, ShadowIsZeroInALightsShadowAndOneInItsLight) {
    const auto scene = load_text(kTwoLights);
    const Rendered r = render_all(scene, small_job(test::kInspectWidth, test::kInspectHeight, {"shadow"}));
    ASSERT_EQ(r.layers.size(), 2u);
    // Under the ball (within 0.74 of its axis on the floor, y = -1.9): light 1 is hidden.
    const glm::ivec2 under = test::project({0.0f, -1.9f, 0.3f});
    EXPECT_EQ(r.rgb("shadow.L1", under.x, under.y), glm::vec3(0.0f));
    EXPECT_EQ(r.rgb("shadow.L2", under.x, under.y), glm::vec3(1.0f));
    // Two units to the side and front: the line to light 1 passes the ball 1.3 units from its centre.
    const glm::ivec2 side = test::project({2.0f, -1.9f, 2.0f});
    EXPECT_EQ(r.rgb("shadow.L1", side.x, side.y), glm::vec3(1.0f));
    EXPECT_EQ(r.rgb("shadow.L2", side.x, side.y), glm::vec3(1.0f));
    // The ball's top faces light 1 and nothing is above it; light 2, below its equator's level
    // (y = -1 < 2), does not reach the top, which faces away from it.
    const glm::ivec2 top = test::project({0.0f, 2.45f, 0.2f});
    EXPECT_EQ(r.rgb("shadow.L1", top.x, top.y), glm::vec3(1.0f));
    EXPECT_EQ(r.rgb("shadow.L2", top.x, top.y), glm::vec3(0.0f));
}

// A wall whose front face is the plane z = 0, seen from (0, 0, 10) down -z with a 60° vertical
// field of view: pixel (x, y)'s centre ray has the direction (sx·tan 30°·aspect, sy·tan 30°, -1)
// (sx, sy in [-1, 1] at the pixel's centre, y up) and meets the plane at 10 × its length.
constexpr const char* kWall = R"(
camera [ eye 0 0 10 focus 0 0 0 up 0 1 0 angle 60 ]
light [ position 0 0 10 color 1 1 1 ]
mastersubgraph root [
  trans [ translate 0 0 -0.5 scale 100 100 1 object cube [ diffuse 0.5 0.5 0.5 ] ]
]
)";

TEST(Aov, DepthIsTheDistanceToAPlane) {
    const auto scene = load_text(kWall);
    constexpr int w = 64, h = 48;
    const Rendered r = render_all(scene, small_job(w, h, {"depth", "normal"}));
    const float tan_half = std::tan(glm::radians(30.0f)), aspect = float(w) / float(h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float sx = 2.0f * (float(x) + 0.5f) / float(w) - 1.0f, sy = 1.0f - 2.0f * (float(y) + 0.5f) / float(h);
            const float expected = 10.0f * glm::length(glm::vec3(sx * tan_half * aspect, sy * tan_half, -1.0f));
            ASSERT_NEAR(*r.at("depth", x, y), expected, 1e-4f * expected) << "pixel " << x << "," << y;
            ASSERT_EQ(r.rgb("normal", x, y), glm::vec3(0, 0, 1));
        }
    // Nothing hit: depth +inf (the inspector's scene's empty corner).
    const auto sky = load_text(test::kInspectScene);
    const Rendered s = render_all(sky, small_job(test::kInspectWidth, test::kInspectHeight, {"depth"}));
    const glm::ivec2 p = test::project(test::kEmptySky);
    EXPECT_TRUE(std::isinf(*s.at("depth", p.x, p.y)));
}

bool same_film(const Film& a, const Film& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (std::memcmp(&a.at(x, y), &b.at(x, y), sizeof(FilmPixel)) != 0) return false;
    return true;
}

// Layers or not, the film holds the same sums: the same colours added in the same order (one
// sample, several, adaptive sampling between passes, path mode).
TEST(Aov, TheImageIsTheSameWithAndWithoutLayers) {
    struct Case {
        const char* scene;
        RenderMode mode;
        int spp;
        float noise;
    };
    for (const Case& c : {Case{"showcase.sc", RenderMode::Whitted, 1, 0.0f},
                          Case{"features/refraction.sc", RenderMode::Whitted, 1, 0.0f},
                          Case{"features/soft_shadows.sc", RenderMode::Whitted, 8, 0.0f},
                          Case{"features/glossy.sc", RenderMode::Whitted, 32, 0.05f},
                          Case{"features/cornell_box.sc", RenderMode::Path, 4, 0.0f}}) {
        SCOPED_TRACE(c.scene);
        LoadResult loaded = load_scene((fs::path(WHITTED_SOURCE_DIR) / "scenes" / c.scene).string());
        ASSERT_TRUE(loaded.ok());
        RenderJob job = small_job(80, 60);
        job.integrator.mode = c.mode;
        job.sampling.spp = c.spp;
        job.sampling.noise_threshold = c.noise;
        job.sampling.min_spp = 4;
        const Rendered plain = render_all(loaded.scene, job);
        job.aovs = {"all"};
        const Rendered layered = render_all(loaded.scene, job);
        EXPECT_TRUE(same_film(plain.session->film(), layered.session->film()));
        EXPECT_EQ(plain.session->samples_per_pixel(), layered.session->samples_per_pixel());
        // The samples layer counts them.
        const std::vector<int> spp = layered.session->samples_per_pixel();
        for (int y = 0; y < 60; y += 7)
            for (int x = 0; x < 80; x += 7) EXPECT_EQ(*layered.at("samples", x, y), float(spp[std::size_t(y) * 80 + std::size_t(x)]));
    }
}

TEST(Aov, NamesAreCheckedForTheModeAndTheScenesLights) {
    EXPECT_EQ(check_aov_names({"diffuse", "shadow.L3", "specular.L*", "all"}, RenderMode::Whitted), "");
    EXPECT_NE(check_aov_names({"direct"}, RenderMode::Whitted), "");
    EXPECT_NE(check_aov_names({"diffuse"}, RenderMode::Path), "");
    EXPECT_NE(check_aov_names({"depth"}, RenderMode::Raycast), "");
    EXPECT_NE(check_aov_names({"shadow.L0"}, RenderMode::Whitted), "");
    EXPECT_NE(check_aov_names({"shadow.Lx"}, RenderMode::Whitted), "");
    EXPECT_NE(check_aov_names({"difuse"}, RenderMode::Whitted), "");
    AovPlan plan;
    EXPECT_NE(AovPlan::make({"shadow.L3"}, RenderMode::Whitted, 2, plan), "");
    ASSERT_EQ(AovPlan::make({"depth", "shadow", "diffuse", "depth"}, RenderMode::Whitted, 2, plan), "");
    std::vector<std::string> names;
    for (const AovLayer& l : plan.layers()) names.push_back(l.name);
    EXPECT_EQ(names, (std::vector<std::string>{"diffuse", "shadow.L1", "shadow.L2", "depth"}));
    EXPECT_NE(AovPlan::make({"all"}, RenderMode::Whitted, 30, plan), "");  // 7 + 90 + 5 layers: too many
    EXPECT_EQ(split_aov_list(" diffuse, ,depth,"), (std::vector<std::string>{"diffuse", "depth"}));
}

}  // namespace
}  // namespace whitted
