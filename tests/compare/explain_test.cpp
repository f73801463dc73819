// whitted explain: every named mistake, rendered, is diagnosed as that mistake; a term taken out or
// halved is fitted as a coefficient near 0 or 0.5; the reference itself shows no difference. Small
// images (64 × 48) of the bundled scenes, each chosen where the mistake changes the picture.
#include <cmath>
#include <map>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "compare/explain.h"
#include "compare/explain_report.h"
#include "film/film.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted {
namespace {

constexpr int kWidth = 64, kHeight = 48;

// A point light between a floor and a sphere above it: only what lies beyond the light shadows the
// floor below it, so the bundled scenes (lights above everything) do not show that mistake.
constexpr const char* kBeyondScene = R"(camera [ eye 0 3 8 focus 0 0 0 up 0 1 0 angle 50 ]
light [ position 0 2 0 color 1 1 1 ]
mastersubgraph root [
  trans [ translate 0 -0.5 0 scale 10 1 10 object cube [ diffuse 0.8 0.8 0.8 ] ]
  trans [ translate 0 4 0 scale 2 2 2 object sphere [ diffuse 0.2 0.2 0.8 ] ]
]
)";

// A plastic sphere on the left and a mirror sphere on the right, far apart over a floor: each
// mistake below changes one of them only.
constexpr const char* kTwoSpheresScene = R"(camera [ eye 0 1 9 focus 0 0 0 up 0 1 0 angle 45 ]
light [ position 0 6 6 color 1 1 1 ]
mastersubgraph root [
  trans [ translate 0 -1.5 0 scale 20 0.2 20 object cube [ diffuse 0.3 0.6 0.3 ] ]
  trans [ translate -2.6 0 0 object sphere [ diffuse 0.6 0.2 0.2 specular 1 1 1 shine 30 ] ]
  trans [ translate 2.6 0 0 object sphere [ diffuse 0.05 0.05 0.05 specular 0.4 0.4 0.4 shine 8 reflect 0.5 0.5 0.5 ] ]
]
)";

std::shared_ptr<const Scene> load(const std::string& name) {
    static std::map<std::string, std::shared_ptr<const Scene>> cache;
    auto& s = cache[name];
    if (!s) {
        LoadResult r = name == "(beyond)"        ? load_scene_text(kBeyondScene, "beyond.sc")
                       : name == "(two spheres)" ? load_scene_text(kTwoSpheresScene, "two.sc")
                                                 : load_scene(std::string(WHITTED_SCENES_DIR) + "/" + name);
        EXPECT_TRUE(r.ok()) << name;
        s = r.scene;
    }
    return s;
}

RenderJob small_job() {
    RenderJob job;
    job.width = kWidth;
    job.height = kHeight;
    job.threads = 2;
    return job;
}

const Variant* find_variant(const std::vector<Variant>& all, const std::string& name) {
    for (const Variant& v : all)
        if (v.name == name) return &v;
    return nullptr;
}

// The plain renderer's image (no variant code), as 8-bit values.
LinearImage plain_render(const Scene& scene, const RenderJob& job) {
    Image image(job.width, job.height);
    render(scene, job, image);
    LinearImage out{job.width, job.height, std::vector<glm::vec3>(image.rgb.size() / 3), {}};
    for (std::size_t i = 0; i < out.rgb.size(); ++i)
        out.rgb[i] = glm::vec3(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]) / 255.0f;
    return out;
}

struct Case {
    const char* variant;
    const char* scene;
};

