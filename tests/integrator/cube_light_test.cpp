// An emissive cube sampled from a shading point (integrator/cube_light.h) under a matrix that
// shears its faces into parallelograms: from outside, the density of directions integrates to 1
// over the directions that meet the cube (so no sample is wasted on a face the point cannot see),
// and the samples' 1 / density averages to the cube's solid angle, summed over the faces the
// point is in front of with the closed form of Van Oosterom and Strackee (1983); from inside,
// to 4π. And the furnace inside a stretched emissive cube.
#include <algorithm>
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "integrator/cube_light.h"
#include "integrator/path_integrator.h"
#include "integrator/path_lights.h"
#include "integrator/path_test_support.h"
#include "sampler/sampler.h"
#include "sampler/warp.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

using test::stats_of;

// The solid angle of the triangle (a, b, c), seen from the origin.
double triangle_solid_angle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double num = std::abs(glm::dot(a, glm::cross(b, c)));
    const double den = la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la;
    return 2 * std::atan2(num, den);
}

// The cube's solid angle from x (object-space point p_obj): its faces x is in front of, each a
// parallelogram of two triangles; 4π from inside.
double cube_solid_angle(const glm::mat4& m, const glm::vec3& p_obj) {
    double total = 0;
    bool outside = false;
    for (int axis = 0; axis < 3; ++axis)
        for (float side : {0.5f, -0.5f}) {
            if (!(side > 0 ? p_obj[axis] > side : p_obj[axis] < side)) continue;
            outside = true;
            const int i = (axis + 1) % 3, j = (axis + 2) % 3;
            glm::dvec3 v[4];
            for (int c = 0; c < 4; ++c) {
                glm::vec3 q(0.0f);
                q[axis] = side;
                q[i] = c == 1 || c == 2 ? 0.5f : -0.5f;
                q[j] = c >= 2 ? 0.5f : -0.5f;
                v[c] = glm::dvec3(glm::vec3(m * glm::vec4(q - p_obj, 0.0f)));
            }
            total += triangle_solid_angle(v[0], v[1], v[2]) + triangle_solid_angle(v[0], v[2], v[3]);
        }
    return outside ? total : 4 * kPi;
}

// Under a matrix that shears the faces (a rotation before a non-uniform scale: faces sampled by
// area) and one that does not (the scale first: faces sampled by solid angle where not too small).
void expect_density_covers_what_x_sees(const glm::mat4& m) {
    test::SceneBuilder b;
    b.add(ShapeKind::Cube, m, test::emitter(glm::vec3(1.0f)));
    const Scene scene = b.build();
    const Instance& inst = scene.data.instances[0];
    const PathLights lights(scene);
    const CubeLight cube(inst);
    // In front of one face, of two, of three, just off a face's middle, near an edge, far, inside.
    const glm::vec3 points[] = {{1.3f, 0.1f, -0.2f}, {1.0f, -0.9f, 0.2f}, {0.9f, 0.8f, -1.1f}, {0.52f, 0.0f, 0.1f},
                                {0.6f, 0.55f, 0.0f}, {4.0f, 3.0f, -2.5f}, {0.1f, 0.2f, -0.1f}};
    for (const glm::vec3& p_obj : points) {
        SCOPED_TRACE("object-space point " + std::to_string(p_obj.x) + " " + std::to_string(p_obj.y) + " " +
                     std::to_string(p_obj.z));
        const glm::vec3 x = glm::vec3(m * glm::vec4(p_obj, 1.0f));
        const double omega = cube_solid_angle(m, p_obj);
        // Directions uniform over the sphere: 4π · the density where they meet the cube, 0 where not.
        const int n = 40000;
        const Sampler sampler(1, n);
        std::vector<double> terms;
        for (int i = 0; i < n; ++i) {
            const glm::vec2 u = sampler.get2d({0, 0, std::uint32_t(i)}, 3);
            const glm::vec3 w = around_axis({0, 0, 1}, 1 - 2 * u.x, u.y);
            Hit hit;
            if (!scene.intersect(Ray{x, w}, hit)) {
                terms.push_back(0.0);
                continue;
            }
            const glm::vec3 p = to_object_space(inst, Ray{x, w}).at(hit.t);
            const glm::vec3 n_obj = unit_shape_normal(ShapeKind::Cube, hit.part, p);
            const double cos_l = std::abs(glm::dot(normal_to_world(inst, n_obj), w));
            terms.push_back(4 * kPi * lights.pdf_area(0, x, x + hit.t * w, n_obj) * hit.t * hit.t / cos_l);
        }
        const auto integral = stats_of(terms);
        EXPECT_NEAR(integral.mean, 1.0, 4 * integral.se + 1e-3);
        // The samples: on a face x can see (nothing of the cube in between), with the density
        // pdf_area reports for them, and 1 / their density per solid angle averages to the solid angle.
        std::vector<double> inverse;
        for (int i = 0; i < 4000; ++i) {
            const glm::vec2 u = sampler.get2d({1, 0, std::uint32_t(i)}, 5);
            const AreaLightSample ls = lights.sample_area(0, x, u);
            const CubeLight::Sample cs = cube.sample(x, u);
            ASSERT_EQ(ls.point, cs.point);
            const glm::vec3 q = to_object_space(inst, Ray{ls.point, glm::vec3(0)}).origin;
            const glm::vec3 aq = glm::abs(q);
            const int axis = aq.x >= aq.y && aq.x >= aq.z ? 0 : aq.y >= aq.z ? 1 : 2;
            ASSERT_NEAR(aq[axis], 0.5f, 1e-4f);
            glm::vec3 n_obj(0.0f);
            n_obj[axis] = q[axis] > 0 ? 1.0f : -1.0f;
            const glm::vec3 to = ls.point - x;
            const double d = glm::length(to);
            // A point on a face's edge (a sample coordinate within 1e-4 of 0 or 1) belongs to two
            // faces as far as its coordinates tell, and the ray to it grazes the cube, which rounding
            // may let pass: the face and visibility are checked away from the edges.
            const bool on_edge = 0.5f - std::max(aq[(axis + 1) % 3], aq[(axis + 2) % 3]) < 1e-4f;
            if (!on_edge) {
                EXPECT_FLOAT_EQ(ls.pdf_area, lights.pdf_area(0, x, ls.point, n_obj));
                if (omega < 4 * kPi) {
                    ASSERT_GT(n_obj[axis] * (p_obj[axis] - q[axis]), 0.0f) << "a face x is behind";
                    Hit hit;
                    ASSERT_TRUE(scene.intersect(Ray{x, to / float(d)}, hit));
                    EXPECT_NEAR(hit.t, d, 1e-3 * d) << "hidden behind another face";
                }
            }
            const double cos_l = std::abs(glm::dot(ls.normal, glm::vec3(to / float(d))));
            inverse.push_back(cos_l / (ls.pdf_area * d * d));
        }
        const auto solid = stats_of(inverse);
        EXPECT_NEAR(solid.mean, omega, 4 * solid.se + 1e-3 * omega);
    }
}

