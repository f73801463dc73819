// A converged-reference test in the spirit of Mitsuba 3's: the Cornell box (scenes/features/
// cornell_box.sc) rendered once at 4096 samples per pixel and checked in as a PFM; a render with
// other sample values (another seed) and far fewer samples must agree with it pixel by pixel
// within its own measured noise (a z-test), and its error must fall as 1/√spp.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "integrator/path_integrator.h"
#include "render/load_scene.h"

namespace whitted {
namespace {

constexpr int kSize = 24, kReferenceSpp = 4096;
const std::string kScene = std::string(WHITTED_SOURCE_DIR) + "/scenes/features/cornell_box.sc";
const std::string kReference = std::string(WHITTED_SOURCE_DIR) + "/tests/integrator/reference/cornell_box_4096spp.pfm";

// A little-endian RGB PFM (what whitted writes): rows bottom to top.
std::vector<glm::vec3> read_pfm(const std::string& path, int& w, int& h) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    float scale = 0;
    in >> magic >> w >> h >> scale;
    in.get();
    std::vector<glm::vec3> rows(std::size_t(w) * std::size_t(h));
    if (magic != "PF" || scale >= 0) return {};
    in.read(reinterpret_cast<char*>(rows.data()), std::streamsize(rows.size() * sizeof(glm::vec3)));
    if (!in) return {};
    std::vector<glm::vec3> top_down(rows.size());
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) top_down[std::size_t(y) * w + x] = rows[std::size_t(h - 1 - y) * w + x];
    return top_down;
}

struct PixelStats {
    std::vector<glm::dvec3> mean, var;  // per pixel: the mean of the samples and their variance
};

// spp samples of every pixel, seeded apart from the reference's, one by one (so that the spread
// of each pixel's samples is known).
PixelStats render_samples(const Scene& scene, int spp, std::uint32_t seed) {
    const PathIntegrator path(scene, scene.data.camera, 64);
    const Sampler sampler(1, spp, seed);
    PixelStats out;
    RayCounts counts;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            glm::dvec3 s(0.0), s2(0.0);
            for (int i = 0; i < spp; ++i) {
                const SampleKey key{std::uint32_t(x), std::uint32_t(y), std::uint32_t(i)};
                const glm::vec2 at = sampler.pixel_offset(key);
                const Ray ray = scene.data.camera.generate_ray(kSize, kSize, float(x) + at.x, float(y) + at.y,
                                                               sampler.get2d(key, dimension::kLens));
                const glm::dvec3 c(path.radiance(ray, key, sampler, counts));
                s += c;
                s2 += c * c;
            }
            const glm::dvec3 m = s / double(spp);
            out.mean.push_back(m);
            out.var.push_back(glm::max(s2 / double(spp) - m * m, glm::dvec3(0.0)) * (double(spp) / (spp - 1)));
        }
    EXPECT_EQ(counts.rejected, 0u);
    return out;
}

class PathReference : public ::testing::Test {
protected:
    void SetUp() override {
        loaded_ = load_scene(kScene);
        ASSERT_TRUE(loaded_.ok());
        int w = 0, h = 0;
        reference_ = read_pfm(kReference, w, h);
        ASSERT_EQ(w, kSize) << "missing or unreadable " << kReference << " (scripts/update-path-reference.sh)";
        ASSERT_EQ(h, kSize);
        ASSERT_EQ(reference_.size(), std::size_t(kSize * kSize));
    }
    LoadResult loaded_;
    std::vector<glm::vec3> reference_;
};

TEST_F(PathReference, A256SampleRenderAgreesWithTheConvergedOneWithinItsNoise) {
    const int spp = 256;
    const PixelStats r = render_samples(*loaded_.scene, spp, 1);
    // Each pixel's noise measured by an independent render (another seed): a path tracer's sample
    // mean and sample spread rise together with a rare bright path, so measured from the same
    // samples they would skew z toward the dark side.
    const PixelStats noise = render_samples(*loaded_.scene, spp, 3);
    int far = 0, n = 0;
    double z_sum = 0, diff_sum = 0, var_sum = 0;
    for (std::size_t p = 0; p < reference_.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            // The reference's own noise: the same per-sample variance over 4096 samples.
            const double var = noise.var[p][c] / spp + noise.var[p][c] / kReferenceSpp;
            const double d = r.mean[p][c] - reference_[p][c];
            diff_sum += d;
            var_sum += var;
            if (!(var > 0)) {
                EXPECT_NEAR(d, 0.0, 1e-6);
                continue;
            }
            const double z = d / std::sqrt(var);
            far += std::abs(z) > 4;
            z_sum += z;
            ++n;
        }
    ASSERT_GT(n, 1000);
    // |z| > 4 has probability 6e-5 for normal errors; means of 256 paths have heavier tails.
    EXPECT_LE(far, n / 200 + 2) << "pixels far outside their noise";
    // No bias: the image's total radiance agrees within 4 standard errors, and z averages to 0.
    EXPECT_NEAR(diff_sum, 0.0, 4 * std::sqrt(var_sum));
    EXPECT_NEAR(z_sum / n, 0.0, 4.0 / std::sqrt(double(n)));
}

TEST_F(PathReference, ErrorFallsAsOneOverTheSquareRootOfTheSamples) {
    auto rmse = [&](int spp) {
        const PixelStats r = render_samples(*loaded_.scene, spp, 2);
        double sq = 0;
        for (std::size_t p = 0; p < reference_.size(); ++p) {
            const glm::dvec3 d = r.mean[p] - glm::dvec3(reference_[p]);
            sq += glm::dot(d, d);
        }
        return std::sqrt(sq / double(reference_.size() * 3));
    };
    const double e16 = rmse(16), e256 = rmse(256);
    // 16 times the samples: 1/√spp says a quarter of the error (the reference's own error, a
    // sixteenth of e16 at 4096 samples, is small beside both).
    EXPECT_GT(e16 / e256, 2.5) << e16 << " " << e256;
    EXPECT_LT(e16 / e256, 8.0) << e16 << " " << e256;
}

}  // namespace
}  // namespace whitted