// One scene per mistake where it changes the picture.
const Case kCases[] = {
    {"horizontal-fov", "showcase.sc"},
    {"pixel-corners", "showcase.sc"},
    {"upside-down", "showcase.sc"},
    {"normals-by-m", "features/transforms.sc"},
    {"blinn-phong", "showcase.sc"},
    {"no-attenuation", "features/point_light_attenuation.sc"},
    {"opaque-shadows", "features/refraction.sc"},
    {"shadows-beyond-light", "(beyond)"},
    {"depth-minus-1", "features/reflection.sc"},
    {"depth-plus-1", "features/refraction.sc"},
    {"no-tir", "features/refraction.sc"},
    {"eta-inverted", "features/refraction.sc"},
    {"texture-v-flipped", "textures.sc"},
    {"no-offset", "features/shadows.sc"},
    {"gamma", "showcase.sc"},
    {"no-specular", "showcase.sc"},
    {"no-diffuse", "showcase.sc"},
    {"no-ambient", "showcase.sc"},
    {"no-reflection", "features/reflection.sc"},
    {"no-transmission", "features/refraction.sc"},
    {"no-shadows-light-1", "features/shadows.sc"},
};

TEST(Explain, EveryMistakeIsDiagnosedAsItself) {
    for (const Case& c : kCases) {
        SCOPED_TRACE(std::string(c.variant) + " on " + c.scene);
        const auto scene = load(c.scene);
        ASSERT_TRUE(scene);
        const RenderJob job = small_job();
        const std::vector<Variant> all = explain_variants(*scene, job);
        const Variant* v = find_variant(all, c.variant);
        ASSERT_NE(v, nullptr);
        const LinearImage image = render_variant(*scene, job, v, true);
        const Explanation e = explain_image(*scene, job, image);
        if (!e.differs() || e.matches.empty()) {
            ADD_FAILURE() << "the mistake does not change this scene, or is not named";
            continue;
        }
        EXPECT_EQ(e.matches.front().variant.name, c.variant);
        EXPECT_TRUE(std::isinf(e.matches.front().psnr));
        EXPECT_TRUE(std::isfinite(e.psnr));
    }
}

// The mistakes made on the image or the camera, built here without the variant code: the image
// flipped, gamma applied to the reference's values, the camera's tangent divided by the aspect,
// the depth one less.
TEST(Explain, MistakesBuiltIndependentlyAreNamed) {
    const auto scene = load("showcase.sc");
    const RenderJob job = small_job();
    const LinearImage reference = plain_render(*scene, job);
    auto best = [&](const LinearImage& image) {
        const Explanation e = explain_image(*scene, job, image);
        return e.matches.empty() ? std::string("(none)") : e.matches.front().variant.name;
    };
    LinearImage flipped = reference;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x)
            flipped.rgb[std::size_t(y) * kWidth + x] = reference.rgb[std::size_t(kHeight - 1 - y) * kWidth + x];
    EXPECT_EQ(best(flipped), "upside-down");

    // Gamma on the 8-bit values is not gamma on the film's: near, not identical; still the closest.
    LinearImage gamma = reference;
    for (glm::vec3& p : gamma.rgb) p = glm::round(255.0f * glm::pow(p, glm::vec3(1 / 2.2f))) / 255.0f;
    EXPECT_EQ(best(gamma), "gamma");

    RenderJob wide = job;
    Camera camera = scene->data.camera;
    camera.tan_half_fov = camera.tan_half_fov * float(kHeight) / float(kWidth);  // the angle across, not up
    wide.camera = camera;
    EXPECT_EQ(best(plain_render(*scene, wide)), "horizontal-fov");

    const auto mirrors = load("features/reflection.sc");
    RenderJob shallow = job;
    shallow.integrator.max_depth = job.integrator.max_depth - 1;
    const Explanation e = explain_image(*mirrors, job, plain_render(*mirrors, shallow));
    ASSERT_FALSE(e.matches.empty());
    EXPECT_EQ(e.matches.front().variant.name, "depth-minus-1");
}

TEST(Explain, TheReferenceItselfShowsNoDifference) {
    const auto scene = load("showcase.sc");
    const RenderJob job = small_job();
    const Explanation e = explain_image(*scene, job, plain_render(*scene, job));
    EXPECT_FALSE(e.differs());
    EXPECT_EQ(e.compare.verdict, Verdict::pass);
    EXPECT_EQ(e.differing, 0u);
    EXPECT_TRUE(std::isinf(e.psnr));
    EXPECT_TRUE(e.variants.empty());  // nothing else is rendered
    const std::string text = explain_text(ExplainInputs{"showcase.sc", "ref.png", "PNG", "", ""}, {}, e);
    EXPECT_NE(text.find("no difference"), std::string::npos) << text;
}

