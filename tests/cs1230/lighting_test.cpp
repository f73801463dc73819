// The course's lighting model (scene-format.md §9.5) on small JSON scenes, each term against a
// value worked out by hand from the formulas (the numbers in the comments), not from the code.
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "cs1230/cs1230_test_support.h"
#include "render/renderer.h"

namespace whitted {
namespace {

using test::expect_vec_near;
using test::json_scene;
using test::light_group;
using test::load_json;
using test::primitive_group;
using test::trace;

Ray down_z(float x, float y) { return Ray{{x, y, 5}, {0, 0, -1}}; }

std::shared_ptr<const Scene> load_ok(const std::string& text, cs1230::Stage stage = cs1230::Stage::Illuminate) {
    LoadResult r = load_json(text, "/nonexistent/scenes/test.json", stage);
    EXPECT_TRUE(r.ok()) << test::diagnostics_text(r);
    return r.scene;
}

const std::string kUnitCube = R"("type": "cube")";

TEST(Cs1230Lighting, AmbientIsKaTimesOaOnceWhateverTheLights) {
    // ka 0.5 · Oa (0.4, 0.2, 0.6) = (0.2, 0.1, 0.3); the lights add nothing to it (Od = 0).
    const auto scene = load_ok(json_scene(
        light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [0, 0, -1])") + "," +
        light_group(R"("type": "point", "color": [1, 1, 1], "attenuationCoeff": [1, 0, 0])", R"("translate": [0, 0, 3], )") +
        "," + primitive_group(kUnitCube + R"(, "ambient": [0.4, 0.2, 0.6], "diffuse": [0, 0, 0])")));
    const auto t = trace(*scene, down_z(0, 0));
    expect_vec_near(t.color(), {0.2f, 0.1f, 0.3f});
    // Written as the course writes bytes: ⌊255·c⌋ = 51, 25, 76 (rounding would give 26 and 77).
    expect_vec_near(t.written, glm::vec3(51, 25, 76) / 255.0f, 1e-7f);
}

TEST(Cs1230Lighting, DiffuseIsKdOdTimesTheLightTimesTheCosineSummedOverLights) {
    // kd 0.8, Od (1, 0.5, 0.25); N = +z. Light 1 white from L = (0, 1, 1)/√2: N·L = 0.7071068,
    // 0.8·Od·0.7071068 = (0.5656854, 0.2828427, 0.1414214). Light 2 (0.25, 0.5, 0.75) head-on:
    // 0.8·Od·(0.25, 0.5, 0.75) = (0.2, 0.2, 0.15). Sum (0.7656854, 0.4828427, 0.2914214).
    const auto scene = load_ok(json_scene(
        light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [0, -1, -1])") + "," +
            light_group(R"("type": "directional", "color": [0.25, 0.5, 0.75], "direction": [0, 0, -1])") + "," +
            primitive_group(kUnitCube + R"(, "diffuse": [1, 0.5, 0.25])"),
        0.0f, 0.8f, 0.5f));
    const auto t = trace(*scene, down_z(0, 0));
    expect_vec_near(t.color(), {0.7656854f, 0.4828427f, 0.2914214f});
    ASSERT_EQ(t.hit().lights.size(), 2u);
    expect_vec_near(t.hit().lights[0].diffuse, {0.5656854f, 0.2828427f, 0.1414214f});
}

