// Motion blur over a shutter (docs/animation.md): each sample takes its own time in the shutter
// interval, and moving objects (velocity, angularrate) are met where they are then. The blur is
// checked against closed forms of the pinhole projection; static scenes are untouched.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The camera of every scene here: 10 units from the plane z = 0, looking straight at it, with
// tan(fov / 2) = 1/2, so that an image `h` pixels high shows 10 units of that plane: a pixel
// is 10 / h units there, and column x (continuous, from the left) is at u = (10 / h)·(x − w/2).
const char* kCamera = "camera [ eye 0 0 10 focus 0 0 0 up 0 1 0 angle 53.13010235415598 ]\n";
constexpr double kEye = 10.0;

struct Shot {
    Image image;
    bool moves = false;
};

Shot shoot(const std::string& text, int w, int h, int spp, const char* shutter, int threads = 0) {
    LoadOptions lo;
    lo.threads = threads;
    if (shutter) {
        float t0 = 0, t1 = 0;
        EXPECT_EQ(std::sscanf(shutter, "%f,%f", &t0, &t1), 2);
        lo.shutter = true;
        lo.shutter_open = t0;
        lo.shutter_close = t1;
    }
    LoadResult r = load_scene_text(text, "motion.sc", lo);
    EXPECT_TRUE(r.ok()) << (r.diagnostics.empty() ? "" : r.diagnostics[0].str());
    Shot shot;
    if (!r.ok()) return shot;
    shot.moves = !r.scene->motion.empty();
    RenderJob job;
    job.width = w;
    job.height = h;
    job.sampling.spp = spp;
    job.threads = threads;
    shot.image = Image(w, h);
    render(*r.scene, job, shot.image);
    return shot;
}

double red(const Image& image, int x, int y) { return image.at(x, y).x / 255.0; }

// An emissive white object on black with no light: a pixel's value is the fraction of its samples
// whose rays hit the object (the lab's colour: emit + ambient·I_a with ambient 0).
const char* kWhite = "[ emit 1 1 1 diffuse 0 0 0 ]";

// A sphere of radius r moving along x at velocity v, seen over the shutter [t0, t1]: its centre
// sweeps [v·t0, v·t1]. The ray through the point u of the plane z = 0 (on the row y = 0) passes
// within r of the centre c exactly when |c − u| < r·√(D² + u²) / D, so its value is the part of the
// sweep within that distance of u; at the sweep's ends u = v·t0 and u = v·t1 it is half the
// plateau's. The streak's length at half its height is therefore v·(t1 − t0), in pixels
// v·(t1 − t0)·h / 10.
TEST(MotionBlur, StreakLengthIsVelocityTimesShutter) {
    const int w = 63, h = 21, spp = 1024;
    const double r = 1.0, v = 4.0, t0 = -0.5, t1 = 0.5;
    const std::string scene = std::string(kCamera) +
                              "mastersubgraph root [ trans [ velocity 4 0 0 scale 2 2 2 object sphere " + kWhite +
                              " ] ]\n";
    const Shot blurred = shoot(scene, w, h, spp, "-0.5,0.5");
    ASSERT_TRUE(blurred.moves);
    const int row = h / 2;  // its centre is y = 0
    const double pixel = 10.0 / h;
    std::vector<double> profile(w);
    for (int x = 0; x < w; ++x) profile[std::size_t(x)] = red(blurred.image, x, row);
    // The plateau, 2r / (v·(t1 − t0)) = 1/2 here (the 2 units in the middle where the whole
    // sphere's chord lies inside the sweep), from the centre pixels.
    const double plateau = (profile[w / 2 - 1] + profile[w / 2] + profile[w / 2 + 1]) / 3.0;
    const double sigma = 0.5 / std::sqrt(double(spp));  // a pixel's mean of spp hits or misses, at worst
    EXPECT_NEAR(plateau, 2.0 * r / (v * (t1 - t0)), 4.0 * sigma + 2.0 / 255.0);
    // Where the profile crosses half the plateau on each side, between pixel centres.
    auto crossing = [&](int from, int step) {
        for (int x = from; x >= 0 && x + step >= 0 && x + step < w; x += step) {
            const double a = profile[std::size_t(x)], b = profile[std::size_t(x + step)];
            if (a >= plateau / 2 && b < plateau / 2) return x + 0.5 + step * (a - plateau / 2) / (a - b);
        }
        return -1.0;
    };
    const double left = crossing(w / 2, -1), right = crossing(w / 2, +1);
    ASSERT_GE(left, 0.0);
    ASSERT_GE(right, 0.0);
    // The profile rises by one pixel's worth of the sweep per pixel (pixel / (v·Δt) of the value):
    // an error of sigma in a value moves a crossing by sigma over that slope.
    const double slope = pixel / (v * (t1 - t0));
    const double tolerance = 4.0 * std::sqrt(2.0) * (sigma + 1.0 / 255.0) / slope;
    EXPECT_NEAR(right - left, v * (t1 - t0) / pixel, tolerance);  // 8.4 pixels
    // Centred where the sweep is (t = 0 is the middle of the shutter): column w/2.
    EXPECT_NEAR((left + right) / 2.0, w / 2.0, tolerance);
    // Without a shutter the sphere stands at t = 0: its image is 2r wide, not the streak.
    const Shot still = shoot(scene, w, h, spp, nullptr);
    EXPECT_FALSE(still.moves);
    int lit = 0;
    for (int x = 0; x < w; ++x) lit += red(still.image, x, row) > 0.5;
    EXPECT_NEAR(lit, 2.0 * r / pixel, 2.0);
}

