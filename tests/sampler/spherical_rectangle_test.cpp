// Sampling a rectangle by the solid angle it subtends (sampler/spherical_rectangle.h): its solid
// angle against the closed form of a centred rectangle seen on its axis and against two triangles'
// (Van Oosterom and Strackee 1983) off the axis; the samples on the rectangle, spread over it in
// proportion to the solid angles of its parts (chi-square), and the map's Jacobian, the solid
// angle per unit of the square, equal to the whole solid angle everywhere.
#include <cmath>
#include <random>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "sampler/spherical_rectangle.h"

namespace whitted {
namespace {

constexpr double kPiD = 3.14159265358979323846;

double triangle_solid_angle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const double la = glm::length(a), lb = glm::length(b), lc = glm::length(c);
    const double num = std::abs(glm::dot(a, glm::cross(b, c)));
    return 2 * std::atan2(num, la * lb * lc + glm::dot(a, b) * lc + glm::dot(a, c) * lb + glm::dot(b, c) * la);
}

// A rectangle in general position: corner + [0,1]·ex + [0,1]·ey, ex ⟂ ey.
struct Rect {
    glm::vec3 corner, ex, ey;
};

// Edges of small integers times powers of 2, so that in float too they are exactly perpendicular
// (a rotated rectangle's rounded edges are not, and the construction assumes they are).
Rect random_rect(std::mt19937& rng) {
    std::uniform_int_distribution<int> small(-4, 4), power(-5, -1);
    std::uniform_real_distribution<float> pos(-2.0f, 2.0f);
    glm::ivec3 v, r, w;
    do {
        v = {small(rng), small(rng), small(rng)};
        r = {small(rng), small(rng), small(rng)};
        w = {v.y * r.z - v.z * r.y, v.z * r.x - v.x * r.z, v.x * r.y - v.y * r.x};  // v × r
    } while (v == glm::ivec3(0) || w == glm::ivec3(0));
    return {glm::vec3(pos(rng), pos(rng), pos(rng)), std::ldexp(1.0f, power(rng)) * glm::vec3(v),
            std::ldexp(1.0f, power(rng) - 2) * glm::vec3(w)};
}

double two_triangles(const Rect& q, const glm::vec3& x) {
    const glm::dvec3 a = glm::dvec3(q.corner) - glm::dvec3(x), b = a + glm::dvec3(q.ex), c = b + glm::dvec3(q.ey),
                     d = a + glm::dvec3(q.ey);
    return triangle_solid_angle(a, b, c) + triangle_solid_angle(a, c, d);
}

TEST(SphericalRectangle, SolidAngleOnTheAxisIsTheClosedForm) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> len(0.01f, 5.0f);
    for (int i = 0; i < 200; ++i) {
        const double a = len(rng), b = len(rng), d = len(rng);
        // A centred a × b rectangle in the plane z = 0 seen from (0, 0, ±d).
        const glm::vec3 corner(float(-a / 2), float(-b / 2), 0.0f), ex(float(a), 0, 0), ey(0, float(b), 0);
        // The rectangle as given in float, for the closed form too.
        const double fa = ex.x, fb = ey.y, fd = float(d);
        const double want = 4 * std::asin(fa * fb / std::sqrt((fa * fa + 4 * fd * fd) * (fb * fb + 4 * fd * fd)));
        for (float sign : {1.0f, -1.0f}) {
            const SphericalRectangle s({0, 0, sign * float(d)}, corner, ex, ey);
            EXPECT_NEAR(s.solid_angle(), want, 1e-9 * want) << a << " x " << b << " at " << d;
        }
    }
}

TEST(SphericalRectangle, SolidAngleOffTheAxisIsTwoTriangles) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> pos(-4.0f, 4.0f);
    for (int i = 0; i < 500; ++i) {
        const Rect q = random_rect(rng);
        const glm::vec3 x(pos(rng), pos(rng), pos(rng));
        const double want = two_triangles(q, x);
        const SphericalRectangle s(x, q.corner, q.ex, q.ey);
        EXPECT_NEAR(s.solid_angle(), want, 1e-9 * want + 1e-12);
        EXPECT_GT(s.solid_angle(), 0.0);
        EXPECT_LT(s.solid_angle(), 2 * kPiD);
    }
}

