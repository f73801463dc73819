// Adaptive anti-aliasing compares a pixel with all four neighbours: the vertical-edge case is in
// renderer_test.cpp; here a horizontal edge (only the up/down neighbours differ) and a corner.
#include <gtest/gtest.h>

#include "render/renderer.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

// A glowing wall filling the image above a horizontal edge at pixel row `edge_py` (in pixel
// units from the top) of a width × height image, and, if `edge_px` > 0, only left of a vertical
// edge at column `edge_px`; the rest background. The default camera looks down −z from z = 1
// with tan(half fov) = 0.57735; the wall's face is at z = −4.5, 5.5 from the eye.
Scene wall_scene(int width, int height, float edge_px, float edge_py, glm::vec3 glow, glm::vec3 background) {
    const Camera cam;
    const float aspect = float(width) / float(height);
    const float edge_y = (1.0f - 2.0f * edge_py / float(height)) * cam.tan_half_fov * 5.5f;
    const float edge_x = edge_px > 0 ? (2.0f * edge_px / float(width) - 1.0f) * cam.tan_half_fov * aspect * 5.5f : 50.0f;
    test::SceneBuilder b;
    b.add(ShapeKind::Cube, test::translate_scale({edge_x - 50.0f, edge_y + 50.0f, -5}, {100, 100, 1}),
          test::emitter(glow));
    b.background(background);
    return b.build();
}

TEST(AdaptiveAntiAliasing, AHorizontalEdgeIsSupersampledOnBothSides) {
    // The edge three quarters down row 4 of a 5 × 9 image: row 4's centre (4.5) sees the red
    // wall, row 5's (5.5) the blue background, so exactly rows 4 and 5 differ from a neighbour,
    // above or below; their left and right neighbours are the same colour as they are. They get
    // 4 × 4 rays: row 4 has sub-pixel rows at 4.125, 4.375, 4.625 (wall) and 4.875 (background),
    // 3/4 red; row 5 is all blue. Every other pixel keeps its centre ray.
    RenderJob o;
    o.width = 5;
    o.height = 9;
    o.sampling.aa = 4;
    o.sampling.aa_threshold = 0.1f;
    o.threads = 1;
    Image img(o.width, o.height);
    const RenderStats s = render(wall_scene(5, 9, 0.0f, 4.75f, {1, 0, 0}, {0, 0, 1}), o, img);
    for (int x = 0; x < 5; ++x) {
        EXPECT_EQ(img.at(x, 3), glm::u8vec3(255, 0, 0)) << x;
        EXPECT_EQ(img.at(x, 4), glm::u8vec3(191, 0, 64)) << x;  // ⌊191.25 + 0.5⌋, ⌊63.75 + 0.5⌋
        EXPECT_EQ(img.at(x, 5), glm::u8vec3(0, 0, 255)) << x;
        EXPECT_EQ(img.at(x, 0), glm::u8vec3(255, 0, 0)) << x;
        EXPECT_EQ(img.at(x, 8), glm::u8vec3(0, 0, 255)) << x;
    }
    // One tile: 45 centre rays, then 16 for each of the 10 pixels of rows 4 and 5.
    EXPECT_EQ(s.rays.camera, 45u + 10u * 16u);
}

TEST(AdaptiveAntiAliasing, ACornerIsSupersampledAlongBothEdges) {
    // The wall's corner at (4.75, 4.75) of a 9 × 9 image: it covers the pixels whose centres are
    // left of 4.75 and above 4.75, i.e. columns 0–4 of rows 0–4. The pixels that differ from a
    // neighbour: (4, y) and (5, y) for y = 0..4 (across the vertical edge), (x, 4) and (x, 5) for
    // x = 0..4 (across the horizontal one), (4, 4) being in two of these lists: 19 pixels.
    RenderJob o;
    o.width = 9;
    o.height = 9;
    o.sampling.aa = 4;
    o.sampling.aa_threshold = 0.1f;
    o.threads = 1;
    Image img(o.width, o.height);
    const RenderStats s = render(wall_scene(9, 9, 4.75f, 4.75f, {1, 0, 0}, {0, 0, 1}), o, img);
    int differing = 0;
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 9; ++x) {
            const bool red = x <= 4 && y <= 4;
            auto is_red = [](int nx, int ny) { return nx <= 4 && ny <= 4; };
            bool differs = false;
            for (auto [dx, dy] : {std::pair{-1, 0}, {1, 0}, {0, -1}, {0, 1}}) {
                const int nx = x + dx, ny = y + dy;
                if (nx >= 0 && nx < 9 && ny >= 0 && ny < 9 && is_red(nx, ny) != red) differs = true;
            }
            differing += differs;
            // Supersampled pixels show the wall's share of their 16 sub-pixels: 4 × 4 sub-pixel
            // centres at .125, .375, .625, .875; the edges at 4.75 leave 3 of 4 columns (rows).
            const int cols = x < 4 ? 4 : (x == 4 ? 3 : 0), rows = y < 4 ? 4 : (y == 4 ? 3 : 0);
            const int share = differs ? cols * rows : (red ? 16 : 0);
            const int r = int(255.0f * float(share) / 16.0f + 0.5f), b = int(255.0f * float(16 - share) / 16.0f + 0.5f);
            EXPECT_EQ(img.at(x, y), glm::u8vec3(r, 0, b)) << x << "," << y;
        }
    EXPECT_EQ(differing, 19);
    EXPECT_EQ(s.rays.camera, 81u + 19u * 16u);
}

}  // namespace
}  // namespace whitted