// The part of [0, sweep] (radians) during which a bar through the origin, turned by θ from the
// x axis, covers the point at polar (rho, phi): |rho·sin(phi − θ)| < half_width (the bar being
// longer than rho), i.e. phi − θ within alpha = asin(half_width / rho) of a multiple of π.
double covered_fraction(double rho, double phi, double half_width, double sweep) {
    if (rho <= half_width) return 1.0;
    const double alpha = std::asin(half_width / rho);
    double covered = 0;
    for (int k = -3; k <= 3; ++k) {
        const double lo = std::max(0.0, phi - alpha + k * kPi), hi = std::min(sweep, phi + alpha + k * kPi);
        if (hi > lo) covered += hi - lo;
    }
    return covered / sweep;
}

// A thin bar spinning about the view axis at 90 degrees per unit of time (angularrate on the trans
// block that uses it, composed with the bar's own scale in a subgraph), over the shutter [0, 1]:
// it sweeps the quarter turn from the x axis to the y axis. Each pixel's value is the part of the
// sweep during which the bar covers it: 2·asin(w / 2ρ) / (π/2) inside the quarter, 0 outside it.
TEST(MotionBlur, SpinningBarSweepsItsAngularRate) {
    const int w = 64, h = 64, spp = 256;
    const double half_width = 0.2, sweep = kPi / 2, thickness = 0.02;
    const std::string scene = std::string(kCamera) +
                              "mastersubgraph bar [ trans [ scale 9 0.4 0.02 object cube " + kWhite + " ] ]\n" +
                              "mastersubgraph root [ trans [ angularrate 0 0 1 90 subgraph bar ] ]\n";
    const Shot blurred = shoot(scene, w, h, spp, "0,1");
    ASSERT_TRUE(blurred.moves);
    const double pixel = 10.0 / h;
    // The bar's front face is thickness/2 nearer the eye than z = 0: a ray meets it at
    // (D − thickness/2) / D of the point of z = 0 that it passes through.
    const double shrink = (kEye - thickness / 2) / kEye;
    const double sigma = 0.5 / std::sqrt(double(spp));
    double sum_error = 0;
    int n = 0, inside = 0;
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            // The expected value over the pixel's area: a 6 × 6 grid of points of it.
            double expected = 0;
            double rho_centre = 0;
            for (int j = 0; j < 6; ++j) {
                for (int i = 0; i < 6; ++i) {
                    const double u = (x + (i + 0.5) / 6 - w / 2.0) * pixel * shrink;
                    const double v = (h / 2.0 - (y + (j + 0.5) / 6)) * pixel * shrink;
                    expected += covered_fraction(std::hypot(u, v), std::atan2(v, u), half_width, sweep) / 36;
                }
            }
            rho_centre = std::hypot((x + 0.5 - w / 2.0) * pixel, (h / 2.0 - y - 0.5) * pixel);
            if (rho_centre < 1.0 || rho_centre > 4.0) continue;  // near the axis a pixel spans many angles; the ends
            const double got = red(blurred.image, x, y);
            EXPECT_NEAR(got, expected, 5.0 * sigma + 2.0 / 255.0) << x << "," << y;
            sum_error += got - expected;
            ++n;
            inside += expected > 0.05;
        }
    }
    ASSERT_GT(n, 500);
    ASSERT_GT(inside, 150);  // the quarter turn is filled: a blur, not one position of the bar
    // Over all these pixels the errors average out: their mean is within a few sigma / √n, plus
    // rounding to bytes and the pixel-area quadrature (a 6 × 6 grid, 1/72 of an edge at most).
    EXPECT_NEAR(sum_error / n, 0.0, 4.0 * sigma / std::sqrt(double(n)) + 0.5 / 255.0 + 1.0 / 72.0 / 8.0);
}