TEST(Cs1230Lighting, SpecularIsKsOsTimesCosinePowerNAndNoneAtShininessZero) {
    // Sphere (radius 0.5) hit at (0, 0, 0.5): N = V = +z. L = (0, 0.6, 0.8), R = 2(N·L)N − L =
    // (0, −0.6, 0.8), R·V = 0.8, n = 2: 0.64. ks 0.5 · Os (0.4, 0.8, 1) · 0.64 = (0.128, 0.256, 0.32).
    const std::string light = light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [0, -0.6, -0.8])");
    const auto shiny = load_ok(json_scene(
        light + "," + primitive_group(R"("type": "sphere", "diffuse": [0, 0, 0], "specular": [0.4, 0.8, 1], "shininess": 2)"),
        0.0f, 0.0f, 0.5f));
    expect_vec_near(trace(*shiny, down_z(0, 0)).color(), {0.128f, 0.256f, 0.32f});
    // The same at shininess 0 (the default): the course draws no highlight, not (R·V)⁰ = 1.
    const auto flat = load_ok(json_scene(
        light + "," + primitive_group(R"("type": "sphere", "diffuse": [0, 0, 0], "specular": [0.4, 0.8, 1])"), 0.0f, 0.0f,
        0.5f));
    expect_vec_near(trace(*flat, down_z(0, 0)).color(), {0, 0, 0});
}

TEST(Cs1230Lighting, HighlightOfALightBehindTheSurfaceShowsWithoutShadowsOnly) {
    // The highlight term has no N·L test. Light behind the sphere, L = (0, 0, −1); hit at
    // (0.4, 0, 0.3), N = (0.8, 0, 0.6): N·L = −0.6 (no diffuse), R = 2(N·L)N − L = (−0.96, 0, 0.28),
    // R·V = 0.28, n = 1: ks 0.5 · Os 1 · 0.28 = 0.14. With shadows, the shadow ray from
    // P + 0.001·L starts inside the sphere and meets its far side: nothing.
    const std::string text = json_scene(
        light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [0, 0, 1])") + "," +
            primitive_group(R"("type": "sphere", "specular": [1, 1, 1], "shininess": 1)"),
        0.0f, 0.5f, 0.5f);
    const auto scene = load_ok(text);
    expect_vec_near(trace(*scene, down_z(0.4f, 0), 4, cs1230::Stage::Intersect).color(), glm::vec3(0.14f), 1e-4f);
    expect_vec_near(trace(*scene, down_z(0.4f, 0)).color(), glm::vec3(0.0f));
}

TEST(Cs1230Lighting, PointLightAttenuationIsOneOverTheFalloffCappedAtOne) {
    // Light at (0, 0, 3), hit (0, 0, 0.5): d = 2.5, N·L = 1; kd 1 · Od 0.5 = 0.5 before attenuation.
    auto lit = [](const char* coefficients) {
        const auto scene = load_ok(json_scene(
            light_group(std::string(R"("type": "point", "color": [1, 1, 1], "attenuationCoeff": )") + coefficients,
                        R"("translate": [0, 0, 3], )") +
                "," + primitive_group(kUnitCube + R"(, "diffuse": [0.5, 0.5, 0.5])"),
            0.0f, 1.0f, 0.0f));
        return trace(*scene, down_z(0, 0)).color().x;
    };
    EXPECT_NEAR(lit("[0, 0.5, 0]"), 0.5f / 1.25f, 1e-6f);                         // 1/(0.5·2.5) = 0.8
    EXPECT_NEAR(lit("[1, 0.1, 0.02]"), 0.5f / (1 + 0.25f + 0.125f), 1e-6f);        // 1/1.375
    EXPECT_NEAR(lit("[0.25, 0, 0]"), 0.5f, 1e-6f);                                // 1/0.25 = 4: capped at 1
}

