// The lighting equation of scene-format.md §7 checked against values worked out by hand.
#include <cmath>

#include <gtest/gtest.h>

#include "integrator/light_sample.h"
#include "integrator/whitted_integrator.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

using test::SceneBuilder;
using test::translate_scale;

constexpr float kTol = 1e-4f;

glm::vec3 shade(const Scene& scene, const Ray& ray, int max_depth = 5) {
    RayCounts counts;
    return WhittedIntegrator(scene, scene.data.camera, max_depth).radiance(ray, SampleKey{}, Sampler(), counts);
}

void expect_color(glm::vec3 got, glm::vec3 want, float tol = kTol) {
    EXPECT_NEAR(got.x, want.x, tol);
    EXPECT_NEAR(got.y, want.y, tol);
    EXPECT_NEAR(got.z, want.z, tol);
}

// A big opaque floor whose top face is the plane y = 0.
Material floor_material() {
    Material m;
    m.diffuse = glm::vec3(1.0f);
    m.ambient = glm::vec3(0.1f);
    return m;
}
void add_floor(SceneBuilder& b) { b.add(ShapeKind::Cube, translate_scale({0, -0.5f, 0}, {100, 1, 100}), floor_material()); }
Ray down_at(float x, float z) { return Ray{{x, 20, z}, {0, -1, 0}}; }

TEST(Attenuation, FollowsTheFalloffFunctionUnclamped) {
    EXPECT_FLOAT_EQ(attenuation({1, 0, 0}, 7.0f), 1.0f);
    EXPECT_FLOAT_EQ(attenuation({0, 0, 0.1f}, 2.0f), 1.0f / 0.4f);  // 10/d² = 2.5: brighter than 1
    EXPECT_FLOAT_EQ(attenuation({1, 0.5f, 0.25f}, 2.0f), 1.0f / 3.0f);
    EXPECT_FLOAT_EQ(attenuation({0, 0, 0}, 3.0f), 1.0f);     // denominator 0: att = 1
    EXPECT_FLOAT_EQ(attenuation({-5, 1, 0}, 2.0f), 1.0f);    // denominator < 0: att = 1
    EXPECT_FLOAT_EQ(attenuation({0, 0.2f, 0}, 5.0f), 1.0f);  // 1 / (0.2·5)
}

TEST(WhittedIntegrator, LitSphereUnderAttenuatedPointLightMatchesHandComputation) {
    // Sphere of radius 1 at the origin, seen head-on from +z: hit (0,0,1), N = (0,0,1), V = (0,0,1).
    Material m;
    m.ambient = {0.1f, 0.1f, 0.1f};
    m.diffuse = {0.8f, 0.4f, 0.2f};
    m.specular = {0.5f, 0.5f, 0.5f};
    m.shine = 10;
    SceneBuilder b;
    b.add(ShapeKind::Sphere, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f)), m)
        .light(test::point_light({3, 0, 4}, {1, 1, 1}, {1, 0.5f, 0.1f}));
    Scene scene = b.build();
    // Light at (3,0,4): L = (3,0,3)/√18, N·L = 1/√2, d = √18.
    const float n_dot_l = 1.0f / std::sqrt(2.0f);
    const float d = std::sqrt(18.0f);
    const float att = 1.0f / (1.0f + 0.5f * d + 0.1f * 18.0f);
    // R = 2(N·L)N − L = (−1/√2, 0, 1/√2), so R·V = 1/√2 and the highlight is (1/√2)^10 = 1/32.
    const float spec = 1.0f / 32.0f;
    glm::vec3 want = m.ambient + att * (m.diffuse * n_dot_l + m.specular * spec);
    expect_color(shade(scene, Ray{{0, 0, 5}, {0, 0, -1}}), want);
}

