// The path tracer (scene-format.md §9.2) against closed forms: the furnace, the Whitted diffuse term
// at one bounce, the irradiance under a spherical emitter; its sampling densities (area lights
// integrate to 1 under any affine map, the BSDF's samples follow its pdf by a chi-square test).
// Tolerances come from the sample counts (standard errors measured from the samples themselves).
#include <cmath>
#include <vector>
#include <string>

#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "integrator/bsdf.h"
#include "integrator/path_integrator.h"
#include "integrator/path_lights.h"
#include "integrator/path_test_support.h"
#include "integrator/whitted_integrator.h"
#include "render/renderer.h"
#include "sampler/warp.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

using test::samples_of;
using test::Stats;
using test::stats_of;

// The camera inside a closed emitting, reflecting surface sees e / (1 − a) everywhere, whatever its shape.
void expect_furnace(const glm::vec3& scale) {
    const float e = 0.4f, a = 0.6f;  // L = 0.4 / 0.4 = 1
    test::SceneBuilder b;
    Material m;
    m.diffuse = glm::vec3(a);
    m.emit = glm::vec3(e);
    b.add(ShapeKind::Sphere, test::translate_scale({0.3f, -0.2f, 0.1f}, scale), m);
    const Scene scene = b.build();
    SCOPED_TRACE("scale " + std::to_string(scale.x) + " " + std::to_string(scale.y) + " " + std::to_string(scale.z));
    test::expect_furnace_image(scene, e / (1 - a));
}

TEST(PathIntegrator, FurnaceSeesEmitOverOneMinusAlbedoEverywhere) {
    expect_furnace(glm::vec3(20.0f));
    expect_furnace({20.0f, 9.0f, 14.0f});  // an ellipsoid: the area light's pdf goes through the matrix
}

// With one bounce, Lambertian surfaces and point lights only, path tracing is the diffuse term of §7.
TEST(PathIntegrator, OneBounceUnderPointLightsIsTheWhittedDiffuseTerm) {
    auto scene_with = [](int lights) {
        test::SceneBuilder b;
        Material floor, ball, box;
        floor.diffuse = glm::vec3(0.7f, 0.6f, 0.5f);
        ball.diffuse = glm::vec3(0.2f, 0.5f, 0.8f);
        box.diffuse = glm::vec3(0.9f, 0.3f, 0.3f);
        b.add(ShapeKind::Cube, test::translate_scale({0, -0.5f, 0}, {20, 1, 20}), floor);
        b.add(ShapeKind::Sphere, test::translate_scale({-0.8f, 0.6f, -1}, glm::vec3(1.2f)), ball);
        b.add(ShapeKind::Cube, test::translate_scale({1, 0.4f, -0.5f}, glm::vec3(0.8f)), box);
        b.light(test::point_light({2, 3, 2}, glm::vec3(0.6f), {1, 0.1f, 0.02f}));
        if (lights > 1) b.light(test::point_light({-3, 2, 1}, glm::vec3(0.3f, 0.35f, 0.4f)));
        Scene s = b.ambient(glm::vec3(0.0f)).build();
        s.data.camera.eye = {0, 1.5f, 4};
        s.data.camera.forward = glm::normalize(glm::vec3(0, -0.4f, -1));
        s.data.camera.right = glm::normalize(glm::cross(s.data.camera.forward, glm::vec3(0, 1, 0)));
        s.data.camera.up = glm::cross(s.data.camera.right, s.data.camera.forward);
        return s;
    };
    for (int lights : {1, 2}) {
        const Scene scene = scene_with(lights);
        RenderJob job;
        job.width = 40;
        job.height = 30;
        job.sampling.spp = lights == 1 ? 4 : 64;
        auto render_mode = [&](RenderMode mode) {
            job.integrator = {mode, 1};
            const auto integrator = make_integrator(scene, scene.data.camera, job.integrator);
            Film film(job.width, job.height);
            render(*integrator, job, film);
            return film;
        };
        const Film whitted = render_mode(RenderMode::Whitted), path = render_mode(RenderMode::Path);
        std::vector<double> diff;
        for (int y = 0; y < job.height; ++y)
            for (int x = 0; x < job.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    const double d = path.at(x, y).value()[c] - whitted.at(x, y).value()[c];
                    // One light: the same sample positions, the same light, exactly the same terms.
                    if (lights == 1) {
                        ASSERT_NEAR(d, 0.0, 1e-5) << x << "," << y;
                    }
                    diff.push_back(d);
                }
        const Stats s = stats_of(diff);
        EXPECT_NEAR(s.mean, 0.0, 4 * s.se + 1e-7) << lights << " lights";
    }
}

