// Sampling a rectangle by the solid angle it subtends (sampler/spherical_rectangle.h): its solid
// angle against the closed form of a centred rectangle seen on its axis and against two triangles'
// (Van Oosterom and Strackee 1983) off the axis; the samples on the rectangle, spread over it in
// proportion to the solid angles of its parts (chi-square), and the map's Jacobian, the solid
// angle per unit of the square, equal to the whole solid angle everywhere.
#include <algorithm>
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

// The map as the paper (and pbrt-v4's SampleSphericalRectangle) writes it, in double, from scratch:
// the point of the rectangle that u maps to.
glm::dvec3 papers_map(const Rect& q, const glm::vec3& x, glm::vec2 u) {
    const double lx = glm::length(glm::dvec3(q.ex)), ly = glm::length(glm::dvec3(q.ey));
    const glm::dvec3 ex = glm::dvec3(q.ex) / lx, ey = glm::dvec3(q.ey) / ly;
    glm::dvec3 ez = glm::cross(ex, ey);
    const glm::dvec3 d0 = glm::dvec3(q.corner) - glm::dvec3(x);
    const double x0 = glm::dot(d0, ex), y0 = glm::dot(d0, ey);
    double z0 = glm::dot(d0, ez);
    if (z0 > 0) {
        ez = -ez;
        z0 = -z0;
    }
    const double x1 = x0 + lx, y1 = y0 + ly;
    const glm::dvec3 v00(x0, y0, z0), v01(x0, y1, z0), v10(x1, y0, z0), v11(x1, y1, z0);
    const glm::dvec3 n0 = glm::normalize(glm::cross(v00, v10)), n1 = glm::normalize(glm::cross(v10, v11)),
                     n2 = glm::normalize(glm::cross(v11, v01)), n3 = glm::normalize(glm::cross(v01, v00));
    const auto between = [](glm::dvec3 a, glm::dvec3 b) { return std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)); };
    const double g0 = between(-n0, n1), g1 = between(-n1, n2), g2 = between(-n2, n3), g3 = between(-n3, n0);
    const double b0 = n0.z, b1 = n2.z, k = 2 * kPiD - g2 - g3, omega = g0 + g1 - k;
    const double au = u.x * omega + k;
    const double fu = (std::cos(au) * b0 - b1) / std::sin(au);
    const double cu = std::clamp(std::copysign(1.0, fu) / std::sqrt(fu * fu + b0 * b0), -1.0, 1.0);
    const double xu = std::clamp(-(cu * z0) / std::sqrt(std::max(0.0, 1 - cu * cu)), x0, x1);
    const double dd = std::sqrt(xu * xu + z0 * z0);
    const double h0 = y0 / std::sqrt(dd * dd + y0 * y0), h1 = y1 / std::sqrt(dd * dd + y1 * y1);
    const double hv = h0 + u.y * (h1 - h0);
    const double yv = hv * hv < 1 - 1e-12 ? std::clamp(hv * dd / std::sqrt(1 - hv * hv), y0, y1) : y1;
    return glm::dvec3(x) + xu * ex + yv * ey + z0 * ez;
}

// Our map, written to wait on fewer roots and divisions, lands where the paper's does (to a
// millionth of the rectangle's size), near its edges and corners too.
TEST(SphericalRectangle, MapsTheSquareAsThePaperDoes) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> pos(-1.5f, 1.5f), unit(0.0f, 1.0f);
    const float edge[] = {0.0f, 1e-6f, 0.5f, 1.0f - 1e-6f, 0x1.fffffep-1f};
    for (int r = 0; r < 300; ++r) {
        const Rect q = random_rect(rng);
        const glm::vec3 x = q.corner + 0.5f * (q.ex + q.ey) + glm::vec3(pos(rng), pos(rng), pos(rng));
        const SphericalRectangle s(x, q.corner, q.ex, q.ey);
        if (!(s.solid_angle() > 1e-4)) continue;  // the light samples those by area
        const double size = std::max(glm::length(q.ex), glm::length(q.ey));
        for (int i = 0; i < 60; ++i) {
            const glm::vec2 u = i < 25 ? glm::vec2(edge[i % 5], edge[i / 5]) : glm::vec2(unit(rng), unit(rng));
            const glm::vec2 st = s.sample(u);
            const glm::dvec3 got = glm::dvec3(q.corner) + double(st.x) * glm::dvec3(q.ex) + double(st.y) * glm::dvec3(q.ey);
            EXPECT_LT(glm::length(got - papers_map(q, x, u)), 1e-6 * size) << r << " u " << u.x << " " << u.y;
        }
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
