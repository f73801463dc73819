// Sampling a placed mesh by area (the path tracer's emissive meshes, §9.2): total areas against
// closed forms, triangles picked in proportion to their world area, points uniform inside them.
#include <cmath>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "integrator/mesh_area_sampler.h"
#include "mesh/obj_reader.h"
#include "mesh/mesh_test_support.h"

namespace whitted {
namespace {

TriangleMesh cube() {
    TriangleMesh m;
    EXPECT_TRUE(read_obj_text(test::cube_obj(), "cube.obj", m).ok);
    return m;
}

TEST(MeshAreaSampler, TotalAreaIsTheSurfaceAreaUnderTheMatrix) {
    const TriangleMesh m = cube();
    EXPECT_NEAR(MeshAreaSampler(m, glm::mat4(1.0f)).total_area(), 6.0f, 1e-5f);
    // A 2 × 1 × 3 box: 2·(2·1 + 1·3 + 2·3) = 22, whatever the rotation and translation.
    glm::mat4 box = glm::translate(glm::mat4(1.0f), glm::vec3(5, -2, 1));
    box = glm::rotate(box, 0.7f, glm::normalize(glm::vec3(1, 2, 3)));
    box = glm::scale(box, glm::vec3(2, 1, 3));
    EXPECT_NEAR(MeshAreaSampler(m, box).total_area(), 22.0f, 1e-4f);
}

TEST(MeshAreaSampler, PicksFacesInProportionToTheirWorldArea) {
    // Under scale (2, 1, 3) the ±x faces have area 3, ±y 6, ±z 2 (each two triangles): a face's
    // share is its area / 22. Counts from N draws are binomial: within 5σ of N·p.
    const TriangleMesh m = cube();
    const MeshAreaSampler s(m, glm::scale(glm::mat4(1.0f), glm::vec3(2, 1, 3)));
    const int n = 200000;
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<int> per_axis(3, 0);
    for (int i = 0; i < n; ++i) {
        const AreaSample a = s.sample({u(rng), u(rng), u(rng)});
        const glm::vec3 n_abs = glm::abs(a.normal);
        const int axis = n_abs.x > 0.5f ? 0 : n_abs.y > 0.5f ? 1 : 2;
        ++per_axis[axis];
        EXPECT_NEAR(a.pdf_area, 1.0f / 22.0f, 1e-6f);
        // The point is on the face its normal says (scaled cube: |x| = 1, |y| = 0.5, |z| = 1.5).
        const float half[3] = {1.0f, 0.5f, 1.5f};
        ASSERT_NEAR(std::abs(a.point[axis]), half[axis], 1e-5f) << i;
    }
    const double share[3] = {6.0 / 22.0, 12.0 / 22.0, 4.0 / 22.0};
    for (int axis = 0; axis < 3; ++axis) {
        const double mean = n * share[axis], sigma = std::sqrt(n * share[axis] * (1 - share[axis]));
        EXPECT_NEAR(per_axis[axis], mean, 5 * sigma) << "axis " << axis;
    }
}

TEST(MeshAreaSampler, PointsAreUniformInsideATriangle) {
    // One triangle (0,0,0), (1,0,0), (0,1,0): x has density 2(1 − x), so uniform points have mean
    // (1/3, 1/3), E[x²] = 1/6 and E[x⁴] = 1/15; the fraction with x + y < 1/2 is the area ratio 1/4.
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}};
    const MeshAreaSampler s(m, glm::mat4(1.0f));
    const int n = 100000;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    double sx = 0, sy = 0, sxx = 0;
    int near_corner = 0;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 p = s.sample({u(rng), u(rng), u(rng)}).point;
        ASSERT_GE(p.x, 0.0f);
        ASSERT_GE(p.y, 0.0f);
        ASSERT_LE(p.x + p.y, 1.0f + 1e-6f);
        sx += p.x, sy += p.y, sxx += double(p.x) * p.x;
        near_corner += p.x + p.y < 0.5f;
    }
    // Var(x) = E[x²] − E[x]² = 1/6 − 1/9 = 1/18 for the uniform triangle; the mean's σ = √(1/18 / n).
    const double sigma_mean = std::sqrt(1.0 / 18.0 / n);
    EXPECT_NEAR(sx / n, 1.0 / 3.0, 5 * sigma_mean);
    EXPECT_NEAR(sy / n, 1.0 / 3.0, 5 * sigma_mean);
    EXPECT_NEAR(sxx / n, 1.0 / 6.0, 5 * std::sqrt((1.0 / 15.0 - 1.0 / 36.0) / n));
    EXPECT_NEAR(double(near_corner) / n, 0.25, 5 * std::sqrt(0.25 * 0.75 / n));
}

}  // namespace
}  // namespace whitted