TEST(WhittedIntegrator, GlobalAmbientScalesAmbientAndEmitIsAdded) {
    Material m;
    m.ambient = {0.5f, 0.25f, 1.0f};
    m.diffuse = glm::vec3(0.0f);
    m.emit = {0.1f, 0.2f, 0.3f};
    Scene scene = SceneBuilder().add(ShapeKind::Cube, glm::mat4(1.0f), m).ambient({0.5f, 0.5f, 0.2f}).build();
    expect_color(shade(scene, Ray{{0, 0, 5}, {0, 0, -1}}), {0.1f + 0.25f, 0.2f + 0.125f, 0.3f + 0.2f});
}

TEST(WhittedIntegrator, SpotlightInsideAndOutsideItsCone) {
    Light spot;
    spot.type = LightType::Spot;
    spot.position = {0, 5, 0};
    spot.direction = {0, -1, 0};
    spot.color = {1, 1, 1};
    spot.cos_aperture = std::cos(glm::radians(30.0f));
    spot.exponent = 2;
    SceneBuilder b;
    add_floor(b);
    Scene scene = b.light(spot).build();
    // Straight below: θ = 0, N·L = 1, spot factor 1.
    expect_color(shade(scene, down_at(0, 0)), glm::vec3(0.1f + 1.0f));
    // At x = 2: cos θ = 5/√29 (θ ≈ 21.8° < 30°) is also N·L; the spot factor is cos²θ.
    const float c = 5.0f / std::sqrt(29.0f);
    expect_color(shade(scene, down_at(2, 0)), glm::vec3(0.1f + c * c * c));
    // At x = 4: θ = atan(4/5) ≈ 38.7° > 30°: ambient only.
    expect_color(shade(scene, down_at(4, 0)), glm::vec3(0.1f));
}

TEST(WhittedIntegrator, DirectionalLightHasNoAttenuation) {
    Light sun;
    sun.type = LightType::Directional;
    sun.direction = glm::normalize(glm::vec3(1, -1, 0));  // travels down at 45°
    sun.color = {0.5f, 0.5f, 0.5f};
    SceneBuilder b;
    add_floor(b);
    Scene scene = b.light(sun).build();
    const float n_dot_l = std::sqrt(0.5f);
    expect_color(shade(scene, down_at(0, 0)), glm::vec3(0.1f + 0.5f * n_dot_l));
    expect_color(shade(scene, down_at(30, 0)), glm::vec3(0.1f + 0.5f * n_dot_l));
}

TEST(WhittedIntegrator, OpaqueOccluderCastsAShadow) {
    SceneBuilder b;
    add_floor(b);
    b.add(ShapeKind::Sphere, translate_scale({0, 3, 0}, glm::vec3(1.0f)), Material{})
        .light(test::point_light({0, 6, 0}, {1, 1, 1}));
    Scene scene = b.build();
    expect_color(shade(scene, Ray{{0.0f, 2.0f, 3.0f}, glm::normalize(glm::vec3(0, -2, -3))}), glm::vec3(0.1f));
    // Away from the shadow the floor is lit: at (5,0,0), N·L = 6/√61, no attenuation.
    expect_color(shade(scene, down_at(5, 0)), glm::vec3(0.1f + 6.0f / std::sqrt(61.0f)));
}

TEST(WhittedIntegrator, TransparentOccluderTintsTheShadowOncePerSurfaceCrossed) {
    Material glass;
    glass.diffuse = glm::vec3(0.0f);
    glass.transparent = {0.5f, 0.8f, 1.0f};
    SceneBuilder b;
    add_floor(b);
    b.add(ShapeKind::Sphere, translate_scale({0, 3, 0}, glm::vec3(1.0f)), glass).light(test::point_light({0, 6, 0}, {1, 1, 1}));
    Scene scene = b.build();
    // Seen from the side (not through the sphere): the shadow ray crosses the sphere twice.
    glm::vec3 tint = glass.transparent * glass.transparent;
    expect_color(shade(scene, Ray{{0.0f, 1.0f, 5.0f}, glm::normalize(glm::vec3(0, -1, -5))}), 0.1f + tint);
}

