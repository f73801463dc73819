// The inspected pixel's ray tree drawn over the picture, on a real X server: a scene whose rays are
// known by hand (tests/inspect/ray_tree_scene.h: a mirror and a glass sphere) has its segments'
// ends on the screen where the pinhole's closed form puts those points, in the colours of their kinds.
#ifdef WHITTED_VIEWER_PATH
#include "inspect/ray_tree_scene.h"
#include "viewer/viewer_e2e_fixtures.h"

namespace whitted {
namespace {

using namespace viewer_e2e;

const Ready::RayLine* find_ray(const Ready& r, const std::string& kind, int depth) {
    for (const Ready::RayLine& l : r.rays)
        if (l.kind == kind && l.depth == depth) return &l;
    return nullptr;
}

// Whether the screen shows `color` at (x, y) or a pixel above or below (lines are 2 pixels wide).
bool shows_color(const Image& screen, float x, float y, glm::u8vec3 color) {
    for (int dy = -1; dy <= 1; ++dy)
        if (screen.at(int(std::floor(x)), int(std::floor(y)) + dy) == color) return true;
    return false;
}

TEST_F(ViewerWorkbench, TheRayTreeIsDrawnWhereTheProjectionsSay) {
    std::ofstream(scene_, std::ios::trunc) << test::kRayTreeScene;
    Child viewer({WHITTED_VIEWER_PATH, scene_, "--width", std::to_string(test::kRayTreeWidth), "--height",
                  std::to_string(test::kRayTreeHeight), "--threads", "2", "--ready-file", ready_},
                 dir_ + "/viewer.log", {{"DISPLAY", x_.display()}, {"ASAN_OPTIONS", asan_options_for_viewer()}});
    Ready r;
    ASSERT_TRUE(wait_for_ready(viewer, ready_, r, [](const Ready& n) { return n.state == "finished"; }))
        << viewer.output();
    ASSERT_EQ(r.image.w, test::kRayTreeWidth);
    xdotool(x_.display(), "mousemove --sync " + std::to_string(r.image.x + test::kRayTreeX) + " " +
                              std::to_string(r.image.y + test::kRayTreeY) + " click 1");
    ASSERT_TRUE(wait_for_ready(viewer, ready_, r, [](const Ready& n) { return n.rays.size() >= 6; }, 20s))
        << viewer.output();

    // Where a point of the scene is on the screen: the image's corner plus its projection.
    auto on_screen = [&](const glm::vec3& p) {
        return glm::vec2(float(r.image.x), float(r.image.y)) + test::ray_tree_project(p);
    };
    const glm::vec2 mirror = on_screen(test::kMirrorHit), entry = on_screen(test::kGlassEntry),
                    exit = on_screen(test::kGlassExit), light = on_screen(test::kRayTreeLight);
    auto expect_at = [](float x, float y, const glm::vec2& want, const char* what) {
        EXPECT_NEAR(x, want.x, 0.6f) << what;
        EXPECT_NEAR(y, want.y, 0.6f) << what;
    };
    const Ready::RayLine* reflected = find_ray(r, "reflected", 1);
    ASSERT_TRUE(reflected);
    expect_at(reflected->x0, reflected->y0, mirror, "the mirror point");
    expect_at(reflected->x1, reflected->y1, entry, "where the glass is entered");
    const Ready::RayLine* through = find_ray(r, "refracted", 2);
    ASSERT_TRUE(through);
    expect_at(through->x0, through->y0, entry, "where the glass is entered");
    expect_at(through->x1, through->y1, exit, "where the glass is left");
    const Ready::RayLine* out = find_ray(r, "refracted", 3);
    ASSERT_TRUE(out);
    expect_at(out->x0, out->y0, exit, "where the glass is left");
    expect_at(out->x1, out->y1, {float(r.image.right()), exit.y}, "on along +x to the image's edge");
    // The mirror point's shadow ray heads for the light (above the picture), cut at the image's top.
    const Ready::RayLine* shadow = find_ray(r, "shadow", 0);
    ASSERT_TRUE(shadow);
    expect_at(shadow->x0, shadow->y0, mirror, "the shadow ray's start");
    const float t = (mirror.y - float(r.image.y)) / (mirror.y - light.y);
    expect_at(shadow->x1, shadow->y1, {mirror.x + t * (light.x - mirror.x), float(r.image.y)}, "toward the light");
    int hits = 0;
    for (const Ready::Mark& m : r.marks)
        for (const glm::vec2& p : {mirror, entry, exit})
            hits += m.shape == "hit" && std::abs(m.x - p.x) < 0.6f && std::abs(m.y - p.y) < 0.6f;
    EXPECT_EQ(hits, 3);

    // On the screen: the colours of the kinds along the segments, the glass's entry marked.
    const std::string png = dir_ + "/tree.png";
    Image screen = grab_screen(x_.display(), png);
    const glm::u8vec3 blue(60, 140, 255), orange(255, 150, 30);
    EXPECT_TRUE(shows_color(screen, (mirror.x + entry.x) / 2, mirror.y, blue)) << "see " << png;
    EXPECT_TRUE(shows_color(screen, (entry.x + exit.x) / 2, entry.y, orange)) << "see " << png;
    EXPECT_EQ(screen.at(int(std::floor(entry.x)), int(std::floor(entry.y))), blue) << "the entry's mark, see " << png;
    // The inspector's text beside the picture, not over it.
    const std::string inspector = wait_for_window(x_.display(), "^Pixel inspector$", 10s);
    ASSERT_FALSE(inspector.empty());
    EXPECT_FALSE(overlap(window_geometry(x_.display(), inspector), r.image));

    // View > Ray tree depth 1: the reflected ray and the shadow rays up to it, not the glass's rays.
    keys("alt+v t");
    const std::string dialog = wait_for_window(x_.display(), "^Ray tree depth$", 20s);
    ASSERT_FALSE(dialog.empty()) << viewer.output();
    xdotool(x_.display(), "windowfocus --sync " + dialog + " key End shift+Home type 1");
    xdotool(x_.display(), "windowfocus --sync " + dialog + " key Return");
    ASSERT_TRUE(wait_for_ready(viewer, ready_, r, [](const Ready& n) { return n.rays.size() == 3; }, 20s))
        << r.rays.size() << " rays:\n" << viewer.output();
    EXPECT_TRUE(find_ray(r, "reflected", 1));
    EXPECT_TRUE(find_ray(r, "shadow", 1));
    EXPECT_FALSE(find_ray(r, "refracted", 2));
    screen = grab_screen(x_.display(), dir_ + "/depth1.png");
    EXPECT_FALSE(shows_color(screen, (entry.x + exit.x) / 2, entry.y, orange)) << "see " << dir_ << "/depth1.png";
    viewer.signal(SIGTERM);
    EXPECT_EQ(viewer.wait_exit(10s), 0) << viewer.output();
}

}  // namespace
}  // namespace whitted
#endif