TEST(CubeLight, DensityCoversExactlyWhatTheShadingPointSeesUnderShear) {
    expect_density_covers_what_x_sees(glm::rotate(test::translate_scale({1, 2, 3}, {2.0f, 0.7f, 1.3f}), 0.6f,
                                                  glm::normalize(glm::vec3(1, 2, 0.5f))));
}

TEST(CubeLight, DensityCoversExactlyWhatTheShadingPointSeesWithRectangularFaces) {
    const glm::mat4 r = glm::rotate(glm::translate(glm::mat4(1.0f), {1, 2, 3}), 0.6f, glm::normalize(glm::vec3(1, 2, 0.5f)));
    expect_density_covers_what_x_sees(glm::scale(r, {2.0f, 0.7f, 1.3f}));
}

// A face of a cube the matrix does not shear, seen from a point in front of it alone and near it,
// is sampled uniformly in its solid angle: every sample's density per unit solid angle is 1 / Ω
// (the closed form of a centred rectangle seen on its axis, and two triangles off it), not only
// their mean; beyond CubeLight::kReach half-diagonals, and sheared, by area (the density per unit
// solid angle then varies from sample to sample).
TEST(CubeLight, AFaceSeenAloneIsSampledUniformlyInItsSolidAngle) {
    const float a = 1.0f, b = 0.6f;
    const glm::mat4 m = glm::scale(glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(0, 1, 0)), {a, 0.1f, b});
    const CubeLight cube(test::SceneBuilder().add(ShapeKind::Cube, m, test::emitter(glm::vec3(1))).build().data.instances[0]);
    const glm::vec3 down(0, -1, 0);
    const Sampler sampler(1, 256);
    const double reach = CubeLight::kReach * std::sqrt(a * a + b * b) / 2;  // 1.17
    for (float d : {0.02f, 0.2f, 1.0f, 1.15f}) {
        ASSERT_LT(d, reach);
        const glm::vec3 x = (0.05f + d) * down;  // below the bottom face, on its axis
        const double omega = 4 * std::asin(a * b / std::sqrt((a * a + 4.0 * d * d) * (b * b + 4.0 * d * d)));
        for (int i = 0; i < 256; ++i) {
            const CubeLight::Sample s = cube.sample(x, sampler.get2d({0, 0, std::uint32_t(i)}, 3));
            const glm::vec3 to = s.point - x;
            const double d2 = glm::dot(to, to), cos_l = std::abs(glm::dot(s.normal, to)) / std::sqrt(d2);
            ASSERT_NEAR(cos_l / (s.pdf_area * d2), omega, 1e-4 * omega) << "d " << d;
        }
    }
    for (float d : {1.19f, 3.0f}) {
        ASSERT_GT(d, reach);
        const glm::vec3 x = (0.05f + d) * down;
        for (int i = 0; i < 256; ++i)
            ASSERT_FLOAT_EQ(cube.sample(x, sampler.get2d({0, 0, std::uint32_t(i)}, 3)).pdf_area * a * b, 1.0f) << "d " << d;
    }
    // The reach is measured from the face's centre, not its plane: 0.1 below the plane but 1.3 off
    // the centre along the face (the point also sees a side face), the bottom face's samples all
    // have the same density per unit area (by area); 0.1 below the centre they do not.
    const glm::vec3 along = glm::vec3(m * glm::vec4(1, 0, 0, 0));  // the face's long edge
    for (const float off : {1.3f, 0.0f}) {
        const glm::vec3 x = 0.15f * down + off * along;
        float lo = INFINITY, hi = 0;
        for (int i = 0; i < 256; ++i) {
            const CubeLight::Sample s = cube.sample(x, sampler.get2d({0, 0, std::uint32_t(i)}, 3));
            if (s.normal.y > -0.5f) continue;  // a side face's
            lo = std::min(lo, s.pdf_area), hi = std::max(hi, s.pdf_area);
        }
        ASSERT_GT(hi, 0.0f) << "no sample on the bottom face, off " << off;
        if (off > 0)
            EXPECT_EQ(lo, hi) << "by area";
        else
            EXPECT_GT(hi, 1.5f * lo) << "by solid angle";
    }
    // Sheared: the face's edges not perpendicular; the same point close below it.
    const glm::mat4 sheared = glm::rotate(glm::scale(glm::mat4(1.0f), {a, 0.1f, b}), 0.4f, glm::vec3(0, 1, 0));
    const CubeLight slanted(test::SceneBuilder().add(ShapeKind::Cube, sheared, test::emitter(glm::vec3(1))).build().data.instances[0]);
    std::vector<double> inverse;
    for (int i = 0; i < 256; ++i) {
        const glm::vec3 x = 0.07f * down;
        const CubeLight::Sample s = slanted.sample(x, sampler.get2d({0, 0, std::uint32_t(i)}, 3));
        const glm::vec3 to = s.point - x;
        const double d2 = glm::dot(to, to);
        EXPECT_FLOAT_EQ(s.pdf_area, slanted.pdf_area(x, s.point, CubeLight::face_of(down)));
        EXPECT_NEAR(s.pdf_area * glm::length(glm::cross(glm::vec3(sheared[0]), glm::vec3(sheared[2]))), 1.0, 1e-5);
        inverse.push_back(std::abs(glm::dot(s.normal, to)) / std::sqrt(d2) / (s.pdf_area * d2));
    }
    EXPECT_GT(stats_of(inverse).se, 0.01);
}