TEST(Cs1230Lighting, SpotLightIsFullInsideThePenumbraSmoothAcrossItDarkOutside) {
    // Spot at (0, 0, 3) pointing −z, angle 30, penumbra 20 (inner cone 10°). Floor face z = 0.5
    // hit at (x, 0, 0.5) with x = 2.5·tan θ; N·L = cos θ; kd 1 · Od 0.5.
    // θ = 5°: S = 1; 15°: r = 0.25, S = 1 − (3r² − 2r³) = 0.84375; 20°: r = 0.5, S = 0.5; 35°: 0.
    const auto scene = load_ok(json_scene(
        light_group(R"("type": "spot", "color": [1, 1, 1], "direction": [0, 0, -1], "angle": 30, "penumbra": 20,
                     "attenuationCoeff": [1, 0, 0])",
                    R"("translate": [0, 0, 3], )") +
            "," + primitive_group(kUnitCube + R"(, "diffuse": [0.5, 0.5, 0.5])", R"("scale": [20, 20, 1], )"),
        0.0f, 1.0f, 0.0f));
    auto at = [&](float degrees) {
        const float theta = degrees * std::numbers::pi_v<float> / 180.0f;
        return trace(*scene, down_z(2.5f * std::tan(theta), 0)).color().x;
    };
    const float deg = std::numbers::pi_v<float> / 180.0f;
    EXPECT_NEAR(at(5), 0.5f * std::cos(5 * deg), 1e-5f);
    EXPECT_NEAR(at(15), 0.5f * 0.84375f * std::cos(15 * deg), 1e-4f);
    EXPECT_NEAR(at(20), 0.5f * 0.5f * std::cos(20 * deg), 1e-4f);
    EXPECT_NEAR(at(35), 0.0f, 1e-7f);
}

TEST(Cs1230Lighting, ShadowRaysFindEveryObjectOpaqueAndStopAtTheLight) {
    // Floor top y = 0 hit at the origin from the side (the ray passes below the blocker): ka 0.5 ·
    // Oa 0.2 = 0.1; lit, kd 0.5 · Od 1 · N·L 1 = 0.5 more.
    const std::string floor = primitive_group(kUnitCube + R"(, "ambient": [0.2, 0.2, 0.2])",
                                              R"("translate": [0, -0.5, 0], "scale": [10, 1, 10], )");
    // A glass cube above the point: opaque to shadow rays all the same.
    const std::string glass = primitive_group(kUnitCube + R"(, "transparent": [1, 1, 1], "ior": 1.5)",
                                              R"("translate": [0, 2, 0], )");
    const Ray ray{{3, 3, 0}, {-1, -1, 0}};
    const std::string sun = light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [0, -1, 0])");
    EXPECT_NEAR(trace(*load_ok(json_scene(sun + "," + floor, 0.5f, 0.5f, 0.5f, 1.0f)), ray).color().x, 0.6f, 1e-6f);
    EXPECT_NEAR(trace(*load_ok(json_scene(sun + "," + floor + "," + glass, 0.5f, 0.5f, 0.5f, 1.0f)), ray).color().x,
                0.1f, 1e-6f);
    // A point light between the point and the blocker: the blocker is beyond it and does not count.
    const std::string bulb = light_group(R"("type": "point", "color": [1, 1, 1], "attenuationCoeff": [1, 0, 0])",
                                         R"("translate": [0, 1, 0], )");
    EXPECT_NEAR(trace(*load_ok(json_scene(bulb + "," + floor + "," + glass, 0.5f, 0.5f, 0.5f, 1.0f)), ray).color().x,
                0.6f, 1e-6f);
}

TEST(Cs1230Lighting, ReflectionAddsKsOrTimesTheMirroredColourClampedAtEachLevel) {
    // A black mirror (Or (1, 0.5, 0.25), ks 0.5: weights 0.5, 0.25, 0.125) facing a cube behind
    // the camera whose colour is ka 0.5 · Oa 3 = 1.5, clamped to 1 before it is weighted.
    const std::string text = json_scene(
        primitive_group(kUnitCube + R"(, "diffuse": [0, 0, 0], "reflective": [1, 0.5, 0.25])") + "," +
            primitive_group(kUnitCube + R"(, "ambient": [3, 3, 3], "diffuse": [0, 0, 0])", R"("translate": [0, 0, 10], )"),
        0.5f, 0.5f, 0.5f);
    const auto scene = load_ok(text);
    const auto t = trace(*scene, down_z(0, 0));
    expect_vec_near(t.color(), {0.5f, 0.25f, 0.125f});
    EXPECT_EQ(t.hit().reflect.outcome, SecondaryRecord::Outcome::Traced);
    // No recursion at depth 0, none in the Intersect stage.
    expect_vec_near(trace(*scene, down_z(0, 0), 0).color(), {0, 0, 0});
    expect_vec_near(trace(*scene, down_z(0, 0), 4, cs1230::Stage::Intersect).color(), {0, 0, 0});
}

