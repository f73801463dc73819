// Path mode's caustics (integrator/caustic_integrator.h): a glass ball's focus where paraxial optics
// puts it, the flux through it conserved, a mirror's caustic at the brightness of the mirror image of
// the light, the same bytes for any thread count, a photon pass that stops when cancelled, scenes
// without such paths left to the path tracer alone, and the error falling at the expected rate.
#include <atomic>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "integrator/caustic_integrator.h"
#include "integrator/path_integrator.h"
#include "render/load_scene.h"
#include "render/renderer.h"
#include "sampler/warp.h"
#include "session/session.h"

namespace whitted {
namespace {

std::shared_ptr<const Scene> load(const std::string& text) {
    LoadResult r = load_scene_text(text, "caustic.sc");
    EXPECT_TRUE(r.ok());
    for (const Diagnostic& d : r.diagnostics) ADD_FAILURE() << d.message;
    return r.scene;
}

// A glass ball of radius 1 (ior 1.5, passing everything: §9.2 has no Fresnel term) at the origin, a
// spotlight of half-angle `aperture` degrees at (0, 10, 0) shining down on it (inverse-square
// falloff, no spot falloff), a diffuse floor whose top is at y = −floor_depth.
std::string ball_scene(float aperture, float floor_depth) {
    return "camera [ eye 0 3 12 focus 0 -1 0 angle 40 ]\n"
           "light [ type spotlight position 0 10 0 direction 0 -1 0 aperture " + std::to_string(aperture) +
           " exponent 0 color 1 1 1 function 0 0 1 ]\n"
           "mastersubgraph root [\n"
           "  trans [ scale 2 2 2 object sphere [ diffuse 0 0 0 transparent 1 1 1 ior 1.5 ] ]\n"
           "  trans [ translate 0 " + std::to_string(-floor_depth - 0.5f) +
           " 0 scale 60 1 60 object cube [ diffuse 0.8 0.8 0.8 ] ]\n"
           "]\n";
}

// Photons traced for `photons` samples of one pass, at most `bounces` surfaces deep.
std::unique_ptr<CausticIntegrator> photon_pass(const Scene& scene, int photons, int bounces, int threads = 2) {
    CausticSettings c;
    c.max_bounces = bounces;
    c.photons_per_sample = photons;
    auto integrator = std::make_unique<CausticIntegrator>(scene, scene.data.camera, c);
    SampleRange range;
    range.begin = 0;
    range.end = 1;
    range.threads = threads;
    EXPECT_TRUE(integrator->prepare(range));
    return integrator;
}

TEST(Caustics, GlassBallFocusesWhereParaxialOpticsSays) {
    // A ball lens has both principal planes at its centre and f = nR / (2(n − 1)) = 1.5 from it; the
    // light at s = 10 is imaged at s' = 1 / (1/f − 1/s) below the centre. A narrow cone (0.5°: rays
    // within 0.09 of the axis, paraxial to 0.5%, checked by tracing the marginal ray exactly) meets
    // the centre plane in a disc of radius h = s tan θ and converges to s'; on a floor at depth D
    // the photons fill a disc of radius ρ = h |D − s'| / s', whose RMS radius is ρ/√2 (uniform
    // directions in so narrow a cone are uniform over that disc to 1e-5).
    const double n = 1.5, R = 1, s = 10, f = n * R / (2 * (n - 1)), s_image = 1 / (1 / f - 1 / s);
    const double theta = 0.5 * kPi / 180, h = s * std::tan(theta);
    for (const double depth : {6.0, 3.0}) {
        SCOPED_TRACE(depth);
        const auto scene = load(ball_scene(0.5f, float(depth)));
        // Three surfaces: into the ball, out of it, the floor (stored there, then no further).
        const auto caustic = photon_pass(*scene, 20000, 3);
        const auto& photons = caustic->photon_map().photons();
        ASSERT_EQ(photons.size(), 20000u);  // every photon of the cone lands on the floor
        double r2 = 0, sx = 0, sz = 0;
        for (const Photon& p : photons) {
            EXPECT_NEAR(p.position.y, -depth, 1e-3);
            r2 += p.position.x * p.position.x + p.position.z * p.position.z;
            sx += p.position.x, sz += p.position.z;
        }
        const double N = double(photons.size());
        const double rho = h * std::abs(depth - s_image) / s_image;
        // The mean square radius of N points uniform in a disc has a relative standard error of
        // 0.577 / √N (0.4% here); the RMS half that. Paraxial error 0.5%, sampling 4 · 0.2%.
        EXPECT_NEAR(std::sqrt(r2 / N), rho / std::sqrt(2.0), 0.014 * rho);
        // The peak on the axis: the centroid within 4 standard errors (ρ/2 / √N per coordinate).
        EXPECT_NEAR(sx / N, 0.0, 4 * 0.5 * rho / std::sqrt(N));
        EXPECT_NEAR(sz / N, 0.0, 4 * 0.5 * rho / std::sqrt(N));
    }
}

TEST(Caustics, FluxThroughTheBallIsConservedOnTheFloor) {
    // The cone of a spotlight of half-angle 5° meets the ball (whose silhouette is 5.74° from the
    // light) and nothing else: its flux π · C · 2π(1 − cos 5°) (§9.2: a point light adds
    // π · f · C · att · cos θ; att = 1/d²) passes the ball whole (transparent 1, no Fresnel) and lands
    // on the floor. Every photon carries the same flux here, so the sum is exact to rounding.
    const auto scene = load(ball_scene(5.0f, 4.0f));
    const int photons = 30000;
    const auto caustic = photon_pass(*scene, photons, 3);
    ASSERT_EQ(caustic->last_pass().emitted, std::size_t(photons));
    const auto& stored = caustic->photon_map().photons();
    ASSERT_EQ(stored.size(), std::size_t(photons));
    double total = 0;
    for (const Photon& p : stored) total += p.power.y;
    const double want = kPi * 2 * kPi * (1 - std::cos(5.0 * kPi / 180));
    EXPECT_NEAR(total / photons, want, 1e-4 * want);
}

TEST(Caustics, FluxThroughTheBallFromAPointLightWithinItsSamplingError) {
    // A point light: a photon meets the ball with probability Ω / 4π (Ω = 2π(1 − cos α), sin α = R / s)
    // and carries 4π · π · C / N. Those meeting it at under 60° incidence (impact parameter below
    // R sin 60°: the cone sin β = R sin 60° / s) leave it deviated by under 50° and land on the floor;
    // grazing ones may leave upward. So the flux on the floor over 4π²C/N is a binomial fraction
    // between the cone's and the silhouette's shares, within 4 standard errors.
    std::string text = ball_scene(5.0f, 4.0f);
    text.replace(text.find("type spotlight"), std::string("type spotlight").size(), "type point");
    const auto scene = load(text);
    const int photons = 400000;
    const auto caustic = photon_pass(*scene, photons, 3);
    double total = 0;
    for (const Photon& p : caustic->photon_map().photons()) total += p.power.y;
    const double s = 10, beta = std::asin(std::sin(kPi / 3) / s);
    const double p_cone = (1 - std::cos(beta)) / 2, p_sil = (1 - std::sqrt(1 - 1 / (s * s))) / 2;
    const double got = total / photons / (4 * kPi * kPi);
    EXPECT_GT(got, p_cone - 4 * std::sqrt(p_cone / photons));
    EXPECT_LT(got, p_sil + 4 * std::sqrt(p_sil / photons));
}

// A point light at height 1 over an ideal mirror (y = 0), under a white ceiling at y = 3 with the camera
// just under it looking up. The mirror's caustic on the ceiling is the light of the mirror image of
// the source at (0, −1, 0): irradiance π C cos θ / d², radiance (1/π) · that = C / 16 straight above.
constexpr const char* kMirror = R"(
camera [ eye 0 2 0 focus 0 3 0 up 0 0 1 angle 10 ]
light [ position 0 1 0 color 1 1 1 function 0 0 1 ]
mastersubgraph root [
  trans [ translate 0 -0.5 0 scale 40 1 40 object cube [ diffuse 0 0 0 reflect 1 1 1 ] ]
  trans [ translate 0 3.5 0 scale 40 1 40 object cube [ diffuse 1 1 1 ] ]
]
)";

TEST(Caustics, MirrorCausticHasTheBrightnessOfTheMirrorImage) {
    const auto scene = load(kMirror);
    CausticSettings c;
    c.max_bounces = 2;  // the mirror, then the ceiling
    c.photons_per_sample = 20000;
    c.radius = 0.1f;
    const CausticIntegrator caustic(*scene, scene->data.camera, c);
    const Ray up{{0, 2, 0}, {0, 1, 0}};
    const int n = 64;
    const Sampler sampler(1, 1);
    RayCounts counts;
    std::vector<double> v;
    for (int i = 0; i < n; ++i) {  // the first sample under 64 seeds: independent photon maps
        SampleRange range;
        range.end = 1;
        range.seed = std::uint32_t(i);
        ASSERT_TRUE(caustic.prepare(range));
        v.push_back(caustic.caustic(up, {0, 0, 0}, sampler, counts).x);
    }
    double m = 0, m2 = 0;
    for (double x : v) m += x, m2 += x * x;
    m /= n;
    const double se = std::sqrt((m2 / n - m * m) / (n - 1));
    // Bias: the irradiance falls as cos³ over the disc, by at most 1.5 (r/4)² ≈ 1e-3 of it.
    const double want = 1.0 / 16;
    EXPECT_NEAR(m, want, 4 * se + 1e-3 * want);
    EXPECT_GT(se, 0.0);
}

RenderJob ball_job(int threads, int spp) {
    RenderJob job;
    job.width = 40;
    job.height = 30;
    job.tile_size = 8;
    job.integrator.mode = RenderMode::Path;
    job.integrator.max_depth = 8;
    job.integrator.photons = 4000;
    job.sampling.spp = spp;
    job.threads = threads;
    return job;
}

TEST(Caustics, SameBytesForAnyThreadCountAndInPassesOrInOneGo) {
    // The spotlight's ball (its photons aimed at the ball), and the ball lit by an emissive sphere.
    std::string emitter = ball_scene(20.0f, 3.0f);
    emitter.replace(emitter.find("light ["), emitter.find("mastersubgraph") - emitter.find("light ["), "");
    emitter.replace(emitter.find("mastersubgraph root [\n") + 22, 0,
                    "  trans [ translate 0 4 0 object sphere [ diffuse 0 0 0 emit 20 20 20 ] ]\n");
    for (const std::string& text : {ball_scene(20.0f, 3.0f), emitter}) {
        SCOPED_TRACE(text);
        const auto scene = load(text);
        Film films[2];
        for (int k = 0; k < 2; ++k) {
            Session session(scene, ball_job(k + 1, 4));
            const auto* caustic = dynamic_cast<const CausticIntegrator*>(&session.integrator());
            ASSERT_NE(caustic, nullptr);
            while (!session.done()) ASSERT_FALSE(session.render_pass().render.cancelled);
            EXPECT_GT(caustic->last_pass().stored, 0u);
            films[k] = session.film();
        }
        // And all samples in one go (as a whitted-mpi rank renders its tiles), on 2 threads: each
        // sample gathers from the map of its block of sample indices, whatever the passes.
        Film one(40, 30);
        const RenderJob job = ball_job(2, 4);
        const auto integrator = make_integrator(*scene, scene->data.camera, job.integrator);
        ASSERT_FALSE(render(*integrator, job, one).cancelled);
        bool same = true, same_one = true, lit = false;
        for (int y = 0; y < 30; ++y)
            for (int x = 0; x < 40; ++x) {
                same = same && std::memcmp(&films[0].at(x, y), &films[1].at(x, y), sizeof(FilmPixel)) == 0;
                same_one = same_one && std::memcmp(&films[0].at(x, y), &one.at(x, y), sizeof(FilmPixel)) == 0;
                lit = lit || films[0].at(x, y).value().x > 0.0f;
            }
        EXPECT_TRUE(same);
        EXPECT_TRUE(same_one);
        EXPECT_TRUE(lit);
    }
}

// A mirror plate moving during the shutter (motion blur): each photon has a time of its own,
// uniform over the shutter, and meets the mirror where it is then. A directional light shines down
// on a 2 × 2 plate at 45° (its top face seen from above: 2√2 of area), which turns the light
// toward +x onto a wall; the plate moves along z at 4 units per unit of time. A photon's z on the
// wall is the z where it met the plate (uniform over [−1, 1]) plus 4t: over the shutter [0, 1] the
// sum of two independent uniforms, of mean 2 and variance 1/3 + 16/12; at one instant, mean 0 and
// variance 1/3. The light's flux into the mirror is the same at every instant: π · C · 2√2.
TEST(Caustics, PhotonsOfAMovingMirrorEachTakeATimeOfTheShutter) {
    const std::string text = "camera [ eye 0 5 30 focus 0 5 0 ]\n"
                             "light [ type directional direction 0 -1 0 color 1 1 1 ]\n"
                             "mastersubgraph root [\n"
                             "  trans [ translate 0 5 0 velocity 0 0 4 rotate 0 0 1 -45 scale 2 0.02 2 object cube "
                             "[ diffuse 0 0 0 reflect 1 1 1 ] ]\n"
                             "  trans [ translate 10.5 5 2 scale 1 10 12 object cube [ diffuse 0.5 0.5 0.5 ] ]\n"
                             "]\n";
    const int photons = 1 << 18;
    for (const bool shutter : {false, true}) {
        SCOPED_TRACE(shutter);
        LoadOptions lo;
        lo.shutter = shutter;
        lo.shutter_close = 1;
        LoadResult r = load_scene_text(text, "moving_mirror.sc", lo);
        ASSERT_TRUE(r.ok());
        ASSERT_EQ(!r.scene->motion.empty(), shutter);
        // Every photon that reaches the wall is stored there (two surfaces: the mirror, the wall).
        const auto caustic = photon_pass(*r.scene, photons, 2);
        const auto& stored = caustic->photon_map().photons();
        ASSERT_GT(stored.size(), 1000u);
        double sz = 0, szz = 0, power = 0, lo_z = 1e9, hi_z = -1e9;
        for (const Photon& p : stored) {
            EXPECT_NEAR(p.position.x, 10.0, 1e-3);
            EXPECT_NEAR(p.position.y, 5.0, 0.75);
            sz += p.position.z, szz += double(p.position.z) * p.position.z;
            lo_z = std::min(lo_z, double(p.position.z)), hi_z = std::max(hi_z, double(p.position.z));
            power += p.power.y;
        }
        const double N = double(stored.size()), mean = sz / N, var = szz / N - mean * mean;
        const double want_mean = shutter ? 2.0 : 0.0, want_var = shutter ? 1.0 / 3 + 16.0 / 12 : 1.0 / 3;
        // The sample variance's standard error: sqrt((μ4 − σ⁴) / N); μ4 of a sum of independent
        // uniforms of widths 2 and 4 is 2⁴/80 + 6 · (1/3)(4/3) + 4⁴/80, of one of width 2 is 2⁴/80.
        const double mu4 = shutter ? 0.2 + 6.0 * (1.0 / 3) * (4.0 / 3) + 3.2 : 0.2;
        EXPECT_NEAR(mean, want_mean, 4 * std::sqrt(want_var / N));
        EXPECT_NEAR(var, want_var, 4 * std::sqrt((mu4 - want_var * want_var) / N));
        EXPECT_GE(lo_z, -1.0 - 1e-3);
        EXPECT_LE(hi_z, (shutter ? 5.0 : 1.0) + 1e-3);
        // Each photon carries the same flux (the disc's, over the photons): the total is binomial.
        const double each = stored[0].power.y, p_hit = N / photons;
        EXPECT_NEAR(power / photons, kPi * 2 * std::sqrt(2.0), 4 * each * std::sqrt(p_hit * (1 - p_hit) / photons));
    }
}

TEST(Caustics, CancelStopsThePhotonPass) {
    const auto scene = load(ball_scene(20.0f, 3.0f));
    CausticSettings c;
    c.photons_per_sample = 1 << 20;
    const CausticIntegrator caustic(*scene, scene->data.camera, c);
    std::atomic<bool> cancel{true};
    SampleRange range;
    range.end = 1;
    range.cancel = &cancel;
    EXPECT_FALSE(caustic.prepare(range));
    EXPECT_EQ(caustic.photon_map().size(), 0u);
    // And a session's pass with the flag set is cancelled, its film left empty.
    RenderJob job = ball_job(2, 1);
    job.cancel = &cancel;
    Session session(scene, job);
    EXPECT_TRUE(session.render_pass().render.cancelled);
    EXPECT_EQ(session.passes_done(), 0);
}

TEST(Caustics, PhotonBudgetCutsAPassInWholeChunks) {
    const auto scene = load(ball_scene(5.0f, 4.0f));
    CausticSettings c;
    c.max_bounces = 3;
    c.photons_per_sample = 100000;
    c.max_stored = 10000;  // every photon of this cone is stored: the budget stops at 2 chunks of 4096
    const CausticIntegrator caustic(*scene, scene->data.camera, c);
    SampleRange range;
    range.end = 1;
    ASSERT_TRUE(caustic.prepare(range));
    EXPECT_TRUE(caustic.last_pass().cut);
    EXPECT_EQ(caustic.last_pass().emitted, 8192u);
    EXPECT_EQ(caustic.last_pass().stored, 8192u);
    EXPECT_GE(caustic.last_pass().bytes, 8192u * sizeof(Photon));
}

TEST(Caustics, ScenesWithoutCausticPathsArePathTracedAlone) {
    // No glass or mirror, lit by a point light or by an emissive sphere; glass and a point light
    // with photons turned off: the path tracer, the same bytes.
    const char* without[] = {
        "light [ position 0 5 0 ]\nmastersubgraph root [ trans [ object sphere [ diffuse 0.5 0.5 0.5 ] ] ]\n",
        "mastersubgraph root [ trans [ translate 0 3 0 object sphere [ emit 4 4 4 ] ]\n"
        "  trans [ object sphere [ diffuse 0.5 0.5 0.5 ] ] ]\n",
    };
    for (const char* text : without) {
        const auto scene = load(std::string("camera [ eye 0 0 5 focus 0 0 0 angle 40 ]\n") + text);
        ASSERT_TRUE(scene);
        IntegratorSettings settings;
        settings.mode = RenderMode::Path;
        const auto integrator = make_integrator(*scene, scene->data.camera, settings);
        EXPECT_NE(dynamic_cast<const PathIntegrator*>(integrator.get()), nullptr);
    }
    const auto scene = load(ball_scene(20.0f, 3.0f));
    RenderJob job = ball_job(2, 4);
    job.integrator.photons = 0;
    Session off(scene, job);
    EXPECT_NE(dynamic_cast<const PathIntegrator*>(&off.integrator()), nullptr);
}

TEST(Caustics, TheCausticPartAddsNothingWhereNoPhotonLands) {
    // Beside the ball's caustic the image is the path tracer's, byte for byte: the photon estimate
    // adds exactly 0 where no photon is within the radius (the sky, most of the floor).
    const auto scene = load(ball_scene(5.0f, 3.0f));
    RenderJob job = ball_job(2, 4);
    Session with(scene, job);
    while (!with.done()) with.render_pass();
    job.integrator.photons = 0;
    Session without(scene, job);
    while (!without.done()) without.render_pass();
    int same = 0, brighter = 0, darker = 0;
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) {
            const glm::vec3 a = with.film().at(x, y).value(), b = without.film().at(x, y).value();
            if (a == b) ++same;
            else if (a.x > b.x) ++brighter;
            else ++darker;
        }
    EXPECT_EQ(darker, 0);
    EXPECT_GT(brighter, 0);
    EXPECT_GT(same, 30 * 40 / 2);
}

