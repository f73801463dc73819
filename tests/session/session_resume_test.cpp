// A session resumed from a checkpoint's state (whole passes, and tiles of the pass after them)
// renders only what is missing, to the bytes of a render never stopped.
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "render/load_scene.h"
#include "session/session.h"

namespace whitted {
namespace {

// A sphere under an area light (soft shadows: every sample differs), on a floor.
constexpr const char* kScene = R"(
background [ color 0.3 0.4 0.6 ]
camera [ eye 0 3 8 focus 0 0.5 0 angle 40 ]
light [ position 2 6 1 color 0.8 0.8 0.8 radius 1.2 ]
mastersubgraph root [
  trans [ translate 0 1 0 object sphere [ diffuse 0.8 0.4 0.2 ] ]
  trans [ translate 0 -0.5 0 scale 12 1 12 object cube [ diffuse 0.7 0.7 0.7 ] ]
]
)";

RenderJob job_of(int threads) {
    RenderJob job;
    job.width = 40;
    job.height = 24;
    job.tile_size = 16;  // 3 × 2 tiles, the last column and row cut short
    job.sampling.spp = 8;
    job.threads = threads;
    return job;
}

bool same_pixels(const Film& a, const Film& b, const Tile& t) {
    for (int y = t.y0; y < t.y1; ++y)
        for (int x = t.x0; x < t.x1; ++x)
            if (std::memcmp(&a.at(x, y), &b.at(x, y), sizeof(FilmPixel)) != 0) return false;
    return true;
}

class SessionResume : public ::testing::Test {
protected:
    void SetUp() override {
        LoadResult r = load_scene_text(kScene, "resume.sc");
        ASSERT_TRUE(r.ok());
        scene = r.scene;
        // The film after each whole pass of a render never stopped.
        Session straight(scene, job_of(2));
        while (!straight.done()) {
            ASSERT_FALSE(straight.render_pass().render.cancelled);
            after.push_back(straight.film());
        }
        ASSERT_EQ(after.size(), 4u);  // 1, 2, 4, 8 samples
    }
    std::shared_ptr<const Scene> scene;
    std::vector<Film> after;
};

TEST_F(SessionResume, FromWholePassesAndSomeTilesOfTheNextGivesTheBytesOfOneRender) {
    for (int passes : {0, 1, 2, 3}) {
        SCOPED_TRACE(passes);
        Session resumed(scene, job_of(1));  // another thread count
        const std::vector<bool> next_done{true, false, false, false, true, false};
        resumed.resume(passes, passes > 0 ? after[std::size_t(passes - 1)] : Film(), after[std::size_t(passes)],
                       next_done);
        EXPECT_EQ(resumed.passes_done(), passes);
        const PassStats pass = resumed.render_pass();
        EXPECT_EQ(pass.render.tiles_done, 6);
        EXPECT_EQ(pass.render.tiles_total, 6);
        EXPECT_EQ(pass.pixels, std::size_t(40 * 24 - 16 * 16 - 16 * 8)) << "the two tiles resumed are not rendered";
        while (!resumed.done()) ASSERT_FALSE(resumed.render_pass().render.cancelled);
        for (const Tile& t : resumed.tiles()) EXPECT_TRUE(same_pixels(resumed.film(), after.back(), t));
    }
}

TEST_F(SessionResume, TheTilesResumedAreKeptNotRenderedAgain) {
    Session resumed(scene, job_of(2));
    Film next = after[2];
    next.at(3, 2).sum.x += 1.0f;  // in tile 0, which the resume says is done
    next.at(20, 2).sum.x += 1.0f;  // in tile 1, which it does not
    resumed.resume(2, after[1], next, {true, false, false, false, false, false});
    resumed.render_pass();
    EXPECT_EQ(resumed.samples_done(), 4);
    EXPECT_EQ(resumed.film().at(3, 2).sum.x, after[2].at(3, 2).sum.x + 1.0f);
    EXPECT_EQ(std::memcmp(&resumed.film().at(20, 2), &after[2].at(20, 2), sizeof(FilmPixel)), 0);
}

TEST_F(SessionResume, EveryPassResumedIsDone) {
    Session resumed(scene, job_of(2));
    resumed.resume(4, after[3], Film(), {});
    EXPECT_TRUE(resumed.done());
    for (const Tile& t : resumed.tiles()) EXPECT_TRUE(same_pixels(resumed.film(), after[3], t));
}

}  // namespace
}  // namespace whitted
