// Soft shadows (scene-format.md §9.1): a disc light above a floor, half of it hidden by the straight
// edge of a slab. The light reaching each floor point is the mean over the disc of the point
// light's contribution; with the disc facing the point, what the slab hides is a circular segment
// cut by the plane through the point and the slab's edge. The renderer's estimate from N samples
// is checked against that geometry, with tolerances from N.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "integrator/whitted_integrator.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr float kH = 40.0f;      // the light's height
constexpr float kR = 1.0f;       // its radius
constexpr float kEdge = 20.0f;   // the slab's top face; it fills x < 0
constexpr float kThick = 0.01f;  // and is this thick

Scene penumbra_scene() {
    test::SceneBuilder b;
    Material floor;  // diffuse 1 only: the pixel is the light's diffuse term
    floor.diffuse = glm::vec3(1.0f);
    b.add(ShapeKind::Cube, test::translate_scale({0, -0.5f, 0}, {200, 1, 200}), floor);
    Material slab;
    slab.diffuse = glm::vec3(0.0f);
    b.add(ShapeKind::Cube, test::translate_scale({-50, kEdge - kThick / 2, 0}, {100, kThick, 200}), slab);
    Light l = test::point_light({0, kH, 0}, glm::vec3(1.0f));
    l.radius = kR;
    return b.light(l).ambient(glm::vec3(0.0f)).build();
}

// The plane through floor point P = (px, 0, 0) and the slab edge at height y_e (the line x = 0,
// y = y_e along z) cuts the disc (centre C, facing P) along a chord: the disc's point C + u is
// visible past that edge iff e·u >= d. Returns e and d.
struct Chord {
    glm::dvec3 e;
    double d;
};
Chord chord(double px, double y_e) {
    const glm::dvec3 n_plane(y_e, px, 0.0);  // normal of the plane through P and the edge
    const glm::dvec3 w = glm::normalize(glm::dvec3(px, -kH, 0.0));  // the disc's normal
    const glm::dvec3 in_disc = n_plane - glm::dot(n_plane, w) * w;
    const double len = glm::length(in_disc);
    return {in_disc / len, -px * (kH - y_e) / len};
}

// Area fraction of the unit-radius-R disc on the far side of a chord at distance d.
double segment_fraction(double d) {
    if (d <= -kR) return 1.0;
    if (d >= kR) return 0.0;
    return (kR * kR * std::acos(d / kR) - d * std::sqrt(kR * kR - d * d)) / (kPi * kR * kR);
}

// The visible fraction: both edges (top and bottom of the slab) cut parallel chords; the farther wins.
double visible_fraction(double px) {
    return segment_fraction(std::max(chord(px, kEdge).d, chord(px, kEdge - kThick).d));
}

// The exact expected pixel: mean over the disc of visibility × N·L, by midpoint quadrature of the
// geometry above (no renderer code).
double expected_light(double px) {
    const Chord c1 = chord(px, kEdge), c2 = chord(px, kEdge - kThick);
    const glm::dvec3 P(px, 0, 0), C(0, kH, 0), z(0, 0, 1);
    const int nr = 300, nphi = 600;
    double sum = 0, area = 0;
    for (int i = 0; i < nr; ++i) {
        const double r = kR * (i + 0.5) / nr;
        for (int j = 0; j < nphi; ++j) {
            const double phi = 2 * kPi * (j + 0.5) / nphi;
            const glm::dvec3 u = r * (std::cos(phi) * c1.e + std::sin(phi) * z);
            area += r;
            if (glm::dot(c1.e, u) < c1.d || glm::dot(c2.e, u) < c2.d) continue;
            const glm::dvec3 q = C + u;
            sum += r * q.y / glm::length(q - P);  // N = +y
        }
    }
    return sum / area;
}

// The renderer's estimate at floor point (px, 0, 0) from samples [0, n) of one pixel's sampler.
double estimate(const WhittedIntegrator& integrator, double px, int n, std::uint32_t pixel) {
    const Sampler sampler(1, n);
    RayCounts counts;
    double sum = 0;
    for (int i = 0; i < n; ++i)
        sum += integrator.radiance(Ray{{float(px), 5, 0}, {0, -1, 0}}, {pixel, 3, std::uint32_t(i)}, sampler, counts).x;
    return sum / n;
}