// The scene's specular colours scaled by `k` (a copy of its data: the BVH is unchanged).
LinearImage with_specular(const Scene& scene, const RenderJob& job, float k) {
    Scene changed = scene;
    for (Material& m : changed.data.materials) m.specular *= k;
    return plain_render(changed, job);
}

const TermFit* fitted(const Explanation& e, const std::string& name) {
    for (const TermFit& t : e.terms)
        if (t.variant.name == name) return &t;
    return nullptr;
}

TEST(Explain, AMissingSpecularTermIsFittedNearZero) {
    const auto scene = load("showcase.sc");
    const RenderJob job = small_job();
    const Explanation e = explain_image(*scene, job, with_specular(*scene, job, 0.0f));
    const TermFit* t = fitted(e, "no-specular");
    ASSERT_NE(t, nullptr);
    EXPECT_NEAR(t->coefficient, 0.0, 0.05);
    EXPECT_GT(e.explained, 0.95);
    EXPECT_EQ(term_words(*t), "the specular highlights are missing");
    for (const TermFit& other : e.terms) {  // every other term is as in the reference
        if (&other != t) {
            EXPECT_NEAR(other.coefficient, 1.0, 0.1) << other.variant.name;
        }
    }
}

// Half the specular colour is half the specular term wherever no sample is clamped: the fit's
// coefficient is 0.5 up to the 8-bit rounding of both images and the few clamped highlights.
TEST(Explain, AHalvedSpecularTermIsFittedNearHalf) {
    const auto scene = load("showcase.sc");
    const RenderJob job = small_job();
    const Explanation e = explain_image(*scene, job, with_specular(*scene, job, 0.5f));
    const TermFit* t = fitted(e, "no-specular");
    ASSERT_NE(t, nullptr);
    EXPECT_NEAR(t->coefficient, 0.5, 0.05);
    EXPECT_EQ(term_words(*t), "the specular highlights are too weak");
}

// A hand-made fit: the image is the reference plus −0.7 × term A plus 0.25 × term B exactly, so
// the coefficients are 0.3 and 1.25 and the fit explains everything.
TEST(Explain, TheFitRecoversKnownCoefficients) {
    LinearImage reference{4, 1, {glm::vec3(0.5f), glm::vec3(0.6f), glm::vec3(0.2f), glm::vec3(0.9f)}, {}};
    LinearImage no_a = reference, no_b = reference;
    no_a.rgb[0] -= glm::vec3(0.2f, 0.1f, 0.0f);
    no_a.rgb[1] -= glm::vec3(0.3f);
    no_b.rgb[1] -= glm::vec3(0.0f, 0.1f, 0.2f);
    no_b.rgb[2] -= glm::vec3(0.1f);
    LinearImage image = reference;
    for (std::size_t i = 0; i < 4; ++i)
        image.rgb[i] += -0.7f * (reference.rgb[i] - no_a.rgb[i]) + 0.25f * (reference.rgb[i] - no_b.rgb[i]);
    double explained = 0;
    const std::vector<double> c = fit_terms(image, reference, {no_a, no_b}, {1, 1, 1, 0}, explained);
    ASSERT_EQ(c.size(), 2u);
    EXPECT_NEAR(c[0], 0.3, 1e-5);
    EXPECT_NEAR(c[1], 1.25, 1e-5);
    EXPECT_NEAR(explained, 1.0, 1e-6);
}

const TermFit* fitted_in(const Region& g, const std::string& name) {
    for (const TermFit& t : g.terms)
        if (t.variant.name == name) return &t;
    return nullptr;
}

