// The render session: passes give the bytes of one render, a cancelled pass leaves the last whole
// one, adaptive sampling stops where the error estimate says and nowhere else, for any threads.
#include <atomic>
#include <cmath>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "integrator/integrator.h"
#include "render/load_scene.h"
#include "render/renderer.h"
#include "session/session.h"

namespace whitted {
namespace {

// A post on a floor under a disc light (a penumbra), the sky behind (one colour: no noise at all).
constexpr const char* kPenumbra = R"(
background [ color 0.3 0.4 0.6 ]
camera [ eye 0 6 9 focus 0 0.5 0 angle 40 ]
light [ position 2 6 1 color 0.8 0.8 0.8 radius 1.2 ]
light [ ambient 0.2 0.2 0.2 ]
mastersubgraph root [
  trans [ translate 0 1.25 0 scale 0.6 2.5 0.6 object cylinder [ diffuse 0.8 0.4 0.2 ] ]
  trans [ translate 0 -0.5 0 scale 12 1 12 object cube [ diffuse 0.7 0.7 0.7 ] ]
]
)";

std::shared_ptr<const Scene> load(const char* text) {
    LoadResult r = load_scene_text(text, "penumbra.sc");
    EXPECT_TRUE(r.ok());
    return r.scene;
}

RenderJob job_of(int spp, int threads) {
    RenderJob job;
    job.width = 48;
    job.height = 36;
    job.tile_size = 8;
    job.sampling.spp = spp;
    job.threads = threads;
    return job;
}

bool same_film(const Film& a, const Film& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (std::memcmp(&a.at(x, y), &b.at(x, y), sizeof(FilmPixel)) != 0) return false;
    return true;
}

TEST(Session, PassesDoubleTheSamplesAndGiveTheBytesOfOneRender) {
    const auto scene = load(kPenumbra);
    Session session(scene, job_of(16, 2));
    EXPECT_EQ(session.pass_ends(), (std::vector<int>{1, 2, 4, 8, 16}));
    while (!session.done()) ASSERT_FALSE(session.render_pass().render.cancelled);
    // The same samples in one go, on one thread.
    const RenderJob one = job_of(16, 1);
    const auto integrator = make_integrator(*scene, one.camera_for(*scene), one.integrator);
    Film film(one.width, one.height);
    render(*integrator, one, film);
    EXPECT_TRUE(same_film(session.film(), film));
}

TEST(Session, ACancelledPassLeavesTheLastWholePass) {
    const auto scene = load(kPenumbra);
    std::atomic<bool> cancel{false};
    RenderJob job = job_of(8, 2);
    job.cancel = &cancel;
    Session session(scene, job);
    session.render_pass();
    session.render_pass();  // 2 samples per pixel
    const Film two = session.film();
    std::atomic<int> tiles{0};
    const PassStats third = session.render_pass([&](const Tile&, const Film&) {
        if (++tiles == 5) cancel = true;  // in the middle of the pass
    });
    EXPECT_TRUE(third.render.cancelled);
    EXPECT_GE(third.render.tiles_done, 5);
    EXPECT_LT(third.render.tiles_done, third.render.tiles_total);
    EXPECT_EQ(session.passes_done(), 2);
    EXPECT_EQ(session.samples_done(), 2);
    EXPECT_TRUE(same_film(session.film(), two)) << "the film shown is the last whole pass";
}

// Adaptive sampling on the penumbra scene, against a 1024-sample render of it.
class Adaptive : public ::testing::Test {
protected:
    static constexpr float kThreshold = 0.02f;
    static constexpr int kMax = 256, kMin = 16;