// The irradiance at x of a square of radiance L above it, parallel to the plane x faces: π · L
// times the form factor, a sum over the four rectangles with a corner above x (each
// (1/2π)·[A/√(1+A²)·atan(B/√(1+A²)) + B/√(1+B²)·atan(A/√(1+B²))], sides A, B in units of the
// height; signed). Estimated with the light's samples: with solid-angle sampling each sample's
// estimate L·cos_x·cos_l/(pdf·d²) = L·cos_x·Ω varies with cos_x alone, with area sampling with
// cos_x·cos_l/d² too, which close to the square peaks under x: the variance at equal samples is
// lower, by a factor that grows as x nears the square.
double corner_form_factor(double a, double b, double c) {
    const double A = std::abs(a) / c, B = std::abs(b) / c, sa = std::sqrt(1 + A * A), sb = std::sqrt(1 + B * B);
    return std::copysign(1.0, a) * std::copysign(1.0, b) / (2 * kPi) *
           (A / sa * std::atan(B / sa) + B / sb * std::atan(A / sb));
}

double square_form_factor(double half, double px, double pz, double c) {
    const double x0 = -half - px, x1 = half - px, z0 = -half - pz, z1 = half - pz;
    return corner_form_factor(x1, z1, c) - corner_form_factor(x0, z1, c) - corner_form_factor(x1, z0, c) +
           corner_form_factor(x0, z0, c);
}