// A Lambertian plane (albedo 1) under a sphere of radiance L: irradiance π·L·sin²α·cos θ, so the
// plane's radiance is L·sin²α·cos θ (α the sphere's angular radius, θ the angle to its centre).
TEST(PathIntegrator, PlaneUnderASphericalEmitterHasTheClosedFormIrradiance) {
    const float r = 0.5f, h = 2.0f, L = 3.0f;
    test::SceneBuilder b;
    Material plane;
    plane.diffuse = glm::vec3(1.0f);
    b.add(ShapeKind::Cube, test::translate_scale({0, -0.5f, 0}, {100, 1, 100}), plane);
    b.add(ShapeKind::Sphere, test::translate_scale({0, h, 0}, glm::vec3(2 * r)), test::emitter(glm::vec3(L)));
    const Scene scene = b.build();
    const PathIntegrator path(scene, scene.data.camera, 1);
    for (float x : {0.0f, 0.8f, 1.5f, 2.5f}) {
        const double D = std::sqrt(double(x) * x + double(h) * h);
        const double want = L * (r / D) * (r / D) * (h / D);
        const Stats s = stats_of(samples_of(path, Ray{{x, 0.5f, 0.0f}, {0, -1, 0}}, 1024));
        EXPECT_NEAR(s.mean, want, 4 * s.se + 1e-4) << "x " << x;
    }
}

// The density sample_area draws points with, turned into a density of directions seen from inside
// the shape, integrates to 1 over the sphere of directions: each direction meets the surface once.
TEST(PathLights, AreaDensityIntegratesToOneUnderNonUniformScale) {
    for (ShapeKind kind : {ShapeKind::Cube, ShapeKind::Sphere, ShapeKind::Cylinder, ShapeKind::Cone, ShapeKind::Ellipsoid}) {
        test::SceneBuilder b;
        const glm::mat4 m = glm::rotate(test::translate_scale({1, 2, 3}, {2.0f, 0.7f, 1.3f}), 0.6f,
                                        glm::normalize(glm::vec3(1, 2, 0.5f)));
        b.add(kind, m, test::emitter(glm::vec3(1.0f)));
        const Scene scene = b.build();
        const PathLights lights(scene);
        const Instance& inst = scene.data.instances[0];
        const glm::vec3 inside = glm::vec3(m * glm::vec4(0, kind == ShapeKind::Cone ? -0.25f : 0.0f, 0, 1));
        const int n = 20000;
        const Sampler sampler(1, n);
        std::vector<double> terms;
        for (int i = 0; i < n; ++i) {
            const glm::vec2 u = sampler.get2d({0, 0, std::uint32_t(i)}, 3);
            const glm::vec3 w = around_axis({0, 0, 1}, 1 - 2 * u.x, u.y);  // uniform over the sphere
            Hit hit;
            ASSERT_TRUE(scene.intersect(Ray{inside, w}, hit)) << shape_name(kind);
            const glm::vec3 p_obj = to_object_space(inst, Ray{inside, w}).at(hit.t);
            const glm::vec3 n_obj = unit_shape_normal(kind, hit.part, p_obj);
            const glm::vec3 n_world = normal_to_world(inst, n_obj);
            const double pdf_w = lights.pdf_area(0, inside, inside + hit.t * w, n_obj) * hit.t * hit.t / std::abs(glm::dot(n_world, w));
            terms.push_back(4 * kPi * pdf_w);
        }
        const Stats s = stats_of(terms);
        EXPECT_NEAR(s.mean, 1.0, 4 * s.se + 1e-3) << shape_name(kind);
        // And the points it samples lie on the surface, where the density says.
        for (int i = 0; i < 64; ++i) {
            const AreaLightSample ls = lights.sample_area(0, inside, sampler.get2d({1, 0, std::uint32_t(i)}, 5));
            const glm::vec3 back = to_object_space(inst, Ray{ls.point, glm::vec3(0)}).origin;
            const auto span = intersect_unit_shape(kind, Ray{back - 0.01f * glm::vec3(1, 1, 1), glm::vec3(1, 1, 1)});
            ASSERT_EQ(span.count, 2) << shape_name(kind);
            EXPECT_NEAR(std::min(std::abs(span.t[0] - 0.01f), std::abs(span.t[1] - 0.01f)), 0.0f, 1e-4f);
        }
        // The world area: the density's reciprocal summed over the shape, and PathLights' quadrature.
        EXPECT_GT(PathLights::world_area(inst), 0.0f);
    }
}