// Two mistakes in two places: the left sphere without its highlights, the right one without its
// reflections (but with its highlights). One fit over the whole image says the highlights are
// missing, the right sphere's too; each region's own fit names its own mistake only.
TEST(Explain, EachRegionGetsTheFitOfItsOwnPixels) {
    const auto scene = load("(two spheres)");
    const RenderJob job = small_job();
    const std::vector<Variant> all = explain_variants(*scene, job);
    const Variant* no_specular = find_variant(all, "no-specular");
    const Variant* no_reflection = find_variant(all, "no-reflection");
    ASSERT_TRUE(no_specular && no_reflection);
    const LinearImage a = render_variant(*scene, job, no_specular, true);
    const LinearImage b = render_variant(*scene, job, no_reflection, true);
    LinearImage image = a;
    for (int y = 0; y < kHeight; ++y)
        for (int x = kWidth / 2; x < kWidth; ++x) image.rgb[std::size_t(y) * kWidth + x] = b.rgb[std::size_t(y) * kWidth + x];
    ExplainOptions o;
    o.max_regions = 2;
    const Explanation e = explain_image(*scene, job, image, o);
    ASSERT_EQ(e.regions.size(), 2u);
    const TermFit* global = fitted(e, "no-specular");
    ASSERT_TRUE(global);
    // The whole image's fit, led by the left sphere's highlights, says they are missing everywhere.
    EXPECT_LT(global->coefficient, 0.2);
    for (const Region& g : e.regions) {
        const bool left = g.x < kWidth / 2;
        SCOPED_TRACE(left ? "the left sphere" : "the right sphere");
        EXPECT_GT(g.explained, 0.9);
        const TermFit* spec = fitted_in(g, "no-specular");
        const TermFit* refl = fitted_in(g, "no-reflection");
        if (left) {
            ASSERT_TRUE(spec);
            EXPECT_NEAR(spec->coefficient, 0.0, 0.1);
            EXPECT_EQ(refl, nullptr) << "no reflection there to fit";
            EXPECT_NE(region_fit_words(g).find("the specular highlights are missing"), std::string::npos)
                << region_fit_words(g);
        } else {
            ASSERT_TRUE(refl);
            EXPECT_NEAR(refl->coefficient, 0.0, 0.1);
            ASSERT_TRUE(spec) << "the right sphere has highlights";
            EXPECT_NEAR(spec->coefficient, 1.0, 0.1);
            EXPECT_NE(region_fit_words(g).find("the reflections are missing"), std::string::npos) << region_fit_words(g);
            EXPECT_EQ(region_fit_words(g).find("specular"), std::string::npos) << region_fit_words(g);
        }
    }
}

TEST(Explain, RegionsAreTheBlocksThatDiffer) {
    const auto scene = load("showcase.sc");
    const RenderJob job = small_job();
    LinearImage image = plain_render(*scene, job);
    // Two separate patches: 3 × 3 pixels at (5, 5) changed by 0.5, one pixel at (50, 40) by 0.2.
    for (int y = 5; y < 8; ++y)
        for (int x = 5; x < 8; ++x) {
            glm::vec3& p = image.rgb[std::size_t(y) * kWidth + x];
            p = glm::vec3(1.0f) - p;
        }
    image.rgb[std::size_t(40) * kWidth + 50].x = image.rgb[std::size_t(40) * kWidth + 50].x > 0.5f ? 0.0f : 1.0f;
    const Explanation e = explain_image(*scene, job, image);
    ASSERT_EQ(e.regions.size(), 2u);
    EXPECT_EQ(e.regions[0].x0, 5);
    EXPECT_EQ(e.regions[0].y0, 5);
    EXPECT_EQ(e.regions[0].x1, 8);
    EXPECT_EQ(e.regions[0].y1, 8);
    EXPECT_EQ(e.regions[0].x, 6);  // the centre of the patch
    EXPECT_EQ(e.regions[0].y, 6);
    EXPECT_EQ(e.regions[1].x, 50);
    EXPECT_EQ(e.regions[1].y, 40);
    EXPECT_EQ(e.regions[1].inspection.x, 50);
}

}  // namespace
}  // namespace whitted
