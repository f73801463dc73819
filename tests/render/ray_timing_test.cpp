// --stats' rays per second of each kind: one traversal in RayCounts::kTimeEvery of each kind is
// timed, only when the job asks, and the timing changes no pixel.
#include <string>

#include <gtest/gtest.h>

#include "render/load_scene.h"
#include "render/renderer.h"

namespace whitted {
namespace {

const Scene& showcase() {
    static const LoadResult loaded = load_scene(std::string(WHITTED_SOURCE_DIR) + "/scenes/showcase.sc");
    EXPECT_TRUE(loaded.ok());
    return *loaded.scene;
}

RenderJob small_job(RenderMode mode, bool time_rays) {
    RenderJob job;
    job.width = 96;
    job.height = 72;
    job.tile_size = 16;
    job.integrator.mode = mode;
    job.time_rays = time_rays;
    job.threads = 1;  // one worker, one set of counts: every kTimeEvery-th call exactly
    if (mode == RenderMode::Path) job.sampling.spp = 4;
    return job;
}

std::uint64_t timed_calls(const RayCounts& c, RayKind k) { return c.timed[int(k)].calls; }

TEST(RayTiming, NothingIsTimedUnlessTheJobAsks) {
    for (RenderMode mode : {RenderMode::Whitted, RenderMode::Path}) {
        Image image(96, 72);
        const RenderStats s = render(showcase(), small_job(mode, false), image);
        EXPECT_GT(s.rays.reflected, 0u);
        for (int k = 0; k < kRayKinds; ++k) {
            EXPECT_EQ(s.rays.timed[k].calls, 0u);
            EXPECT_EQ(s.rays.timed[k].nanos, 0u);
            EXPECT_EQ(s.rays.rays_per_second(RayKind(k)), 0.0);
        }
    }
}

TEST(RayTiming, ChangesNoPixel) {
    for (RenderMode mode : {RenderMode::Whitted, RenderMode::Path}) {
        SCOPED_TRACE(render_mode_name(mode));
        Image plain(96, 72), timed(96, 72);
        const RenderStats a = render(showcase(), small_job(mode, false), plain);
        const RenderStats b = render(showcase(), small_job(mode, true), timed);
        EXPECT_EQ(plain.rgb, timed.rgb);
        EXPECT_EQ(a.rays.total(), b.rays.total());
    }
}

// Whitted: every refracted ray counted is traced once, on its own, so the timed calls are the
// count and one in kTimeEvery of them was timed (the 1st, 33rd, ...). Reflected rays too, but the
// camera hits' opaque mirrors trace theirs together, a call for several.
TEST(RayTiming, WhittedTimesOneSecondaryRayInEveryKTimeEvery) {
    Image image(96, 72);
    const RenderStats s = render(showcase(), small_job(RenderMode::Whitted, true), image);
    const RayCounts& c = s.rays;
    ASSERT_GT(c.reflected, 0u);
    ASSERT_GT(c.refracted, 0u);
    EXPECT_EQ(timed_calls(c, RayKind::Refracted), c.refracted);
    const std::uint64_t n = RayCounts::kTimeEvery;
    EXPECT_EQ(c.timed[int(RayKind::Refracted)].rays, (c.refracted + n - 1) / n);
    EXPECT_GT(timed_calls(c, RayKind::Reflected), 0u);
    EXPECT_LT(timed_calls(c, RayKind::Reflected), c.reflected);
    EXPECT_LE(c.timed[int(RayKind::Reflected)].rays, (timed_calls(c, RayKind::Reflected) + n - 1) / n * kPacketSize);
    // Camera rays go in packets: a call carries up to kPacketSize of them.
    const RayCounts::Timed& cam = c.timed[int(RayKind::Camera)];
    EXPECT_GT(cam.rays, 0u);
    EXPECT_LE(cam.rays, (cam.calls + n - 1) / n * kPacketSize);
    EXPECT_GE(cam.calls * kPacketSize, c.camera);
    // Shadow queries answered by a packet's query from the light, or of unshadowed lights, trace
    // nothing of their own.
    EXPECT_GT(timed_calls(c, RayKind::Shadow), 0u);
    EXPECT_LE(timed_calls(c, RayKind::Shadow), c.shadow);
    for (RayKind k : {RayKind::Camera, RayKind::Reflected, RayKind::Refracted, RayKind::Shadow})
        EXPECT_GT(c.rays_per_second(k), 0.0) << int(k);
}

// Path tracing: a bounce's direction is counted when drawn and traced on the next vertex, unless
// Russian roulette ends the path in between.
TEST(RayTiming, PathTimesEachKind) {
    Image image(96, 72);
    const RenderStats s = render(showcase(), small_job(RenderMode::Path, true), image);
    const RayCounts& c = s.rays;
    for (auto [kind, count] : {std::pair{RayKind::Reflected, c.reflected}, std::pair{RayKind::Refracted, c.refracted},
                               std::pair{RayKind::Shadow, c.shadow}}) {
        EXPECT_GT(timed_calls(c, kind), 0u) << int(kind);
        EXPECT_LE(timed_calls(c, kind), count) << int(kind);
        EXPECT_GT(c.rays_per_second(kind), 0.0) << int(kind);
    }
    EXPECT_GT(c.rays_per_second(RayKind::Camera), 0.0);
}

TEST(RayTiming, CountsFromThreadsAddUp) {
    RayCounts a, b;
    a.timed[int(RayKind::Shadow)] = {16, 2, 100};
    b.timed[int(RayKind::Shadow)] = {8, 1, 200};
    b.timing = true;
    a += b;
    EXPECT_TRUE(a.timing);
    EXPECT_EQ(a.timed[int(RayKind::Shadow)].calls, 24u);
    EXPECT_EQ(a.timed[int(RayKind::Shadow)].rays, 3u);
    EXPECT_EQ(a.timed[int(RayKind::Shadow)].nanos, 300u);
    EXPECT_DOUBLE_EQ(a.rays_per_second(RayKind::Shadow), 3.0 / 300e-9);
    EXPECT_EQ(a.rays_per_second(RayKind::Camera), 0.0);
}

}  // namespace
}  // namespace whitted