// The ellipsoid x² + 4y² + z² = 1 is the oblate spheroid of semi-axes a = 1, c = 1/2: its area is
// 2πa² + (πc²/e)·ln((1 + e)/(1 − e)) with e² = 1 − c²/a². Under a scale s, a sphere's.
TEST(PathLights, EllipsoidAreaIsTheSpheroidsClosedForm) {
    const double e = std::sqrt(0.75), want = 2 * kPi + kPi * 0.25 / e * std::log((1 + e) / (1 - e));
    for (float s : {1.0f, 2.0f}) {
        test::SceneBuilder b;
        b.add(ShapeKind::Ellipsoid, test::translate_scale({0, 0, 0}, glm::vec3(s)), test::emitter(glm::vec3(1.0f)));
        const Scene scene = b.build();
        EXPECT_NEAR(PathLights::world_area(scene.data.instances[0]), want * s * s, 1e-3 * want * s * s) << "scale " << s;
    }
    // Stretched by (1, 2, 1) it is the sphere of radius 1: 4π.
    test::SceneBuilder b;
    b.add(ShapeKind::Ellipsoid, test::translate_scale({0, 0, 0}, {1, 2, 1}), test::emitter(glm::vec3(1.0f)));
    EXPECT_NEAR(PathLights::world_area(b.build().data.instances[0]), 4 * kPi, 1e-3 * 4 * kPi);
}

// Pearson's chi-square test of a BSDF's samples against its pdf (as pbrt-v4's Chi2Test): directions
// binned in (cos θ, φ) about the normal, expected counts from the pdf integrated over each bin.
double chi2_p_value(const Bsdf& bsdf, const glm::vec3& n, int samples) {
    constexpr int kTheta = 10, kPhi = 20;
    glm::vec3 t, bt;
    orthonormal_basis(n, t, bt);
    std::vector<double> observed(kTheta * kPhi, 0.0), expected(kTheta * kPhi, 0.0);
    // The renderer's sampler as the renderer uses it: a few thousand samples in each of many pixels.
    constexpr int kPerPixel = 4096;
    const Sampler sampler(1, kPerPixel);
    for (int i = 0; i < samples; ++i) {
        const SampleKey key{std::uint32_t(i / kPerPixel), 7, std::uint32_t(i % kPerPixel)};
        const glm::vec2 lobe = sampler.get2d(key, 1);
        const BsdfSample s = bsdf.sample(lobe.x, sampler.get2d(key, 2));
        if (!s.valid || s.delta) continue;
        const float c = std::clamp(glm::dot(s.wi, n), -1.0f, 0.999999f);
        float phi = std::atan2(glm::dot(s.wi, bt), glm::dot(s.wi, t));
        if (phi < 0) phi += 2 * kPi;
        const int ti = std::min(kTheta - 1, int((c + 1) / 2 * kTheta)), pi = std::min(kPhi - 1, int(phi / (2 * kPi) * kPhi));
        observed[std::size_t(ti * kPhi + pi)] += 1;
    }
    // Midpoint rule in (cos θ, φ), where the solid angle element is d(cos θ) dφ.
    constexpr int kSub = 40;
    for (int ti = 0; ti < kTheta; ++ti)
        for (int pi = 0; pi < kPhi; ++pi) {
            double sum = 0;
            for (int a = 0; a < kSub; ++a)
                for (int c = 0; c < kSub; ++c) {
                    const double cz = -1 + 2.0 * (ti + (a + 0.5) / kSub) / kTheta;
                    const double ph = 2 * kPi * (pi + (c + 0.5) / kSub) / kPhi;
                    const double sz = std::sqrt(std::max(0.0, 1 - cz * cz));
                    const glm::vec3 w = float(sz * std::cos(ph)) * t + float(sz * std::sin(ph)) * bt + float(cz) * n;
                    sum += bsdf.pdf(glm::normalize(w));
                }
            expected[std::size_t(ti * kPhi + pi)] = sum / (kSub * kSub) * (2.0 / kTheta) * (2 * kPi / kPhi) * samples;
        }
    // Pool the bins expecting fewer than 5 (as pbrt does), then Pearson's statistic.
    std::vector<std::size_t> order(expected.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return expected[a] < expected[b]; });
    double pooled_o = 0, pooled_e = 0, chi2 = 0;
    int dof = -1;
    for (std::size_t k : order) {
        if (expected[k] == 0) {
            EXPECT_EQ(observed[k], 0) << "a sample where the pdf is 0";
            continue;
        }
        if (expected[k] < 5) {
            pooled_o += observed[k], pooled_e += expected[k];
            if (pooled_e < 5) continue;
            chi2 += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e, ++dof;
            pooled_o = pooled_e = 0;
            continue;
        }
        chi2 += (observed[k] - expected[k]) * (observed[k] - expected[k]) / expected[k], ++dof;
    }
    if (pooled_e > 0) chi2 += (pooled_o - pooled_e) * (pooled_o - pooled_e) / pooled_e, ++dof;
    // Upper tail of chi-square with dof degrees of freedom, by the Wilson–Hilferty cube-root normal.
    const double k = std::max(dof, 1), z = (std::cbrt(chi2 / k) - (1 - 2 / (9 * k))) / std::sqrt(2 / (9 * k));
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