// Given its solid angle (the two triangles'), the rectangle maps the square as it does when it
// finds the solid angle itself: the same points to float's rounding.
TEST(SphericalRectangle, GivenItsSolidAngleItMapsTheSameWay) {
    std::mt19937 rng(13);
    std::uniform_real_distribution<float> pos(-1.5f, 1.5f), unit(0.0f, 1.0f);
    for (int r = 0; r < 200; ++r) {
        const Rect q = random_rect(rng);
        const glm::vec3 x = q.corner + 0.5f * (q.ex + q.ey) + glm::vec3(pos(rng), pos(rng), pos(rng));
        const SphericalRectangle plain(x, q.corner, q.ex, q.ey), given(x, q.corner, q.ex, q.ey, two_triangles(q, x));
        EXPECT_NEAR(given.solid_angle(), plain.solid_angle(), 1e-9 * plain.solid_angle() + 1e-12);
        for (int i = 0; i < 50; ++i) {
            const glm::vec2 u(unit(rng), unit(rng));
            const glm::vec2 a = plain.sample(u), b = given.sample(u);
            EXPECT_NEAR(a.x, b.x, 1e-5f) << r << " u " << u.x << " " << u.y;
            EXPECT_NEAR(a.y, b.y, 1e-5f) << r << " u " << u.x << " " << u.y;
        }
    }
}

// The samples land on the rectangle, in each of its 4 × 4 cells in proportion to the cell's solid
// angle: a chi-square test with 15 degrees of freedom at p = 1e-4 for each rectangle.
TEST(SphericalRectangle, SamplesFillTheCellsInProportionToTheirSolidAngles) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> pos(-1.5f, 1.5f), unit(0.0f, 1.0f);
    constexpr int kCells = 4, n = 20000;
    for (int r = 0; r < 20; ++r) {
        const Rect q = random_rect(rng);
        // Close to the rectangle, where its cells' solid angles differ most.
        const glm::vec3 x = q.corner + 0.5f * (q.ex + q.ey) + glm::vec3(pos(rng), pos(rng), pos(rng));
        const SphericalRectangle s(x, q.corner, q.ex, q.ey);
        int count[kCells][kCells] = {};
        for (int i = 0; i < n; ++i) {
            const glm::vec2 st = s.sample({unit(rng), unit(rng)});
            ASSERT_GE(st.x, 0.0f);
            ASSERT_LE(st.x, 1.0f);
            ASSERT_GE(st.y, 0.0f);
            ASSERT_LE(st.y, 1.0f);
            ++count[std::min(kCells - 1, int(st.x * kCells))][std::min(kCells - 1, int(st.y * kCells))];
        }
        double chi2 = 0;
        for (int i = 0; i < kCells; ++i)
            for (int j = 0; j < kCells; ++j) {
                const Rect cell{q.corner + (float(i) / kCells) * q.ex + (float(j) / kCells) * q.ey, q.ex / float(kCells),
                                q.ey / float(kCells)};
                const double expected = n * two_triangles(cell, x) / s.solid_angle();
                chi2 += (count[i][j] - expected) * (count[i][j] - expected) / expected;
            }
        EXPECT_LT(chi2, 42.6) << "rectangle " << r << ", solid angle " << s.solid_angle();
    }
}

// Uniform in solid angle: the directions of the four corners of a small square of the unit
// square span a solid angle of (its area) · Ω, wherever the square is.
TEST(SphericalRectangle, EqualAreasOfTheSquareAreEqualSolidAngles) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> pos(-1.5f, 1.5f), inner(0.05f, 0.95f);
    for (int r = 0; r < 20; ++r) {
        const Rect q = random_rect(rng);
        const glm::vec3 x = q.corner + 0.5f * (q.ex + q.ey) + glm::vec3(pos(rng), pos(rng), pos(rng));
        const SphericalRectangle s(x, q.corner, q.ex, q.ey);
        for (int i = 0; i < 20; ++i) {
            const glm::vec2 u(inner(rng), inner(rng));
            const float h = 2e-3f;
            glm::dvec3 w[4];
            const glm::vec2 du[4] = {{0, 0}, {h, 0}, {h, h}, {0, h}};
            for (int c = 0; c < 4; ++c) {
                const glm::vec2 st = s.sample(u + du[c]);
                w[c] = glm::dvec3(q.corner + st.x * q.ex + st.y * q.ey) - glm::dvec3(x);
            }
            const double cell = triangle_solid_angle(w[0], w[1], w[2]) + triangle_solid_angle(w[0], w[2], w[3]);
            // The cell's sides are arcs, not the great circles the triangles have: an error of
            // order h² of the cell, plus float's rounding of the sampled points.
            EXPECT_NEAR(cell / (h * h), s.solid_angle(), 2e-2 * s.solid_angle()) << "u " << u.x << " " << u.y;
        }
    }
}

}  // namespace
}  // namespace whitted
