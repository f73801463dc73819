// An emissive cube sampled from a shading point (integrator/cube_light.h) under a matrix that
// shears its faces into parallelograms: from outside, the density of directions integrates to 1
// over the directions that meet the cube (so no sample is wasted on a face the point cannot see),
// and the samples' 1 / density averages to the cube's solid angle, summed over the faces the
// point is in front of with the closed form of Van Oosterom and Strackee (1983); from inside,
// to 4π. And the furnace inside a stretched emissive cube.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "integrator/cube_light.h"
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

TEST(CubeLight, DensityCoversExactlyWhatTheShadingPointSees) {
    const glm::mat4 m = glm::rotate(test::translate_scale({1, 2, 3}, {2.0f, 0.7f, 1.3f}), 0.6f,
                                    glm::normalize(glm::vec3(1, 2, 0.5f)));
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
            terms.push_back(4 * kPi * lights.pdf_area(0, x, n_obj) * hit.t * hit.t / cos_l);
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
                EXPECT_FLOAT_EQ(ls.pdf_area, lights.pdf_area(0, x, n_obj));
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