TEST(Bsdf, SamplesFollowThePdfByChiSquare) {
    const glm::vec3 n = glm::normalize(glm::vec3(0.2f, 1, -0.1f));
    const glm::vec3 wo = glm::normalize(glm::vec3(0.5f, 0.6f, 0.3f));
    struct Case {
        const char* name;
        Material m;
        glm::vec3 wo;
    };
    std::vector<Case> cases;
    auto add = [&](const char* name, auto set, glm::vec3 w = glm::vec3(0)) {
        Material m;
        m.diffuse = glm::vec3(0.0f);
        set(m);
        cases.push_back({name, m, w == glm::vec3(0) ? wo : glm::normalize(w)});
    };
    add("diffuse", [](Material& m) { m.diffuse = glm::vec3(0.8f); });
    add("phong 10", [](Material& m) { m.specular = glm::vec3(0.7f); m.shine = 10; });
    add("diffuse + phong 40", [](Material& m) { m.diffuse = glm::vec3(0.4f); m.specular = glm::vec3(0.5f); m.shine = 40; });
    add("glossy mirror", [](Material& m) { m.reflect = glm::vec3(0.9f); m.gloss = 20; });
    add("frosted glass, entering", [](Material& m) { m.transparent = glm::vec3(0.9f); m.gloss = 30; m.ior = 1.5f; });
    add("frosted glass, leaving",
        [](Material& m) { m.transparent = glm::vec3(0.9f); m.gloss = 30; m.ior = 1.5f; }, -n + 0.3f * glm::vec3(1, 0, 0));
    add("frosted glass, total internal reflection",
        [](Material& m) { m.transparent = glm::vec3(0.9f); m.gloss = 30; m.ior = 1.5f; }, -n + 2.0f * glm::vec3(1, 0, 0));
    add("everything", [](Material& m) {
        m.diffuse = glm::vec3(0.2f);
        m.specular = glm::vec3(0.2f);
        m.shine = 5;
        m.reflect = glm::vec3(0.2f);
        m.transparent = glm::vec3(0.2f);
        m.gloss = 8;
    });
    // Šidák-corrected significance 1% over the cases.
    const double alpha = 1 - std::pow(1 - 0.01, 1.0 / double(cases.size()));
    for (const Case& c : cases) {
        const Bsdf bsdf(c.m, c.m.diffuse, n, c.wo);
        const double p = chi2_p_value(bsdf, n, 262144);
        EXPECT_GT(p, alpha) << c.name;
    }
}

TEST(Bsdf, EnergyIsNeverCreated) {
    Material m;
    m.diffuse = glm::vec3(0.9f, 0.2f, 0.2f);
    m.reflect = glm::vec3(0.5f);
    EXPECT_FLOAT_EQ(energy_scale(m), 1.0f / 1.4f);  // red: 0.9 + 0.5
    m.reflect = glm::vec3(0.1f);
    EXPECT_EQ(energy_scale(m), 1.0f);
    // The directional albedo of a white Lambertian + normalised Phong surface stays at most 1.
    Material w;
    w.diffuse = glm::vec3(0.5f);
    w.specular = glm::vec3(0.5f);
    w.shine = 20;
    const glm::vec3 n(0, 1, 0);
    for (float c : {1.0f, 0.7f, 0.3f}) {
        const glm::vec3 wo(std::sqrt(1 - c * c), c, 0);
        const Bsdf bsdf(w, w.diffuse, n, wo);
        const int k = 200000;
        const Sampler s(1, k);
        double albedo = 0;
        for (int i = 0; i < k; ++i) {
            const BsdfSample b = bsdf.sample(s.get2d({0, 0, std::uint32_t(i)}, 1).x, s.get2d({0, 0, std::uint32_t(i)}, 2));
            if (b.valid) albedo += b.weight.x;
        }
        EXPECT_LT(albedo / k, 1.0 + 0.01) << "cos " << c;
        // Head-on, the normalised lobe reflects all it is given: (n + 2)/(2π) ∫ cos^n θ cos θ dω = 1.
        if (c == 1.0f) {
            EXPECT_NEAR(albedo / k, 1.0, 0.01);
        }
    }
}

}  // namespace
}  // namespace whitted