TEST(WhittedIntegrator, LightsBeyondAPointLightDoNotShadow) {
    SceneBuilder b;
    add_floor(b);
    // The blocker is above the light: not between the floor and the light.
    b.add(ShapeKind::Cube, translate_scale({0, 8, 0}, glm::vec3(4.0f)), Material{}).light(test::point_light({0, 5, 0}, {1, 1, 1}));
    expect_color(shade(b.build(), Ray{{3, 1, 0}, glm::normalize(glm::vec3(-3, -1, 0))}), glm::vec3(1.1f));
}

TEST(WhittedIntegrator, MirrorReflectsWhatIsBehindTheViewer) {
    Material mirror;
    mirror.diffuse = glm::vec3(0.0f);
    mirror.reflect = {0.8f, 0.8f, 0.8f};
    SceneBuilder b;
    b.add(ShapeKind::Cube, translate_scale({0, 0, -0.5f}, {10, 10, 1}), mirror)          // face at z = 0
        .add(ShapeKind::Sphere, translate_scale({0, 0, 10}, glm::vec3(2.0f)), test::emitter({1, 0, 0}));
    Scene scene = b.build();
    expect_color(shade(scene, Ray{{0, 0, 5}, {0, 0, -1}}), {0.8f, 0, 0});
    expect_color(shade(scene, Ray{{0, 0, 5}, {0, 0, -1}}, 0), {0, 0, 0});  // depth limit 0: no reflection
}

TEST(WhittedIntegrator, SlabRefractsBySnellsLaw) {
    // A glass slab 1 thick (z in [-1, 0]), ior 1.5, entered at 30°: inside, sin r = sin 30° / 1.5;
    // it leaves parallel to the incoming ray, shifted sideways by sin(i − r)/cos r.
    Material glass;
    glass.diffuse = glm::vec3(0.0f);
    glass.transparent = {1, 1, 1};
    glass.ior = 1.5f;
    const float i = glm::radians(30.0f), r = std::asin(std::sin(i) / 1.5f);
    const glm::vec3 dir(std::sin(i), 0, -std::cos(i));
    const glm::vec3 entry(0, 0, 0);
    const glm::vec3 exit = entry + glm::vec3(std::tan(r), 0, -1);  // through the slab along the refracted ray
    const glm::vec3 on_refracted = exit + 5.0f * dir;               // 5 further, parallel again
    const glm::vec3 on_straight = entry + (5.0f + 1.0f / std::cos(i)) * dir;  // where an unbent ray would go
    ASSERT_GT(glm::length(on_refracted - on_straight), 0.15f);
    SceneBuilder b;
    b.add(ShapeKind::Cube, translate_scale({0, 0, -0.5f}, {20, 20, 1}), glass)
        .add(ShapeKind::Sphere, translate_scale(on_refracted, glm::vec3(0.1f)), test::emitter({0, 1, 0}))
        .add(ShapeKind::Sphere, translate_scale(on_straight, glm::vec3(0.1f)), test::emitter({1, 0, 0}));
    Scene scene = b.build();
    expect_color(shade(scene, Ray{entry - 3.0f * dir, dir}), {0, 1, 0});
}

TEST(WhittedIntegrator, AThickSlabShowsTheRefractionAngleExactly) {
    // The same 30° entry into glass of ior 1.5 (sin r = 1/3, tan r = 1/√8 = 0.35355), through a
    // slab 10 thick (z in [-10, 0]): the ray leaves 10 tan r = 3.5355 to the side of its entry and
    // goes on parallel to where it came from. A target of radius 0.02 there is hit only if r is
    // right to within about 0.1°: through 1 unit of glass (the test above) an angle 0.6° off still
    // hit its target.
    Material glass;
    glass.diffuse = glm::vec3(0.0f);
    glass.transparent = {1, 1, 1};
    glass.ior = 1.5f;
    const float i = glm::radians(30.0f);
    const glm::vec3 dir(std::sin(i), 0, -std::cos(i));
    const glm::vec3 exit(10.0f / std::sqrt(8.0f), 0, -10);
    SceneBuilder b;
    b.add(ShapeKind::Cube, translate_scale({0, 0, -5}, {40, 40, 10}), glass)
        .add(ShapeKind::Sphere, translate_scale(exit + 2.0f * dir, glm::vec3(0.04f)), test::emitter({0, 1, 0}));
    Scene scene = b.build();
    expect_color(shade(scene, Ray{-3.0f * dir, dir}), {0, 1, 0});
}