    static Session& run(std::unique_ptr<Session>& s, int threads) {
        RenderJob job = job_of(kMax, threads);
        job.sampling.noise_threshold = kThreshold;
        job.sampling.min_spp = kMin;
        s = std::make_unique<Session>(load(kPenumbra), job);
        while (!s->done()) s->render_pass();
        return *s;
    }
};

// The film of the first `n` samples of every pixel (as one render of n samples: the sampler is
// progressive); with another seed, an independent render of n samples.
Film first_samples(const Session& session, int n, std::uint32_t seed = 0) {
    RenderJob job = session.job();
    job.sampling.spp = n;
    job.sampling.seed = seed;
    job.sampling.noise_threshold = 0.0f;
    job.active = nullptr;
    Film film(job.width, job.height);
    render(session.integrator(), job, film);
    return film;
}

// Per pixel, its first half: what the estimate that stopped it compared with.
Film first_halves(const Session& session, const std::vector<int>& spp) {
    Film out(session.job().width, session.job().height);
    for (int n = 8; n <= 128; n *= 2) {
        const Film f = first_samples(session, n);
        for (int y = 0; y < out.height(); ++y)
            for (int x = 0; x < out.width(); ++x)
                if (spp[std::size_t(y) * std::size_t(out.width()) + std::size_t(x)] == 2 * n) out.at(x, y) = f.at(x, y);
    }
    return out;
}

TEST_F(Adaptive, FlatRegionsStopAtTheMinimumAndPenumbraeTakeMore) {
    std::unique_ptr<Session> s;
    const Session& session = run(s, 2);
    const std::vector<int> spp = session.samples_per_pixel();
    const Film& film = session.film();
    const Film noise_a = first_samples(session, kMin, 1), noise_b = first_samples(session, kMin, 2);
    int sky = 0, noisy = 0, noisy_more = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) {
            const int n = spp[std::size_t(y) * 48 + std::size_t(x)];
            ASSERT_TRUE(n == kMin || n == 32 || n == 64 || n == 128 || n == kMax) << n;
            const glm::vec3 v = film.at(x, y).value();
            // Sky: every sample the background colour; a zero error estimate stops it at once.
            if (glm::all(glm::lessThan(glm::abs(v - glm::vec3(0.3f, 0.4f, 0.6f)), glm::vec3(1e-6f)))) {
                bool sky_around = true;  // and its neighbours' too (the 3 x 3 rule)
                for (int ny = std::max(0, y - 1); ny <= std::min(35, y + 1); ++ny)
                    for (int nx = std::max(0, x - 1); nx <= std::min(47, x + 1); ++nx)
                        sky_around &= glm::all(glm::lessThan(
                            glm::abs(film.at(nx, ny).value() - glm::vec3(0.3f, 0.4f, 0.6f)), glm::vec3(1e-6f)));
                if (sky_around) {
                    ++sky;
                    EXPECT_EQ(n, kMin) << "sky pixel " << x << "," << y;
                }
            }
            // Noisy: two independent 16-sample renders (other seeds) differ there by more than
            // twice the threshold (normalised as the estimate is).
            const glm::vec3 a = noise_a.at(x, y).value(), b = noise_b.at(x, y).value(), d = glm::abs(a - b);
            if ((d.x + d.y + d.z) / (1e-4f + std::sqrt(a.x + a.y + a.z)) > 2 * kThreshold) {
                ++noisy;
                noisy_more += n > kMin;
            }
        }
    EXPECT_GT(sky, 100);
    EXPECT_GT(noisy, 50);
    EXPECT_GT(noisy_more, noisy * 9 / 10) << "noisy pixels (the penumbra, the post's edges) take more than the minimum";
}

TEST_F(Adaptive, PixelsThatStoppedHaveAnEstimateBelowTheThresholdAndATrueErrorNearIt) {
    std::unique_ptr<Session> s;
    const Session& session = run(s, 2);
    const std::vector<int> spp = session.samples_per_pixel();
    const Film& film = session.film();
    // The reference: 1024 samples per pixel (its own error is a few times below what is measured).
    RenderJob ref = job_of(1024, 2);
    const auto integrator = make_integrator(session.scene(), ref.camera_for(session.scene()), ref.integrator);
    Film truth(ref.width, ref.height);
    render(*integrator, ref, truth);
    const Film before = first_halves(session, spp);
    double true_error = 0, estimated = 0;
    int stopped = 0;
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 48; ++x) {
            if (spp[std::size_t(y) * 48 + std::size_t(x)] == kMax) continue;
            const float estimate = pixel_error_estimate(film.at(x, y), before.at(x, y));
            EXPECT_LT(estimate, kThreshold) << x << "," << y;
            if (estimate < kThreshold / 4) continue;  // the sky, full light: (almost) no noise to measure
            ++stopped;
            estimated += estimate;
            const glm::vec3 v = film.at(x, y).value(), t = truth.at(x, y).value();
            const glm::vec3 d = glm::abs(v - t);
            true_error += (d.x + d.y + d.z) / (1e-4 + std::sqrt(t.x + t.y + t.z));
        }
    ASSERT_GT(stopped, 100) << "noisy pixels that stopped before the maximum";
    // The stopped pixels' true error is below the threshold on average, and the estimate is an
    // honest one: within a factor of a few of the true error, neither blind to noise nor so
    // pessimistic that nothing stops (a plain variance overstates stratified samples' error tenfold).
    EXPECT_LT(true_error / stopped, kThreshold);
    EXPECT_GT(true_error / estimated, 0.25);
    EXPECT_LT(true_error / estimated, 2.0);
    // |mean − even mean| is half |mean of the even − mean of the odd samples|: its expectation is
    EXPECT_LT(true_error / stopped, 1.5 * kThreshold);
}

TEST_F(Adaptive, TheSameForAnyThreadCount) {
    std::unique_ptr<Session> a, b;
    run(a, 1);
    run(b, 2);
    EXPECT_TRUE(same_film(a->film(), b->film()));
    EXPECT_EQ(a->samples_per_pixel(), b->samples_per_pixel());
}

}  // namespace
}  // namespace whitted
