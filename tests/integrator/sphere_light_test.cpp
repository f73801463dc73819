// An emissive sphere sampled from a shading point by the cone it subtends (integrator/sphere_light.h):
// against closed forms. From outside, every sample's 1 / density per solid angle is the cone's solid
// angle 2π(1 − cos α), sin α = r / distance (a constant: no variance at all), every sample is on the
// side x sees, and the irradiance a unit-radiance sphere gives a surface facing it is π sin² α (cosine
// law, the sphere wholly above the horizon). By directions uniform over all the sphere around x, the
// density integrates to 1 over the directions that meet the sphere (nothing outside it).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "integrator/path_lights.h"
#include "integrator/path_test_support.h"
#include "integrator/sphere_light.h"
#include "sampler/sampler.h"
#include "sampler/warp.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

using test::stats_of;

// A sphere of radius 0.5 · 1.6 = 0.8 at (1, 2, 3), turned about a skew axis: still round.
glm::mat4 round_sphere() {
    return glm::rotate(test::translate_scale({1, 2, 3}, glm::vec3(1.6f)), 0.7f, glm::normalize(glm::vec3(1, 2, 0.5f)));
}

TEST(SphereLight, OnlyARoundSphereIsSampledByItsCone) {
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, round_sphere(), test::emitter(glm::vec3(1.0f)));
    const Scene scene = b.build();
    const std::optional<SphereLight> round = SphereLight::of(scene.data.instances[0]);
    ASSERT_TRUE(round.has_value());
    EXPECT_NEAR(round->radius(), 0.8f, 1e-5f);
    EXPECT_NEAR(glm::length(round->centre() - glm::vec3(1, 2, 3)), 0.0f, 1e-5f);
    test::SceneBuilder stretched;  // an ellipsoid: by area
    stretched.add(ShapeKind::Sphere, test::translate_scale({0, 0, 0}, {1.0f, 1.3f, 1.0f}), test::emitter(glm::vec3(1.0f)));
    EXPECT_FALSE(SphereLight::of(stretched.build().data.instances[0]).has_value());
}

TEST(SphereLight, EverySampleIsSeenAndCarriesTheConesSolidAngle) {
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, round_sphere(), test::emitter(glm::vec3(1.0f)));
    const Scene scene = b.build();
    const PathLights lights(scene);
    const glm::vec3 c(1, 2, 3);
    const float r = 0.8f;
    // Near (α = 53°), at a few radii, far (α = 0.46°: the small-cone branch).
    for (float distance : {1.0f, 2.5f, 100.0f}) {
        SCOPED_TRACE("distance " + std::to_string(distance));
        const glm::vec3 x = c + distance * glm::normalize(glm::vec3(-0.3f, 0.9f, 0.2f));
        const double sin_a = r / distance, cos_a = std::sqrt(1 - sin_a * sin_a);
        const double omega = 2 * kPi * (1 - cos_a);
        const Sampler sampler(1, 4096);
        for (int i = 0; i < 4096; ++i) {
            const glm::vec2 u = sampler.get2d({0, 0, std::uint32_t(i)}, 3);
            const AreaLightSample ls = lights.sample_area(0, x, u);
            ASSERT_NEAR(glm::length(ls.point - c), r, 1e-4f * distance);
            const glm::vec3 to = ls.point - x;
            const float d = glm::length(to);
            // On the near side: the ray from x meets the sphere there first.
            ASSERT_GE(glm::dot(ls.normal, -to / d), -1e-3f);
            Hit hit;
            ASSERT_TRUE(scene.intersect(Ray{x, to / d}, hit));
            ASSERT_NEAR(hit.t, d, 2e-3f * d);
            // The density pdf_area reports for the point (a BSDF ray's MIS weight) is the one drawn with.
            const glm::vec3 n_obj = glm::normalize(glm::vec3(to_object_space(scene.data.instances[0], Ray{ls.point, {}}).origin));
            EXPECT_NEAR(lights.pdf_area(0, x, ls.point, n_obj), ls.pdf_area, 1e-3f * ls.pdf_area);
            const double cos_l = std::abs(glm::dot(ls.normal, to / d));
            ASSERT_NEAR(cos_l / (ls.pdf_area * double(d) * d), omega, 2e-3 * omega);
        }
    }
}

TEST(SphereLight, IrradianceOfAFacingSurfaceIsPiSinSquaredAlpha) {
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, round_sphere(), test::emitter(glm::vec3(1.0f)));
    const Scene scene = b.build();
    const PathLights lights(scene);
    const glm::vec3 c(1, 2, 3);
    const glm::vec3 x = c + glm::vec3(0, -2.0f, 0);  // the surface's normal +y faces the centre
    const double sin_a = 0.8 / 2.0;
    const int n = 20000;
    const Sampler sampler(1, n);
    std::vector<double> terms;
    for (int i = 0; i < n; ++i) {
        const AreaLightSample ls = lights.sample_area(0, x, sampler.get2d({0, 0, std::uint32_t(i)}, 3));
        const glm::vec3 to = ls.point - x;
        const double d2 = glm::dot(to, to);
        const glm::vec3 w = to / float(std::sqrt(d2));
        terms.push_back(double(w.y) * std::abs(glm::dot(ls.normal, w)) / (d2 * ls.pdf_area));
    }
    const auto e = stats_of(terms);
    EXPECT_NEAR(e.mean, kPi * sin_a * sin_a, 4 * e.se + 1e-4);
}

// Directions uniform over all the sphere of directions around x: 4π · the density of the point each
// meets averages to 1 (the density covers the cone and nothing else), from outside and from inside.
TEST(SphereLight, DensityIntegratesToOneOverTheDirectionsThatMeetIt) {
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, round_sphere(), test::emitter(glm::vec3(1.0f)));
    const Scene scene = b.build();
    const PathLights lights(scene);
    const Instance& inst = scene.data.instances[0];
    for (const glm::vec3 x : {glm::vec3(1.9f, 2.4f, 2.2f), glm::vec3(1.1f, 2.2f, 3.1f)}) {
        const int n = 40000;
        const Sampler sampler(1, n);
        std::vector<double> terms;
        for (int i = 0; i < n; ++i) {
            const glm::vec2 u = sampler.get2d({0, 0, std::uint32_t(i)}, 5);
            const glm::vec3 w = around_axis({0, 0, 1}, 1 - 2 * u.x, u.y);
            Hit hit;
            if (!scene.intersect(Ray{x, w}, hit)) {
                terms.push_back(0.0);
                continue;
            }
            const glm::vec3 p = to_object_space(inst, Ray{x, w}).at(hit.t);
            const glm::vec3 n_obj = glm::normalize(p);
            const double cos_l = std::abs(glm::dot(normal_to_world(inst, n_obj), w));
            terms.push_back(4 * kPi * lights.pdf_area(0, x, x + hit.t * w, n_obj) * hit.t * hit.t / cos_l);
        }
        const auto integral = stats_of(terms);
        EXPECT_NEAR(integral.mean, 1.0, 4 * integral.se + 1e-3);
    }
}

}  // namespace
}  // namespace whitted