TEST(WhittedIntegrator, TotalInternalReflectionSendsOneRayWeightedReflectPlusTransparent) {
    // From inside a glass slab (faces z = ±5) a ray meets z = −5 at 60° from the normal, past the
    // critical angle asin(1/1.5) ≈ 41.8°: one mirror ray with weight reflect + transparent.
    Material glass;
    glass.diffuse = glm::vec3(0.0f);
    glass.emit = {0.1f, 0.1f, 0.1f};
    glass.reflect = {0.2f, 0.2f, 0.2f};
    glass.transparent = {0.7f, 0.7f, 0.7f};
    glass.ior = 1.5f;
    Scene scene = SceneBuilder().add(ShapeKind::Cube, glm::scale(glm::mat4(1.0f), {1000, 1000, 10}), glass).build();
    const Ray ray{{0, 0, 0}, {std::sin(glm::radians(60.0f)), 0, -0.5f}};
    // Depth limit 1: the camera ray's hit (depth 0) spawns one ray (depth 1) that hits z = +5 and
    // stops there, adding only that surface's emit.
    expect_color(shade(scene, ray, 1), glm::vec3(0.1f + 0.9f * 0.1f));
}

TEST(WhittedIntegrator, RecursionLimitAndWeightCutOff) {
    // Between two facing mirrors that glow 0.1 and reflect 0.5, a ray of limit L collects
    // 0.1·(1 + 0.5 + … + 0.5^L) — until the weight 0.5^k drops below 1/256 (k = 9).
    Material m;
    m.diffuse = glm::vec3(0.0f);
    m.emit = glm::vec3(0.1f);
    m.reflect = glm::vec3(0.5f);
    SceneBuilder b;
    b.add(ShapeKind::Cube, translate_scale({0, 0, -5}, {100, 100, 1}), m)
        .add(ShapeKind::Cube, translate_scale({0, 0, 5}, {100, 100, 1}), m);
    Scene scene = b.build();
    auto expected = [](int bounces) {
        float sum = 0, w = 1;
        for (int k = 0; k <= bounces; ++k, w *= 0.5f) sum += 0.1f * w;
        return sum;
    };
    const Ray ray{{0, 0, 0}, {0, 0, -1}};
    for (int limit : {0, 1, 2, 5, 8}) expect_color(shade(scene, ray, limit), glm::vec3(expected(limit)));
    expect_color(shade(scene, ray, 20), glm::vec3(expected(8)));  // 0.5^9 < 1/256: not traced
    EXPECT_NE(shade(scene, ray, 2).x, shade(scene, ray, 3).x);
}

TEST(WhittedIntegrator, MissGivesTheBackground) {
    Scene scene = SceneBuilder().background({0.2f, 0.3f, 0.4f}).build();
    expect_color(shade(scene, Ray{{0, 0, 0}, {0, 0, -1}}), {0.2f, 0.3f, 0.4f});
}

TEST(WhittedIntegrator, SurfaceSeenFromInsideIsLitThroughItsOwnGlass) {
    // A point light inside a glass sphere lights the inner surface; the shadow ray never leaves.
    Material glass;
    glass.diffuse = glm::vec3(0.5f);
    glass.transparent = glm::vec3(0.5f);
    glass.ior = 1.0f;
    Scene scene = SceneBuilder()
                      .add(ShapeKind::Sphere, glm::scale(glm::mat4(1.0f), glm::vec3(4.0f)), glass)
                      .light(test::point_light({0, 0, 0}, {1, 1, 1}))
                      .build();
    // From the centre looking out: hit at distance 2, the flipped normal faces the centre, N·L = 1,
    // nothing shadows it (limit 0 keeps the refracted ray out of the sum).
    expect_color(shade(scene, Ray{{0, 0, 0}, {0, 0, -1}}, 0), glm::vec3(0.5f));
}

}  // namespace
}  // namespace whitted