TEST(Cs1230Lighting, RefractionWeighsWhatComesThroughTheShapeOnceByKtOt) {
    // A clear sphere (Ot 1, kt 0.5, black itself) before the bright cube (clamped to 1): the ray
    // through its centre goes straight in and out (normal incidence, any ior) and brings 1, weighed
    // once for the shape (0.5), not once per surface crossed.
    for (const char* ior : {"1.0", "1.5"}) {
        const std::string text = json_scene(
            primitive_group(std::string(R"("type": "sphere", "diffuse": [0, 0, 0], "transparent": [1, 1, 1], "ior": )") + ior) +
                "," + primitive_group(kUnitCube + R"(, "ambient": [3, 3, 3], "diffuse": [0, 0, 0])",
                                      R"("translate": [0, 0, -10], )"),
            0.5f, 0.5f, 0.5f, 0.5f);
        const auto t = trace(*load_ok(text), down_z(0, 0));
        expect_vec_near(t.color(), glm::vec3(0.5f));
        EXPECT_EQ(t.hit().refract.outcome, SecondaryRecord::Outcome::Traced) << ior;
    }
}

TEST(Cs1230Lighting, TheIntersectStageHasDirectionalLightsOnlyAndNoShadows) {
    // Floor point under a blocker, lit by the sun (blocked) and a bright point light: Illuminate
    // gives ambient 0.1 + the point light 0.5; Intersect ignores the point light and shadows:
    // 0.1 + the sun's 0.5·(0, 1, 0)·(0, 1, 0) = 0.6.
    const std::string text = json_scene(
        light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [0, -1, 0])") + "," +
            light_group(R"("type": "point", "color": [1, 1, 1], "attenuationCoeff": [1, 0, 0])",
                        R"("translate": [1, 1, 0], )") +
            "," +
            primitive_group(kUnitCube + R"(, "ambient": [0.2, 0.2, 0.2])",
                            R"("translate": [0, -0.5, 0], "scale": [10, 1, 10], )") +
            "," + primitive_group(kUnitCube, R"("translate": [0, 2, 0], )"),
        0.5f, 0.5f, 0.5f);
    const auto scene = load_ok(text);
    const Ray ray{{3, 3, 0}, {-1, -1, 0}};
    // Illuminate: the point light at (1, 1, 0), d = √2, N·L = 1/√2: 0.5·0.7071068 = 0.3535534.
    EXPECT_NEAR(trace(*scene, ray).color().x, 0.1f + 0.3535534f, 1e-6f);
    EXPECT_NEAR(trace(*scene, ray, 4, cs1230::Stage::Intersect).color().x, 0.6f, 1e-6f);
}

TEST(Cs1230Lighting, RenderedBytesAreTruncatedNotRounded) {
    // The ambient scene through the renderer and the film: the bytes the file gets.
    const auto scene = load_ok(json_scene(primitive_group(kUnitCube + R"(, "ambient": [0.4, 0.2, 0.6], "diffuse": [0, 0, 0])")));
    RenderJob job;
    job.width = 1;
    job.height = 1;
    job.threads = 1;
    const auto integrator = make_integrator(*scene, job.camera_for(*scene), job.integrator);
    Film film(1, 1);
    render(*integrator, job, film);
    const Image image = film.to_image();
    EXPECT_EQ(int(image.rgb[0]), 51);  // 255 · 0.2 = 51
    EXPECT_EQ(int(image.rgb[1]), 25);  // 255 · 0.1 = 25.5
    EXPECT_EQ(int(image.rgb[2]), 76);  // 255 · 0.3 = 76.5
}

}  // namespace
}  // namespace whitted
