// Where photons start (integrator/photon_emitter.h): emissive shapes and meshes emit their flux
// emit · area · π (per side), conserved through a glass slab onto a floor; photons aimed at the
// objects with a delta lobe carry the same expected flux as photons sent everywhere, and far more
// of them meet such an object.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "integrator/caustic_integrator.h"
#include "integrator/path_integrator.h"
#include "integrator/path_test_support.h"
#include "integrator/photon_emitter.h"
#include "sampler/warp.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

Material glass() {
    Material m;
    m.diffuse = glm::vec3(0.0f);
    m.transparent = glm::vec3(1.0f);
    m.ior = 1.5f;
    return m;
}

Material white(float albedo) {
    Material m;
    m.diffuse = glm::vec3(albedo);
    return m;
}

// The unit square of the plane y = 0, two triangles.
TriangleMesh unit_quad() {
    TriangleMesh m;
    m.positions = {{-0.5f, 0, -0.5f}, {0.5f, 0, -0.5f}, {0.5f, 0, 0.5f}, {-0.5f, 0, 0.5f}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}};
    return m;
}

// Photons traced for one sample index, at most `bounces` surfaces deep.
std::unique_ptr<CausticIntegrator> photon_pass(const Scene& scene, int photons, int bounces, bool aim = true) {
    CausticSettings c;
    c.max_bounces = bounces;
    c.photons_per_sample = photons;
    c.aim = aim;
    auto integrator = std::make_unique<CausticIntegrator>(scene, scene.data.camera, c);
    SampleRange range;
    range.begin = 0;
    range.end = 1;
    range.threads = 2;
    EXPECT_TRUE(integrator->prepare(range));
    return integrator;
}

// The solid angle of a square of half-side a seen from height h over its centre: four times that of
// an a × a rectangle seen from over its corner, atan(a² / (h √(2a² + h²))).
double square_solid_angle(double a, double h) { return 4 * std::atan(a * a / (h * std::sqrt(2 * a * a + h * h))); }

TEST(PhotonEmitter, EmissiveSphereAndMeshFluxPassesAGlassSlabToTheFloor) {
    // A glass slab (ior 1.5, passing everything, top at y = 1.2) 4000 wide over a floor twice as
    // wide; an emitter of radiance L above it. A photon meets the slab first (so it counts), crosses
    // it (the (η_from/η_to)² factors cancel) and lands on the floor; one going up meets nothing.
    const double L = 2.0, h = 3.0 - 1.2, A = 2000;
    const int photons = 200000;
    struct Case {
        bool mesh;
        double expected;  // flux onto the floor
        double p;         // the share of photons that land there
    };
    // A sphere of radius 0.5 is, seen from outside, a point of intensity π L a² in every direction
    // (its visible cap's irradiance is π L sin²α cos θ exactly): through the square, π L a² Ω.
    // A 0.8 × 0.6 quad facing down (emitting from both sides): π L A_quad downward, all but
    // h²/(h² + 2000²) < 1e-6 of it through the square; half of its photons go up.
    const double omega = square_solid_angle(A, h);
    for (const Case c : {Case{false, kPi * L * 0.25 * omega, omega / (4 * kPi)},
                         Case{true, kPi * L * 0.48 * (1 - h * h / (h * h + A * A)), 0.5}}) {
        SCOPED_TRACE(c.mesh ? "mesh quad" : "sphere");
        SceneData flat;
        flat.materials = {glass(), white(0.8f), test::emitter(glm::vec3(float(L)))};
        flat.instances.push_back(make_instance(test::translate_scale({0, 1, 0}, {4000, 0.4f, 4000}), ShapeKind::Cube, 0));
        flat.instances.push_back(make_instance(test::translate_scale({0, -0.5f, 0}, {8000, 1, 8000}), ShapeKind::Cube, 1));
        if (c.mesh) {
            Instance quad = make_instance(test::translate_scale({0, 3, 0}, {0.8f, 1, 0.6f}), ShapeKind::Mesh, 2);
            quad.mesh = 0;
            flat.instances.push_back(quad);
            flat.meshes.push_back(unit_quad());
        } else {
            flat.instances.push_back(make_instance(test::translate_scale({0, 3, 0}, glm::vec3(1)), ShapeKind::Sphere, 2));
        }
        const Scene scene = accelerate(flat);
        ASSERT_TRUE(scene_has_caustic_paths(scene.data));
        const auto caustic = photon_pass(scene, photons, 3);
        ASSERT_EQ(caustic->last_pass().emitted, std::size_t(photons));
        double total = 0;
        for (const Photon& ph : caustic->photon_map().photons()) {
            EXPECT_NEAR(ph.position.y, 0.0, 1e-3);
            total += ph.power.x;
        }
        // Every photon carries the emitter's whole flux (π L area, per side emitted): the estimate
        // is that times a binomial share, within 4 of its standard errors.
        const double se = c.expected / c.p * std::sqrt(c.p * (1 - c.p) / photons);
        EXPECT_NEAR(total / photons, c.expected, 4 * se);
        EXPECT_LT(4 * se, 0.02 * c.expected);
    }
}