TEST(CubeLight, IrradianceUnderASquareIsTheClosedFormWithLessVarianceThanByArea) {
    const float side = 1.0f, thick = 1e-4f, L = 2.0f;
    const glm::mat4 m = test::translate_scale({0, 0, 0}, {side, thick, side});
    const CubeLight cube(test::SceneBuilder().add(ShapeKind::Cube, m, test::emitter(glm::vec3(L))).build().data.instances[0]);
    const int n = 4096;
    const Sampler sampler(1, n);
    struct Case {
        glm::vec3 x;
        double min_ratio;  // the variance of area sampling over that of solid-angle sampling, at least
    };
    // Under the middle at 0.05 and 0.3 below the square, under an edge, off to the side.
    // (Measured: 180, 22, 350, 28.) Then farther than CubeLight::kReach half-diagonals (1.41) from
    // its middle, where it is sampled by area: the same estimates (a ratio of 1).
    for (const Case& c : {Case{{0.0f, -0.05f, 0.0f}, 50.0}, Case{{0.0f, -0.3f, 0.0f}, 5.0},
                          Case{{0.5f, -0.05f, 0.1f}, 50.0}, Case{{0.9f, -0.2f, -0.3f}, 5.0},
                          Case{{0.2f, -1.6f, 0.1f}, 0.0}}) {
        const double h = -double(c.x.y) - thick / 2;
        const double want = kPi * L * square_form_factor(side / 2, c.x.x, c.x.z, h);
        std::vector<double> by_angle, by_area;
        for (int i = 0; i < n; ++i) {
            const glm::vec2 u = sampler.get2d({0, 0, std::uint32_t(i)}, 3);
            const CubeLight::Sample s = cube.sample(c.x, u);
            const glm::vec3 to = s.point - c.x;
            const double d2 = glm::dot(to, to), d = std::sqrt(d2);
            // The square's bottom face alone (not its thin sides, which x may also see).
            const bool bottom = s.normal.y < -0.5f;
            by_angle.push_back(bottom ? L * (to.y / d) * std::abs(glm::dot(s.normal, to)) / d / (s.pdf_area * d2) : 0.0);
            // By area on the face below: a point uniform on it, density 1 / side².
            const glm::vec3 q(side * (u.x - 0.5f), -thick / 2, side * (u.y - 0.5f));
            const glm::vec3 tq = q - c.x;
            const double e2 = glm::dot(tq, tq);
            by_area.push_back(L * (tq.y / std::sqrt(e2)) * (tq.y / std::sqrt(e2)) * side * side / e2);
        }
        const auto sa = stats_of(by_angle), ar = stats_of(by_area);
        SCOPED_TRACE("x " + std::to_string(c.x.x) + " " + std::to_string(c.x.y) + " " + std::to_string(c.x.z));
        EXPECT_NEAR(sa.mean, want, 4 * sa.se + 2e-4 * want);
        EXPECT_NEAR(ar.mean, want, 4 * ar.se + 2e-4 * want);
        const double ratio = (ar.se * ar.se) / (sa.se * sa.se);
        if (c.min_ratio > 0)
            EXPECT_GT(ratio, c.min_ratio) << "area sampling's variance over solid-angle sampling's";
        else
            EXPECT_NEAR(ratio, 1.0, 1e-3) << "far off: by area";
    }
}

// In path mode, a white Lambertian floor under the square has radiance L times the form factor.
TEST(CubeLight, PathModeFloorUnderASquareHasTheClosedFormRadiance) {
    const float side = 1.0f, thick = 1e-4f, L = 3.0f, h = 0.15f;
    test::SceneBuilder b;
    Material floor;
    floor.diffuse = glm::vec3(1.0f);
    b.add(ShapeKind::Cube, test::translate_scale({0, -0.5f, 0}, {100, 1, 100}), floor);
    b.add(ShapeKind::Cube, test::translate_scale({0, h + thick / 2, 0}, {side, thick, side}), test::emitter(glm::vec3(L)));
    const Scene scene = b.build();
    const PathIntegrator path(scene, scene.data.camera, 1);
    for (float px : {0.0f, 0.4f, 0.6f, 1.2f}) {
        const double want = L * square_form_factor(side / 2, px, 0.1, h);
        const auto s = stats_of(test::samples_of(path, Ray{{px, 0.05f, 0.1f}, {0, -1, 0}}, 2048));
        EXPECT_NEAR(s.mean, want, 4 * s.se + 1e-3 * want) << "x " << px;
    }
}

// The camera inside a closed, stretched emitting cube with grey albedo a sees e / (1 − a).
TEST(CubeLight, FurnaceInsideAStretchedCube) {
    const float e = 0.4f, a = 0.6f;
    test::SceneBuilder b;
    Material m;
    m.diffuse = glm::vec3(a);
    m.emit = glm::vec3(e);
    b.add(ShapeKind::Cube, glm::rotate(test::translate_scale({0.3f, -0.2f, 0.1f}, {20.0f, 9.0f, 14.0f}), 0.4f,
                                       glm::normalize(glm::vec3(1, 1, 0))),
          m);
    test::expect_furnace_image(b.build(), e / (1 - a));
}

}  // namespace
}  // namespace whitted
