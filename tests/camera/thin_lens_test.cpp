// Depth of field (scene-format.md §9.1): through a thin lens of diameter A focused at distance F, a
// point at depth d is spread over a disc of diameter A·|d − F|/d in the plane in focus. Rendered:
// a small glowing sphere out of focus lights exactly the pixels of that disc (grown by the sphere's
// own image), and the spread of its light has the disc's second moment.
#include <cmath>

#include <gtest/gtest.h>

#include "camera/camera.h"
#include "render/renderer.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

constexpr int kSize = 96;
constexpr float kHalfFov = 0.3490658504f;  // 20°
constexpr float kAperture = 1.6f, kFocus = 5.0f;

Camera lens_camera() {
    Camera c;
    c.eye = glm::vec3(0.0f);
    c.forward = {0, 0, -1};
    c.right = {1, 0, 0};
    c.up = {0, 1, 0};
    c.tan_half_fov = std::tan(kHalfFov);
    c.lens_radius = kAperture / 2;
    c.focal_distance = kFocus;
    return c;
}

TEST(ThinLens, EveryLensRayPassesThroughThePinholeRaysPointInFocus) {
    const Camera cam = lens_camera();
    Camera pinhole = cam;
    pinhole.lens_radius = 0;
    for (float x : {3.5f, 50.0f, 90.25f})
        for (glm::vec2 lens : {glm::vec2(0.1f, 0.9f), glm::vec2(0.7f, 0.2f), glm::vec2(0.99f, 0.5f)}) {
            const Ray p = pinhole.generate_ray(kSize, kSize, x, 20.0f, lens);
            const Ray r = cam.generate_ray(kSize, kSize, x, 20.0f, lens);
            const glm::vec3 focus = p.at(kFocus / -p.direction.z);  // pinhole ray at the plane z = −F
            const glm::vec3 there = r.at((kFocus + r.origin.z) / -r.direction.z);
            EXPECT_NEAR(glm::length(there - focus), 0.0f, 1e-5f);
            EXPECT_NEAR(r.origin.z, 0.0f, 1e-7f);  // the lens lies in the eye's plane
            EXPECT_LE(glm::length(r.origin), kAperture / 2 + 1e-6f);
        }
    // The lens centre is the pinhole, to the bit.
    const Ray c = cam.generate_ray(kSize, kSize, 10.5f, 70.5f, glm::vec2(0.5f));
    const Ray p = pinhole.generate_ray(kSize, kSize, 10.5f, 70.5f, glm::vec2(0.5f));
    EXPECT_EQ(c.origin, p.origin);
    EXPECT_EQ(c.direction, p.direction);
}

struct Blur {
    double outside_lit = 0;   // light in pixels beyond the disc's reach (must be none)
    int inside_dark = 0;      // pixels well inside the disc that got no light (must be none)
    double second_moment = 0; // E[ρ²] of the light about the image centre, in pixels²
    double hits = 0;          // samples that saw the sphere
};

// A glowing sphere of radius s at depth d on the axis, rendered at spp samples per pixel.
Blur render_blur(float d, float s, int spp) {
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, test::translate_scale({0, 0, -d}, glm::vec3(2 * s)), test::emitter(glm::vec3(1.0f)));
    const Scene scene = b.build();
    RenderJob job;
    job.width = job.height = kSize;
    job.camera = lens_camera();
    job.sampling.spp = spp;
    job.threads = 2;
    const auto integrator = make_integrator(scene, *job.camera, job.integrator);
    Film film(kSize, kSize);
    render(*integrator, job, film);

    // In pixels: the plane in focus is 2·F·tan(fov/2) tall.
    const double px_per_unit = kSize / (2.0 * kFocus * std::tan(kHalfFov));
    const double r = 0.5 * kAperture * std::abs(d - kFocus) / d * px_per_unit;  // the blur disc
    const double sr = s * kFocus / d * px_per_unit;                               // the sphere's own image
    Blur out;
    double m2 = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double v = film.at(x, y).value().x;
            const double dx = x + 0.5 - kSize / 2.0, dy = y + 0.5 - kSize / 2.0, rho = std::sqrt(dx * dx + dy * dy);
            if (rho > r + sr + 1.0) out.outside_lit += v;
            if (rho < r - sr - 1.0 && v == 0.0) ++out.inside_dark;
            out.hits += v * spp;
            m2 += v * spp * (dx * dx + dy * dy);
        }
    out.second_moment = m2 / out.hits;
    // The expected second moment: the blur disc and the sphere's disc (uniform discs, E[ρ²] = R²/2
    // each) plus a pixel's spread (1/12 per axis).
    const double want = (r * r + sr * sr) / 2 + 1.0 / 6;
    // Its standard error: the variance of ρ² over a uniform disc of radius r + sr is (r + sr)⁴/12.
    const double se = std::pow(r + sr, 2) / std::sqrt(12.0) / std::sqrt(out.hits);
    EXPECT_NEAR(out.second_moment, want, 4 * se + 0.03 * want)
        << "depth " << d << ": blur radius " << r << " px, sphere " << sr << " px";
    return out;
}

TEST(ThinLens, AnOutOfFocusPointSpreadsOverTheThinLensDisc) {
    for (auto [d, s] : {std::pair{10.0f, 0.3f}, std::pair{2.5f, 0.075f}}) {
        const Blur b = render_blur(d, s, 256);
        EXPECT_EQ(b.outside_lit, 0.0) << "depth " << d;
        EXPECT_EQ(b.inside_dark, 0) << "depth " << d;
        EXPECT_GT(b.hits, 5000) << "depth " << d;
    }
}

TEST(ThinLens, InFocusStaysSharp) {
    // The same sphere in the plane in focus: only the pixels of its own image are lit.
    test::SceneBuilder b;
    b.add(ShapeKind::Sphere, test::translate_scale({0, 0, -kFocus}, glm::vec3(0.4f)), test::emitter(glm::vec3(1.0f)));
    const Scene scene = b.build();
    RenderJob job;
    job.width = job.height = kSize;
    job.camera = lens_camera();
    job.sampling.spp = 64;
    Image sharp(kSize, kSize), pinhole(kSize, kSize);
    render(scene, job, sharp);
    job.camera->lens_radius = 0;
    render(scene, job, pinhole);
    int differ = 0, lit = 0;
    for (std::size_t i = 0; i < sharp.rgb.size(); ++i) {
        differ += std::abs(int(sharp.rgb[i]) - int(pinhole.rgb[i])) > 16;
        lit += pinhole.rgb[i] > 0;
    }
    EXPECT_GT(lit, 300);
    // Only the silhouette's pixels may differ a little: the sphere has depth (radius 0.2 at 5).
    EXPECT_LT(differ, lit / 4);
}

}  // namespace
}  // namespace whitted