TEST(PhotonEmitter, AStretchedSphereEmitsEmitTimesItsAreaTimesPi) {
    // An oblate spheroid (semi-axes 0.5, 0.2, 0.5: a unit sphere scaled 1, 0.4, 1) of radiance L:
    // its photons' mean flux is π L · area, area = 2π a² (1 + (1 − e²)/e · atanh e), e² = 1 − c²/a².
    SceneData flat;
    const float L = 1.5f;
    flat.materials = {test::emitter(glm::vec3(L))};
    flat.instances.push_back(make_instance(test::translate_scale({1, 2, 3}, {1, 0.4f, 1}), ShapeKind::Sphere, 0));
    const Scene scene = accelerate(flat);
    const PhotonEmitter emitter(scene);
    ASSERT_FALSE(emitter.empty());
    const double a = 0.5, c = 0.2, e = std::sqrt(1 - c * c / (a * a));
    const double area = 2 * kPi * a * a * (1 + (1 - e * e) / e * std::atanh(e));
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uni(0.0f, 1.0f);
    std::vector<double> power;
    for (int i = 0; i < 100000; ++i) {
        EmissionNumbers u;
        u.light = uni(rng), u.point = {uni(rng), uni(rng)}, u.dir = {uni(rng), uni(rng)};
        const EmittedPhoton p = emitter.emit(u);
        // Outward: it starts on the surface and leaves it.
        const glm::vec3 q = (p.ray.origin - glm::vec3(1, 2, 3)) / glm::vec3(0.5f, 0.2f, 0.5f);
        EXPECT_NEAR(glm::length(q), 1.0, 1e-2);  // just off it
        EXPECT_GT(glm::dot(p.ray.direction, q / glm::vec3(0.5f, 0.2f, 0.5f)), 0.0f);
        power.push_back(p.power.x);
    }
    double s = 0, s2 = 0;
    for (double x : power) s += x, s2 += x * x;
    const double n = double(power.size()), mean = s / n, se = std::sqrt((s2 / n - mean * mean) / n);
    EXPECT_NEAR(mean, kPi * L * area, 4 * se + 1e-6 * mean);
    EXPECT_GT(se, 0.0);  // the density varies over a stretched sphere: not a constant by construction
}

// A point light at (0, 10, 0) over a glass ball of radius 1 at the origin and a floor at y = −4.
Scene point_over_ball() {
    return test::SceneBuilder()
        .light(test::point_light({0, 10, 0}, glm::vec3(1), {0, 0, 1}))
        .add(ShapeKind::Sphere, test::translate_scale({0, 0, 0}, glm::vec3(2)), glass())
        .add(ShapeKind::Cube, test::translate_scale({0, -4.5f, 0}, {60, 1, 60}), white(0.8f))
        .build();
}

// The flux the photons leave on the floor per emitted photon, its standard error (every stored
// photon carries the same flux here: a binomial count), and the share that met the ball first.
struct FloorFlux {
    double flux, se, reached;
};
FloorFlux floor_flux(const Scene& scene, int photons, bool aim) {
    const auto caustic = photon_pass(scene, photons, 3, aim);
    const auto& stored = caustic->photon_map().photons();
    double total = 0;
    for (const Photon& ph : stored) total += ph.power.x;
    const double k = double(stored.size()), n = double(photons);
    const double each = k > 0 ? total / k : 0.0;
    for (const Photon& ph : stored) EXPECT_NEAR(ph.power.x, each, 1e-3 * each);
    return {total / n, each * std::sqrt(k * (1 - k / n)) / n, double(caustic->last_pass().reached) / n};
}

