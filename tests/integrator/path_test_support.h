#pragma once
// Statistics for the path tracer's tests: a sample mean with its standard error, the per-sample
// radiance estimates of one ray, and the furnace check of a rendered image.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "integrator/path_integrator.h"
#include "render/renderer.h"

namespace whitted::test {

struct Stats {
    double mean = 0, se = 0;  // the mean and its standard error
};

inline Stats stats_of(const std::vector<double>& v) {
    double s = 0, s2 = 0;
    for (double x : v) s += x, s2 += x * x;
    const double n = double(v.size()), m = s / n;
    return {m, std::sqrt(std::max(0.0, s2 / n - m * m) / (n - 1))};
}

// The per-sample estimates of one ray's radiance (channel 0).
inline std::vector<double> samples_of(const PathIntegrator& path, const Ray& ray, int n, std::uint32_t pixel = 0) {
    const Sampler sampler(1, n);
    RayCounts counts;
    std::vector<double> v;
    for (int i = 0; i < n; ++i) v.push_back(path.radiance(ray, {pixel, 0, std::uint32_t(i)}, sampler, counts).x);
    return v;
}

// The camera inside a closed emitting, reflecting surface sees `want` (e / (1 − albedo)) in every
// pixel of a small path-traced image (256 samples per pixel): the image's mean within 4 standard
// errors, each pixel within 5 of one pixel's spread.
inline void expect_furnace_image(const Scene& scene, double want) {
    RenderJob job;
    job.width = 12;
    job.height = 10;
    job.integrator = {RenderMode::Path, 64};
    job.sampling.spp = 256;
    const auto integrator = make_integrator(scene, scene.data.camera, job.integrator);
    Film film(job.width, job.height);
    const RenderStats rs = render(*integrator, job, film);
    EXPECT_EQ(rs.rays.rejected, 0u);
    std::vector<double> pixels;
    for (int y = 0; y < job.height; ++y)
        for (int x = 0; x < job.width; ++x) pixels.push_back(film.at(x, y).value().x);
    const Stats s = stats_of(pixels);
    const double sd = s.se * std::sqrt(double(pixels.size()));  // one pixel's spread (256 samples)
    EXPECT_NEAR(s.mean, want, 4 * s.se + 1e-3);
    for (double p : pixels) EXPECT_NEAR(p, want, 5 * sd + 1e-3);
    EXPECT_GT(sd, 0.0);
}

}  // namespace whitted::test