TEST(Caustics, ErrorFallsAsTheCubeRootOfTheSamples) {
    // Probabilistic progressive photon mapping with α = 2/3: sample s's estimate has a variance
    // ∝ 1 / (photons · r_s²) with r_s² ∝ (s + 1)^(−1/3), independent of the others, so the RMS error
    // of the mean of N samples falls as N^(−1/3) (a fixed radius would give N^(−1/2) to a bias
    // floor; here the bias is under 1e-3). Over 64 independent seeds the RMS error's relative
    // standard error is 1/√128 ≈ 9%, the slope fitted over N = 4 … 256 then within ±0.03; the test
    // allows 0.1. The samples are rendered in the session's doubling passes.
    const auto scene = load(kMirror);
    CausticSettings c;
    c.max_bounces = 2;
    c.photons_per_sample = 400;
    c.radius = 0.1f;
    const CausticIntegrator caustic(*scene, scene->data.camera, c);
    const Ray up{{0, 2, 0}, {0, 1, 0}};
    const double want = 1.0 / 16;
    const std::vector<int> checkpoints{4, 16, 64, 256};
    std::vector<double> mse(checkpoints.size(), 0.0);
    const int seeds = 64;
    const Sampler sampler(1, 256);
    RayCounts counts;
    for (int seed = 0; seed < seeds; ++seed) {
        double sum = 0;
        std::size_t next = 0;
        for (int begin = 0, end = 1; begin < 256; begin = end, end *= 2) {
            SampleRange range;
            range.begin = begin;
            range.end = end;
            range.seed = std::uint32_t(seed);
            ASSERT_TRUE(caustic.prepare(range));
            for (int i = begin; i < end; ++i)
                sum += caustic.caustic(up, {std::uint32_t(seed), 0, std::uint32_t(i)}, sampler, counts).x;
            if (next < checkpoints.size() && end == checkpoints[next]) {
                const double e = sum / end - want;
                mse[next++] += e * e / seeds;
            }
        }
    }
    // Least squares slope of log RMS error against log N.
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double k = double(checkpoints.size());
    for (std::size_t i = 0; i < checkpoints.size(); ++i) {
        const double x = std::log(double(checkpoints[i])), y = 0.5 * std::log(mse[i]);
        sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
    EXPECT_NEAR(slope, -1.0 / 3.0, 0.1);
}

}  // namespace
}  // namespace whitted
