// Image regression: every bundled scene (scenes/**/*.sc) rendered at 160×120 must match its
// reference in tests/regression/reference/ within a tolerance. The references were inspected by
// eye when written (scripts/update-reference-images.sh says how); this test guards them against
// unintended change, e.g. from an optimisation that was meant to alter no pixel.
//
// Tolerance: a knife-edge pixel (a ray grazing a silhouette or a shadow boundary) may flip with the
// compiler's floating-point choices (Release -O3 against the sanitizer build), so a few pixels may
// differ a lot; the picture as a whole may not.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "film/image_io.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 160, kHeight = 120;
constexpr double kMaxOutlierFraction = 0.005;  // pixels with a channel off by more than kOutlier
constexpr int kOutlier = 24;
constexpr double kMaxMeanError = 0.5;  // mean absolute error per channel, in 8-bit steps

const fs::path kScenes = fs::path(WHITTED_SOURCE_DIR) / "scenes";
const fs::path kReferences = fs::path(WHITTED_SOURCE_DIR) / "tests" / "regression" / "reference";

// scenes/features/shapes.sc -> features__shapes (the name the update script gives it).
std::string reference_name(const fs::path& scene) {
    std::string name = scene.lexically_relative(kScenes).replace_extension().generic_string();
    for (std::size_t i; (i = name.find('/')) != std::string::npos;) name.replace(i, 1, "__");
    return name;
}

std::vector<fs::path> bundled_scenes() {
    std::vector<fs::path> scenes;
    for (const auto& e : fs::recursive_directory_iterator(kScenes))
        if (e.is_regular_file() && e.path().extension() == ".sc") scenes.push_back(e.path());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

struct Difference {
    double mean = 0;  // mean absolute error per channel
    double outlier_fraction = 0;
    int worst = 0;
};

Difference compare(const Image& a, const Image& b) {
    Difference d;
    long long sum = 0, outliers = 0;
    for (std::size_t p = 0; p < a.rgb.size(); p += 3) {
        int pixel_worst = 0;
        for (int c = 0; c < 3; ++c) {
            const int e = std::abs(int(a.rgb[p + c]) - int(b.rgb[p + c]));
            sum += e;
            pixel_worst = std::max(pixel_worst, e);
        }
        outliers += pixel_worst > kOutlier;
        d.worst = std::max(d.worst, pixel_worst);
    }
    d.mean = double(sum) / double(a.rgb.size());
    d.outlier_fraction = double(outliers) / double(a.rgb.size() / 3);
    return d;
}

// Renders `scene` at the test size and compares it with reference `name`.png.
void expect_matches_reference(const fs::path& scene, const std::string& name, int aa, int spp = 1) {
    const fs::path failed_dir = fs::temp_directory_path() / "whitted-regression";
    {
        SCOPED_TRACE(name);
        Image reference;
        const std::string ref_path = (kReferences / (name + ".png")).string();
        ASSERT_EQ(read_image(ref_path, reference), "")
            << "no reference for " << scene << ": run scripts/update-reference-images.sh and inspect it";
        ASSERT_EQ(reference.width, kWidth);
        ASSERT_EQ(reference.height, kHeight);

        const LoadResult loaded = load_scene(scene.string());
        ASSERT_TRUE(loaded.ok()) << (loaded.diagnostics.empty() ? "" : loaded.diagnostics.back().str());
        RenderJob options;
        options.width = kWidth;
        options.height = kHeight;
        options.sampling.aa = aa;
        options.sampling.spp = spp;
        Image image(kWidth, kHeight);
        render(*loaded.scene, options, image);

        const Difference d = compare(image, reference);
        const bool ok = d.mean <= kMaxMeanError && d.outlier_fraction <= kMaxOutlierFraction;
        if (!ok) {  // keep the new picture where it can be looked at next to the reference
            fs::create_directories(failed_dir);
            write_image(image, (failed_dir / (name + ".png")).string());
        }
        EXPECT_TRUE(ok) << "mean error " << d.mean << " (max " << kMaxMeanError << "), "
                        << 100 * d.outlier_fraction << "% of pixels off by more than " << kOutlier
                        << " (max " << 100 * kMaxOutlierFraction << "%), worst " << d.worst
                        << "; this render is in " << failed_dir.string();
    }
}

TEST(SceneImages, EveryBundledSceneMatchesItsReference) {
    const auto scenes = bundled_scenes();
    ASSERT_GE(scenes.size(), 12u) << "the showcase, the texture scene and the feature scenes";
    for (const fs::path& scene : scenes) expect_matches_reference(scene, reference_name(scene), 1);
}

TEST(SceneImages, TheAntiAliasedShowcaseMatchesItsReference) {
    expect_matches_reference(kScenes / "showcase.sc", "showcase__aa3", 3);
}

// The distribution effects (§9.1) need samples: their scenes and the showcase at 16 per pixel.
TEST(SceneImages, TheDistributionEffectsMatchTheirReferencesAt16Samples) {
    for (const char* scene : {"features/soft_shadows.sc", "features/depth_of_field.sc", "features/glossy.sc",
                              "showcase.sc"})
        expect_matches_reference(kScenes / scene, reference_name(kScenes / scene) + "__spp16", 1, 16);
}

// The comparison itself must catch real changes: lighting switched off, and (subtler) the
// mirrors of the reflection scene losing their reflections.
TEST(SceneImages, TheComparisonCatchesAChangedPicture) {
    auto render_scene = [](const char* file, RenderMode mode, int max_depth) {
        const LoadResult loaded = load_scene((kScenes / "features" / file).string());
        EXPECT_TRUE(loaded.ok());
        RenderJob options;
        options.width = kWidth;
        options.height = kHeight;
        options.integrator.mode = mode;
        options.integrator.max_depth = max_depth;
        Image image(kWidth, kHeight);
        if (loaded.ok()) render(*loaded.scene, options, image);
        return image;
    };
    auto caught = [](const Difference& d) {
        return d.mean > kMaxMeanError || d.outlier_fraction > kMaxOutlierFraction;
    };
    const Difference unlit = compare(render_scene("shapes.sc", RenderMode::Whitted, 5),
                                     render_scene("shapes.sc", RenderMode::Raycast, 5));
    EXPECT_TRUE(caught(unlit)) << "mean " << unlit.mean;
    const Difference no_mirrors = compare(render_scene("reflection.sc", RenderMode::Whitted, 5),
                                          render_scene("reflection.sc", RenderMode::Whitted, 0));
    EXPECT_TRUE(caught(no_mirrors)) << "mean " << no_mirrors.mean;
    // And a render compared with itself is no change at all.
    const Image a = render_scene("refraction.sc", RenderMode::Whitted, 5);
    EXPECT_EQ(compare(a, a).worst, 0);
}

}  // namespace
}  // namespace whitted
