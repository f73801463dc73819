// Motion blur over a shutter (docs/animation.md): each sample takes its own time in the shutter
// interval, and moving objects (velocity, angularrate) are met where they are then. The blur is
// checked against closed forms of the pinhole projection; static scenes are untouched.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "accel/scene.h"
#include "render/load_scene.h"
#include "integrator/render_mode.h"
#include "render/renderer.h"
#include "session/render_settings.h"

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

// only_row >= 0: that row of the image alone.
Shot shoot(const std::string& text, int w, int h, int spp, const char* shutter, int threads = 0,
           RenderMode mode = RenderMode::Whitted, int only_row = -1) {
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
    job.integrator.mode = mode;
    if (only_row >= 0) job.region = PixelRegion{0, only_row, w, only_row + 1};
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
// The same in path mode, where the emitter seen is its emission (1) and nothing else.
class StreakLength : public ::testing::TestWithParam<RenderMode> {};

TEST_P(StreakLength, IsVelocityTimesShutter) {
    const int w = 63, h = 21, spp = 1024;
    const double r = 1.0, v = 4.0, t0 = -0.5, t1 = 0.5;
    const std::string scene = std::string(kCamera) +
                              "mastersubgraph root [ trans [ velocity 4 0 0 scale 2 2 2 object sphere " + kWhite +
                              " ] ]\n";
    const Shot blurred = shoot(scene, w, h, spp, "-0.5,0.5", 0, GetParam());
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
    const Shot still = shoot(scene, w, h, spp, nullptr, 0, GetParam());
    EXPECT_FALSE(still.moves);
    int lit = 0;
    for (int x = 0; x < w; ++x) lit += red(still.image, x, row) > 0.5;
    EXPECT_NEAR(lit, 2.0 * r / pixel, 2.0);
}

INSTANTIATE_TEST_SUITE_P(MotionBlur, StreakLength, ::testing::Values(RenderMode::Whitted, RenderMode::Path),
                         [](const auto& info) { return std::string(render_mode_name(info.param)); });

// Path mode: a floor lit by an emissive sphere that moves during the shutter. A sphere of radius r
// and radiance L whose centre is at d from a point of a plane, wholly above it, gives that point
// the irradiance of a point source: E = π L r² cos θ / |d|², cos θ = height / |d|. The diffuse
// floor (f = kd / π) shows kd L r² height / |d|³ at each instant, and over the shutter the mean of
// that over the sphere's positions (by quadrature here, with the pixel's area). A moving emitter
// is not one of the lights sampled (its position differs at every sample's time): every sample is
// the cosine-sampled direction that meets it or not, kd L or 0, so a pixel's value has the standard
// deviation kd · sqrt(p (1 − p) / spp) with p = its value / kd.
TEST(MotionBlur, PathModeFloorLitByAMovingEmitterIsTheTimeAverageOfItsLight) {
    const int w = 40, h = 40, spp = 256;
    const double r = 1.0, height = 1.5, kd = 0.8, v = 4.0, x0 = -2.0;
    const std::string scene = std::string(kCamera) +
                              "mastersubgraph root [\n"
                              "  trans [ translate 0 0 -0.1 scale 40 40 0.2 object cube [ diffuse 0.8 0.8 0.8 ] ]\n"
                              "  trans [ translate -2 0 1.5 velocity 4 0 0 scale 2 2 2 object sphere [ emit 1 1 1 "
                              "diffuse 0 0 0 ] ]\n"
                              "]\n";
    const double pixel = 10.0 / h;
    // The floor's expected value at pixel (x, y) with the sphere's centre over [x0, x0 + sweep].
    auto expected_at = [&](int x, int y, double sweep) {
        constexpr int kArea = 3, kTimes = 64;
        double sum = 0;
        for (int j = 0; j < kArea; ++j)
            for (int i = 0; i < kArea; ++i)
                for (int k = 0; k < kTimes; ++k) {
                    const double px = (x + (i + 0.5) / kArea - w / 2.0) * pixel;
                    const double py = (h / 2.0 - (y + (j + 0.5) / kArea)) * pixel;
                    const double cx = x0 + sweep * (k + 0.5) / kTimes;
                    const double d = std::sqrt((cx - px) * (cx - px) + py * py + height * height);
                    sum += kd * r * r * height / (d * d * d);
                }
        return sum / (kArea * kArea * kTimes);
    };
    // Every pixel of the rows the sphere never hides from the camera (its sweep projects within
    // |y| < 10/8.5 r) against the closed form; the errors' mean within 4 standard errors, plus the
    // rounding to bytes and the quadrature's error (midpoint rules on smooth integrands, below 1e-3
    // of these values), and the mean of the squared errors over those variances: at most 1 for the
    // right image (the sampler's stratified samples do better than independent ones), its standard
    // error √(2/n), 0.04 here. The still sphere is a sampled light (multiple importance sampling
    // with the BSDF's directions): its noise is below the BSDF's alone, which bounds it.
    auto check = [&](const Image& image, double sweep) {
        double sum_error = 0, sum_var = 0, chi2 = 0;
        int n = 0;
        for (int y = 0; y < h; ++y) {
            if (std::abs((h / 2.0 - (y + 0.5)) * pixel) < 1.3) continue;
            for (int x = 0; x < w; ++x) {
                const double expected = expected_at(x, y, sweep), got = red(image, x, y);
                const double p = expected / kd, sigma = kd * std::sqrt(p * (1 - p) / spp);
                EXPECT_NEAR(got, expected, 5.0 * sigma + 1.0 / 255.0) << x << "," << y;
                sum_error += got - expected;
                sum_var += sigma * sigma;
                chi2 += (got - expected) * (got - expected) / (sigma * sigma);
                ++n;
            }
        }
        ASSERT_GT(n, 600);
        EXPECT_NEAR(sum_error / n, 0.0, 4.0 * std::sqrt(sum_var) / n + 0.5 / 255.0 + 1e-3 * 0.2);
        EXPECT_LT(chi2 / n, 1.3);
    };
    const Shot blurred = shoot(scene, w, h, spp, "0,1", 0, RenderMode::Path);
    ASSERT_TRUE(blurred.moves);
    check(blurred.image, v);
    // Without a shutter the sphere stands at x = -2 (time 0), sampled as a light.
    const Shot still = shoot(scene, w, h, spp, nullptr, 0, RenderMode::Path);
    EXPECT_FALSE(still.moves);
    check(still.image, 0.0);
    // The two differ by more than the tolerances: the sweep's light reaches the right-hand side.
    EXPECT_GT(expected_at(w - 8, 6, v), 1.5 * expected_at(w - 8, 6, 0.0));
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

// A textured cylinder spinning about its own axis: its outline stands still, its texture moves
// under it. The texture is two texels, white then black, read bilinearly between their centres
// (§8): the value at s is 1 − 2·(the distance from s to 0.25 around the unit circle). A point of
// the side seen from the eye at azimuth φ = atan2(z, x) in the world shows, at time t, the object
// point turned back by the angle rate·t; a right-handed turn about +y by θ takes azimuth φ to
// φ − θ (z toward x), so the object point's azimuth is φ + rate·t and u = 0.5 − (φ + rate·t) / 2π
// there; lit by a light at the eye it shows texel · (n · l). Over the shutter [0, 1] at 180 degrees
// per unit of time each pixel is that averaged over half a turn, here by quadrature over the
// pixel's width and the time.
TEST(MotionBlur, SpinningTexturedCylinderBlursItsTextureByItsAngularRate) {
    const std::string texture = ::testing::TempDir() + "/whitted_spin_stripes.ppm";
    {
        std::FILE* f = std::fopen(texture.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        const unsigned char texels[6] = {255, 255, 255, 0, 0, 0};
        std::fprintf(f, "P6\n2 1\n255\n");
        std::fwrite(texels, 1, sizeof texels, f);
        std::fclose(f);
    }
    const int w = 41, h = 41, spp = 1024;
    const double radius = 4.0, rate = kPi;
    const std::string scene = std::string(kCamera) + "light [ position 0 0 10 color 1 1 1 ]\n" +
                              "mastersubgraph root [ trans [ angularrate 0 1 0 180 scale 8 8 8 object cylinder "
                              "[ diffuse 1 1 1 specular 0 0 0 texture " + texture + " 1 1 ] ] ]\n";
    const int row = h / 2;  // y = 0 through its centre
    const Shot blurred = shoot(scene, w, h, spp, "0,1", 0, RenderMode::Whitted, row);
    const Shot still = shoot(scene, w, h, spp, nullptr, 0, RenderMode::Whitted, row);
    ASSERT_TRUE(blurred.moves);
    const double pixel = 10.0 / h;
    auto texel = [](double s) {
        s -= std::floor(s);
        const double d = std::abs(s - 0.25);
        return 1.0 - 2.0 * std::min(d, 1.0 - d);
    };
    // The expected value of column x with the cylinder turned through [0, sweep] radians.
    auto expected_at = [&](int x, double sweep, bool& on_cylinder) {
        constexpr int kWidth = 8, kTimes = 64;
        double sum = 0;
        on_cylinder = true;
        for (int i = 0; i < kWidth; ++i) {
            const double a = (x + (i + 0.5) / kWidth - w / 2.0) * pixel;  // the ray through (a, 0, 0)
            const glm::dvec3 eye(0, 0, kEye), d = glm::normalize(glm::dvec3(a, 0, -kEye));
            // |eye + s·d|² = R² in x and z: s² (dx² + dz²) + 2 s (ez dz) + ez² − R² = 0.
            const double qa = d.x * d.x + d.z * d.z, qb = 2 * eye.z * d.z, qc = eye.z * eye.z - radius * radius;
            const double disc = qb * qb - 4 * qa * qc;
            if (disc <= 0) {
                on_cylinder = false;
                return 0.0;
            }
            const glm::dvec3 p = eye + d * ((-qb - std::sqrt(disc)) / (2 * qa));
            const glm::dvec3 n = glm::dvec3(p.x, 0, p.z) / radius, l = glm::normalize(eye - p);
            const double phi = std::atan2(p.z, p.x);
            double mean = 0;
            for (int k = 0; k < kTimes; ++k)
                mean += texel(0.5 - (phi + sweep * (k + 0.5) / kTimes) / (2 * kPi)) / kTimes;
            sum += mean * std::max(0.0, glm::dot(n, l)) / kWidth;
        }
        return sum;
    };
    const double sigma = 0.5 / std::sqrt(double(spp));
    int checked = 0, apart = 0;
    for (int x = 0; x < w; ++x) {
        bool on = false;
        const double want = expected_at(x, rate, on), want_still = expected_at(x, 0.0, on);
        // The outline's pixels mix the cylinder with the black around it: left out.
        if (!on) continue;
        const double tolerance = 5.0 * sigma + 2.0 / 255.0;
        EXPECT_NEAR(red(blurred.image, x, row), want, tolerance) << x;
        EXPECT_NEAR(red(still.image, x, row), want_still, tolerance) << x;
        ++checked;
        apart += std::abs(want - want_still) > 2.0 * tolerance;
    }
    EXPECT_GT(checked, 20);
    EXPECT_GT(apart, 5);  // the blur is told from the still texture, not within the tolerance of it
}

// A filtered texture on a moving floor (--texture-filter trilinear or ewa, one sample per pixel):
// the footprint is taken where the floor is at the sample's time. A shutter of no length at time 2
// shows the floor where the scene at --time 2 has it, so the two images must agree (up to the
// rounding of the moving placement's matrix, computed at the shutter's time rather than at the
// load): the same texels, read over the same footprints, at the same mip levels.
TEST(MotionBlur, FilteredTexturesFollowAMovingObject) {
    const std::string texture = ::testing::TempDir() + "/whitted_moving_checker.ppm";
    {
        std::FILE* f = std::fopen(texture.c_str(), "wb");
        ASSERT_NE(f, nullptr);
        std::fprintf(f, "P6\n8 8\n255\n");
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 8; ++x)
                for (int c = 0; c < 3; ++c) std::fputc((x + y) % 2 ? 255 : 0, f);
        std::fclose(f);
    }
    const std::string scene = "camera [ eye 0 1 6 focus 0 0 -10 up 0 1 0 angle 50 ]\n"
                              "light [ type directional direction 0 -1 0 color 1 1 1 ]\n"
                              "mastersubgraph root [ trans [ translate 0 -0.1 0 velocity 1.3 0 0.7 scale 40 0.2 40 "
                              "object cube [ diffuse 1 1 1 texture " + texture + " 20 20 ] ] ]\n";
    for (const char* filter : {"trilinear", "ewa"}) {
        SCOPED_TRACE(filter);
        auto render_with = [&](float time, const char* shutter, bool& moves) {
            RenderSettings s;
            s.texture_filter = filter;
            s.time = time;
            if (shutter) s.shutter = shutter;
            s.width = 64;
            s.height = 48;
            EXPECT_EQ(validate(s), "");
            LoadResult r = load_scene_text(scene, "moving_floor.sc", make_load_options(s));
            EXPECT_TRUE(r.ok());
            Image image(s.width, s.height);
            if (!r.ok()) return image;
            moves = !r.scene->motion.empty();
            render(*r.scene, make_render_job(s), image);
            return image;
        };
        bool moves = false, still_moves = true;
        const Image shuttered = render_with(0.0f, "2,2", moves);
        const Image still = render_with(2.0f, nullptr, still_moves);
        ASSERT_TRUE(moves);
        ASSERT_FALSE(still_moves);
        int off = 0, worst = 0;
        for (std::size_t i = 0; i < still.rgb.size(); ++i) {
            const int d = std::abs(int(still.rgb[i]) - int(shuttered.rgb[i]));
            worst = std::max(worst, d);
            off += d > 2;
        }
        // A few texels may round the other way where a matrix differs in its last bits.
        EXPECT_LE(off, int(still.rgb.size() / 200)) << "worst " << worst;
    }
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