// A scene that does not move is the same image, byte for byte, with and without a shutter: the
// shutter only matters where something moves.
TEST(MotionBlur, StaticSceneIsByteIdenticalWithAShutter) {
    const std::string scene = std::string(kCamera) +
                              "light [ position 3 4 6 color 1 1 1 radius 0.5 ]\n"
                              "mastersubgraph root [\n"
                              "  trans [ translate 0 -1 0 scale 8 0.2 8 object cube [ diffuse 0.8 0.8 0.8 ] ]\n"
                              "  trans [ rotate 0 1 0 30 object cylinder [ diffuse 0.9 0.2 0.1 reflect 0.3 0.3 0.3 ] ]\n"
                              "]\n";
    for (int spp : {1, 16}) {
        SCOPED_TRACE(spp);
        const Shot with = shoot(scene, 48, 32, spp, "0,2");
        const Shot without = shoot(scene, 48, 32, spp, nullptr);
        EXPECT_FALSE(with.moves);
        EXPECT_EQ(with.image.rgb, without.image.rgb);
    }
}

// The same bytes for one thread and two: each sample's time comes from the sampler, by its pixel
// and index, as every other sampled dimension. Shadows and mirror rays of a moving scene included.
TEST(MotionBlur, SameBytesForAnyThreadCount) {
    const std::string scene = std::string(kCamera) +
                              "light [ position 3 4 6 color 1 1 1 radius 0.3 ]\n"
                              "mastersubgraph spin [ trans [ scale 2 0.5 0.5 object cube [ diffuse 0.2 0.7 0.2 ] ] ]\n"
                              "mastersubgraph root [\n"
                              "  trans [ translate 0 -1.5 0 scale 10 0.2 10 object cube [ diffuse 0.8 0.8 0.8 "
                              "reflect 0.3 0.3 0.3 ] ]\n"
                              "  trans [ velocity 1.5 0.5 0 object sphere [ diffuse 0.9 0.2 0.1 ] ]\n"
                              "  trans [ translate -2 0 0 angularrate 1 1 0 120 subgraph spin ]\n"
                              "]\n";
    const Shot one = shoot(scene, 48, 32, 16, "0,1", 1);
    const Shot two = shoot(scene, 48, 32, 16, "0,1", 2);
    ASSERT_TRUE(one.moves);
    EXPECT_EQ(one.image.rgb, two.image.rgb);
    EXPECT_NE(one.image.rgb, shoot(scene, 48, 32, 16, nullptr, 2).image.rgb);  // and it is blurred
}

}  // namespace
}  // namespace whitted
