// What the viewer draws of a ray tree, without a display: the mirror-and-glass tree
// (tests/inspect/ray_tree_scene.h) cut at each depth, its colours and marks.
#if __has_include("ray_overlay.h")  // built only with the viewer (WHITTED_BUILD_VIEWER=ON)
#include "ray_overlay.h"

#include <gtest/gtest.h>

#include "inspect/pixel_inspector.h"
#include "inspect/ray_tree_scene.h"
#include "render/load_scene.h"

namespace whitted::viewer {
namespace {

RayTree tree() {
    const LoadResult r = load_scene_text(test::kRayTreeScene, "tree.sc");
    EXPECT_TRUE(r.ok());
    RenderJob job;
    job.width = test::kRayTreeWidth;
    job.height = test::kRayTreeHeight;
    return r.ok() ? inspect_pixel(*r.scene, job, test::kRayTreeX, test::kRayTreeY).ray_tree : RayTree{};
}

int count(const RayOverlay& o, RayKind kind) {
    int n = 0;
    for (const OverlayLine& l : o.lines) n += l.kind == kind;
    return n;
}

TEST(RayOverlay, EachDepthAddsTheRaysLeavingTheHitsBefore) {
    const RayTree t = tree();
    ASSERT_EQ(t.deepest(), 3);
    // Depth 0: the camera ray (end on: no line) and its hit's shadow ray; its hit marked.
    const RayOverlay d0 = ray_overlay(t, 0);
    EXPECT_EQ(d0.lines.size(), 1u);
    EXPECT_EQ(count(d0, RayKind::Shadow), 1);
    ASSERT_EQ(d0.marks.size(), 1u);  // the light is above the picture: not marked
    EXPECT_EQ(d0.marks[0].shape, MarkShape::Hit);
    EXPECT_NEAR(d0.marks[0].at.x, 100.5f, 1e-3f);
    EXPECT_NEAR(d0.marks[0].at.y, 75.5f, 1e-3f);
    // Depth 1: the reflected ray and its hit's shadow ray.
    const RayOverlay d1 = ray_overlay(t, 1);
    EXPECT_EQ(d1.lines.size(), 3u);
    EXPECT_EQ(count(d1, RayKind::Reflected), 1);
    EXPECT_EQ(d1.marks.size(), 2u);
    // All of it: two refracted rays, three shadow rays (the last through the sphere's glass).
    const RayOverlay all = ray_overlay(t, 3);
    EXPECT_EQ(all.lines.size(), 6u);
    EXPECT_EQ(count(all, RayKind::Refracted), 2);
    EXPECT_EQ(count(all, RayKind::Shadow), 3);
    EXPECT_EQ(all.marks.size(), 3u) << "the three hits; the ray leaving the scene ends in no mark";
    const glm::vec2 entry = test::ray_tree_project(test::kGlassEntry);
    for (const OverlayLine& l : all.lines)
        if (l.kind == RayKind::Reflected) {
            EXPECT_EQ(l.color, glm::u8vec3(60, 140, 255));
            EXPECT_NEAR(l.b.x, entry.x, 1e-2f);
            EXPECT_NEAR(l.b.y, entry.y, 1e-2f);
        }
}

TEST(RayOverlay, ShadowRaysAreColouredByWhatTheyMeet) {
    RaySegment s;
    s.kind = RayKind::Shadow;
    EXPECT_EQ(ray_color(s), glm::u8vec3(40, 220, 40));
    s.shadow = ShadowState::Blocked;
    EXPECT_EQ(ray_color(s), glm::u8vec3(230, 30, 30));
    s.shadow = ShadowState::Tinted;
    s.tint = {0.9f, 0.9f, 0.9f};  // grey glass: the yellow itself
    EXPECT_EQ(ray_color(s), glm::u8vec3(230, 230, 60));
    s.tint = {0.0f, 0.5f, 0.25f};  // green glass: green and half as much blue (60 · 0.5 = 30)
    EXPECT_EQ(ray_color(s), glm::u8vec3(0, 230, 30));
}

}  // namespace
}  // namespace whitted::viewer
#endif