const std::vector<double> kPoints = {-1.5, -1.2, -0.9, -0.6, -0.3, 0.0, 0.3, 0.6, 0.9, 1.2, 1.5};

TEST(SoftShadow, TheAnalyticSegmentIsWhatTheQuadratureIntegrates) {
    // The reference itself: N·L lies in [cos_min, 1] over the disc, so the exact value lies between
    // cos_min and 1 times the visible fraction of the analytic overlap.
    for (double px : kPoints) {
        const double f = visible_fraction(px), e = expected_light(px);
        const double cos_min = 1.0 / std::sqrt(1.0 + std::pow((std::abs(px) + kR) / (kH - kR), 2));
        EXPECT_LE(e, f + 2e-3) << px;
        EXPECT_GE(e, cos_min * f - 2e-3) << px;
    }
    EXPECT_NEAR(visible_fraction(0.0), 0.5, 0.01);  // under the edge: about half the disc
    EXPECT_EQ(visible_fraction(-2.0), 0.0);          // deep in the umbra
    EXPECT_EQ(visible_fraction(2.0), 1.0);           // fully lit
}

TEST(SoftShadow, PenumbraMatchesTheVisibleSegmentOfTheDisc) {
    const Scene scene = penumbra_scene();
    const WhittedIntegrator integrator(scene, scene.data.camera, 5);
    const int n = 1024;
    int in_penumbra = 0;
    for (std::size_t k = 0; k < kPoints.size(); ++k) {
        const double px = kPoints[k], want = expected_light(px), f = visible_fraction(px);
        // 5 standard errors of plain Monte Carlo visibility with n samples (the stratified samples
        // do better), plus the quadrature's own error.
        const double tol = 5.0 * std::sqrt(f * (1 - f) / n) + 2e-3;
        EXPECT_NEAR(estimate(integrator, px, n, std::uint32_t(k)), want, tol) << "x = " << px;
        in_penumbra += f > 0.05 && f < 0.95;
    }
    EXPECT_GE(in_penumbra, 5) << "the points should cross the penumbra";
}

TEST(SoftShadow, ErrorFallsAsTheSampleCountGrows) {
    const Scene scene = penumbra_scene();
    const WhittedIntegrator integrator(scene, scene.data.camera, 5);
    double err[2] = {};
    const int counts[2] = {16, 1024};
    for (int c = 0; c < 2; ++c) {
        // RMS over many pixels (scrambles) and the penumbra's points.
        double sq = 0;
        int m = 0;
        for (std::uint32_t pixel = 0; pixel < 8; ++pixel)
            for (double px : kPoints) {
                const double d = estimate(integrator, px, counts[c], pixel) - expected_light(px);
                sq += d * d;
                ++m;
            }
        err[c] = std::sqrt(sq / m);
    }
    // 64 times the samples: plain Monte Carlo would divide the error by 8. Ask for 4.
    EXPECT_GT(err[0], 0.0);
    EXPECT_LT(err[1], err[0] / 4) << "16 spp: " << err[0] << ", 1024 spp: " << err[1];
}

TEST(SoftShadow, RadiusZeroOrOneSampleIsThePointLight) {
    Scene disc = penumbra_scene();
    const WhittedIntegrator soft(disc, disc.data.camera, 5);
    Scene hard = penumbra_scene();
    hard.data.lights[0].radius = 0.0f;
    const WhittedIntegrator point(hard, hard.data.camera, 5);
    RayCounts counts;
    for (double px : kPoints) {
        const Ray ray{{float(px), 5, 0}, {0, -1, 0}};
        // One sample: the light's centre, exactly the point light.
        EXPECT_EQ(soft.radiance(ray, {0, 0, 0}, Sampler(), counts), point.radiance(ray, {0, 0, 0}, Sampler(), counts));
        // Radius 0 at 16 samples: every sample is the point light.
        for (std::uint32_t i = 0; i < 16; ++i)
            EXPECT_EQ(point.radiance(ray, {0, 0, i}, Sampler(1, 16), counts),
                      point.radiance(ray, {0, 0, 0}, Sampler(), counts));
    }
}

}  // namespace
}  // namespace whitted