TEST(PhotonEmitter, AimedPhotonsCarryTheSameFluxAndFarFewerAreWasted) {
    const Scene scene = point_over_ball();
    const PhotonEmitter emitter(scene);
    // The ball's bounding sphere: the box [−1, 1]³'s, radius √3.
    ASSERT_EQ(emitter.targets().size(), 1u);
    const float bound = emitter.targets()[0].radius;
    EXPECT_NEAR(bound, std::sqrt(3.0f), 1e-3f);
    const int n_uniform = 2000000, n_aimed = 200000;
    const FloorFlux uniform = floor_flux(scene, n_uniform, false), aimed = floor_flux(scene, n_aimed, true);
    // Meeting the ball first: over the sphere, its cone's share (1 − cos α)/2, sin α = 1/10; aimed,
    // the ball's cone's share of the bounding sphere's cone. Binomial, within 4 standard errors.
    auto one_minus_cos = [](double sin2) { return sin2 / (1 + std::sqrt(1 - sin2)); };
    const double p_uniform = one_minus_cos(0.01) / 2;
    const double p_aimed = one_minus_cos(0.01) / one_minus_cos(double(bound) * bound / 100);
    EXPECT_NEAR(uniform.reached, p_uniform, 4 * std::sqrt(p_uniform * (1 - p_uniform) / n_uniform));
    EXPECT_NEAR(aimed.reached, p_aimed, 4 * std::sqrt(p_aimed * (1 - p_aimed) / n_aimed));
    EXPECT_GT(aimed.reached / uniform.reached, 100.0);  // 132 expected
    // The same expected flux on the floor: the two estimates within 4 standard errors of their difference.
    EXPECT_NEAR(aimed.flux, uniform.flux, 4 * std::hypot(aimed.se, uniform.se));
    EXPECT_LT(aimed.se, 0.5 * uniform.se);  // a tenth of the photons, and half the error (0.22 expected)
}

TEST(PhotonEmitter, AnEmittersCausticIsCountedOnceAsThePathTracerAloneFindsIt) {
    // An emissive sphere (radius 0.5, radiance 10) 4 above a glass ball (radius 1) over a floor at
    // y = −2, under and beside the ball. The path tracer alone finds the light through the ball by
    // chance (unbiased); with photons, it leaves those paths out and the photons carry them. The two
    // estimates of the floor's radiance agree within 4 standard errors (plus 2% for the photon
    // estimate's bias at radius 0.05, where the caustic is 0.3 wide); counted twice, they would be
    // twice it. Under the ball the path tracer's part (the floor sees the emitter only through it) is 0.
    SceneData flat;
    flat.materials = {glass(), white(0.8f), test::emitter(glm::vec3(10.0f))};
    flat.instances.push_back(make_instance(test::translate_scale({0, 0, 0}, glm::vec3(2)), ShapeKind::Sphere, 0));
    flat.instances.push_back(make_instance(test::translate_scale({0, -2.5f, 0}, {60, 1, 60}), ShapeKind::Cube, 1));
    flat.instances.push_back(make_instance(test::translate_scale({0, 4, 0}, glm::vec3(1)), ShapeKind::Sphere, 2));
    flat.background = glm::vec3(0.0f);
    const Scene scene = accelerate(flat);
    ASSERT_TRUE(scene_has_caustic_paths(scene.data));
    const PathIntegrator alone(scene, scene.data.camera, 8);
    PathIntegrator rest(scene, scene.data.camera, 8);
    rest.leave_emitter_caustics_to_photons(true);
    CausticSettings c;
    c.max_bounces = 8;
    c.photons_per_sample = 1 << 16;
    c.radius = 0.05f;
    const int samples = 64;
    CausticIntegrator caustic(scene, scene.data.camera, c);
    SampleRange range;
    range.begin = 0;
    range.end = samples;
    range.threads = 2;
    ASSERT_TRUE(caustic.prepare(range));
    const Sampler few(1, samples);
    RayCounts counts;
    std::uint32_t pixel = 0;
    for (const float x : {0.0f, 0.25f, 2.5f}) {
        SCOPED_TRACE(x);
        const Ray down{{x, -1.5f, 0.1f}, {0, -1, 0}};
        const test::Stats want = test::stats_of(test::samples_of(alone, down, 20000, ++pixel));
        std::vector<double> split, path_part;
        for (int i = 0; i < samples; ++i) {
            const SampleKey key{pixel, 0, std::uint32_t(i)};
            const double p = rest.radiance(down, key, few, counts).x;
            path_part.push_back(p);
            split.push_back(p + caustic.caustic(down, key, few, counts).x);
        }
        const test::Stats got = test::stats_of(split), part = test::stats_of(path_part);
        EXPECT_NEAR(got.mean, want.mean, 4 * std::hypot(got.se, want.se) + 0.02 * want.mean);
        if (x < 1.0f) {
            EXPECT_GT(want.mean, 0.1);
            EXPECT_EQ(part.mean, 0.0);  // the caustic is the photons'
        }
    }
}

}  // namespace
}  // namespace whitted
