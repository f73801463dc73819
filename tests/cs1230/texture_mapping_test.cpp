// The course's texture mapping (scene-format.md §9.5): each surface's (u, v) from the table, the
// nearest texel, repeats, the texture named relative to the parent of the file's folder, GIF.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>

#include "cs1230/cs1230_test_support.h"
#include "cs1230/texture_lookup.h"
#include "support/run_process.h"
#include "texture/texture_decode.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

using test::json_scene;
using test::light_group;
using test::primitive_group;

glm::vec3 colour(glm::u8vec3 c) { return glm::vec3(c) / 255.0f; }

// A scene of one textured primitive showing the 2 × 2 quadrant picture as is (blend 1), in a
// folder of its own: <dir>/scenes/test.json naming textures/quad.png, i.e. <dir>/textures/quad.png.
struct TexturedScene {
    std::string dir = test::make_temp_dir();
    std::shared_ptr<const Scene> scene;
    TexturedScene(const std::string& primitive, const std::string& repeat = "") {
        std::filesystem::create_directories(dir + "/textures");
        EXPECT_TRUE(test::write_png(dir + "/textures/quad.png", test::quadrant_picture(2)));
        const std::string text = json_scene(primitive_group(primitive + R"(, "blend": 1, "textureFile": "textures/quad.png")" + repeat));
        LoadResult r = test::load_json(text, dir + "/scenes/test.json");
        EXPECT_TRUE(r.ok()) << test::diagnostics_text(r);
        scene = r.scene;
    }
    // The (u, v) and the texel (the diffuse colour, blend 1) where the ray meets the primitive.
    std::pair<glm::vec2, glm::vec3> at(const Ray& ray) const {
        const auto t = test::trace(*scene, ray);
        return {t.hit().surface.uv, t.hit().surface.diffuse};
    }
};

struct Probe {
    const char* where;
    Ray ray;
    glm::vec2 uv;        // from the table of §9.5, by hand
    glm::u8vec3 texel;   // the quadrant: u < 0.5 left, v > 0.5 top (row ⌊(1 − v)·2⌋)
};

void check(const char* primitive, const std::vector<Probe>& probes) {
    const TexturedScene s(primitive);
    for (const Probe& p : probes) {
        const auto [uv, texel] = s.at(p.ray);
        EXPECT_NEAR(uv.x, p.uv.x, 1e-5f) << primitive << " " << p.where;
        EXPECT_NEAR(uv.y, p.uv.y, 1e-5f) << primitive << " " << p.where;
        test::expect_vec_near(texel, colour(p.texel));
    }
}

TEST(Cs1230TextureMapping, CubeFacesFollowTheTable) {
    using namespace test;
    check(R"("type": "cube")",
          {// +z at (−0.25, 0.25): (x + 0.5, y + 0.5) = (0.25, 0.75): top left.
           {"+z", {{-0.25f, 0.25f, 5}, {0, 0, -1}}, {0.25f, 0.75f}, kTopLeft},
           // −z at (−0.25, 0.25): (0.5 − x, y + 0.5) = (0.75, 0.75): top right.
           {"-z", {{-0.25f, 0.25f, -5}, {0, 0, 1}}, {0.75f, 0.75f}, kTopRight},
           // +x at (y, z) = (0.25, 0.25): (0.5 − z, y + 0.5) = (0.25, 0.75).
           {"+x", {{5, 0.25f, 0.25f}, {-1, 0, 0}}, {0.25f, 0.75f}, kTopLeft},
           // −x: (z + 0.5, y + 0.5) = (0.75, 0.75).
           {"-x", {{-5, 0.25f, 0.25f}, {1, 0, 0}}, {0.75f, 0.75f}, kTopRight},
           // +y at (x, z) = (0.25, 0.25): (x + 0.5, 0.5 − z) = (0.75, 0.25): bottom right.
           {"+y", {{0.25f, 5, 0.25f}, {0, -1, 0}}, {0.75f, 0.25f}, kBottomRight},
           // −y: (x + 0.5, z + 0.5) = (0.75, 0.75).
           {"-y", {{0.25f, -5, 0.25f}, {0, 1, 0}}, {0.75f, 0.75f}, kTopRight}});
}

TEST(Cs1230TextureMapping, SphereIsAroundTheAxisAndUpByLatitude) {
    using namespace test;
    // Hit (0, 0.25, ±0.4330): v = 0.5 + asin(0.25/0.5)/π = 0.5 + 1/6. In front θ = atan2(z, x) = π/2,
    // u = 1 − 1/4; behind θ = −π/2, u = 1/4.
    const float v = 0.5f + 1.0f / 6.0f;
    check(R"("type": "sphere")", {{"front", {{0, 0.25f, 5}, {0, 0, -1}}, {0.75f, v}, kTopRight},
                                  {"back", {{0, 0.25f, -5}, {0, 0, 1}}, {0.25f, v}, kTopLeft},
                                  // Below the equator at (0, −0.25, 0.433): v = 1/3.
                                  {"front low", {{0, -0.25f, 5}, {0, 0, -1}}, {0.75f, 1.0f / 3.0f}, kBottomRight}});
}

TEST(Cs1230TextureMapping, CylinderSidesAndCaps) {
    using namespace test;
    check(R"("type": "cylinder")",
          {// Side at (0, 0.25, 0.5): θ = π/2, u = 0.75; v = y + 0.5 = 0.75.
           {"side front", {{0, 0.25f, 5}, {0, 0, -1}}, {0.75f, 0.75f}, kTopRight},
           // Side at (0.5, −0.25, 0): θ = 0, u = 1 − 0 = 1, the last column; v = 0.25.
           {"side +x", {{5, -0.25f, 0}, {-1, 0, 0}}, {1.0f, 0.25f}, kBottomRight},
           // Top at (0.25, 0.5, 0.25): (x + 0.5, 0.5 − z) = (0.75, 0.25).
           {"top", {{0.25f, 5, 0.25f}, {0, -1, 0}}, {0.75f, 0.25f}, kBottomRight},
           // Bottom at (0.25, −0.5, 0.25): (x + 0.5, z + 0.5) = (0.75, 0.75).
           {"bottom", {{0.25f, -5, 0.25f}, {0, 1, 0}}, {0.75f, 0.75f}, kTopRight}});
}

TEST(Cs1230TextureMapping, ConeSideAndBase) {
    using namespace test;
    check(R"("type": "cone")",
          {// Side at y = 0 (radius 0.25), front: θ = π/2, u = 0.75; v = 0.5: the bottom row.
           {"side front", {{0, 0, 5}, {0, 0, -1}}, {0.75f, 0.5f}, kBottomRight},
           // Side at y = −0.25 (radius 0.375), behind: θ = −π/2, u = 0.25; v = 0.25.
           {"side back", {{0, -0.25f, -5}, {0, 0, 1}}, {0.25f, 0.25f}, kBottomLeft},
           // Base at (−0.25, −0.5, 0.25): (x + 0.5, z + 0.5) = (0.25, 0.75).
           {"base", {{-0.25f, -5, 0.25f}, {0, 1, 0}}, {0.25f, 0.75f}, kTopLeft}});
}

TEST(Cs1230TextureMapping, RepeatsTileTheImage) {
    // textureU 2: u = 0.25 → column ⌊0.25·2·2⌋ mod 2 = 1 (the right half of the first copy).
    // textureV 3: v = 0.75 → row ⌊0.25·3·2⌋ mod 2 = ⌊1.5⌋ = 1.
    const TexturedScene s(R"("type": "cube")", R"(, "textureU": 2, "textureV": 3)");
    const auto [uv, texel] = s.at(Ray{{-0.25f, 0.25f, 5}, {0, 0, -1}});
    test::expect_vec_near(texel, colour(test::kBottomRight));
}

TEST(Cs1230TextureMapping, BlendMixesKdOdWithTheTexelNotScaledByKd) {
    // kd 0.5 · Od (0.4, 0.8, 1) = (0.2, 0.4, 0.5); the texel at (−0.25, 0.25) of the +z face is the
    // top left one, (220, 30, 30)/255 = (0.8627451, 0.1176471, 0.1176471). blend 0.25, lit head-on
    // by a white light: D = 0.75·(0.2, 0.4, 0.5) + 0.25·texel = (0.3656863, 0.3294118, 0.4044118).
    const std::string dir = test::make_temp_dir();
    std::filesystem::create_directories(dir + "/textures");
    ASSERT_TRUE(test::write_png(dir + "/textures/quad.png", test::quadrant_picture(2)));
    auto lit = [&](const char* blend, cs1230::Stage stage) {
        const std::string text = json_scene(
            light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [0, 0, -1])") + "," +
                primitive_group(std::string(R"("type": "cube", "diffuse": [0.4, 0.8, 1], "textureFile": "textures/quad.png",
                                             "blend": )") + blend),
            0.0f, 0.5f, 0.0f);
        const LoadResult r = test::load_json(text, dir + "/scenes/blend.json", stage);
        EXPECT_TRUE(r.ok()) << test::diagnostics_text(r);
        return test::trace(*r.scene, Ray{{-0.25f, 0.25f, 5}, {0, 0, -1}}, 4, stage).color();
    };
    test::expect_vec_near(lit("0.25", cs1230::Stage::Illuminate), {0.3656863f, 0.3294118f, 0.4044118f});
    test::expect_vec_near(lit("0", cs1230::Stage::Illuminate), {0.2f, 0.4f, 0.5f});   // the default: no texture
    test::expect_vec_near(lit("1", cs1230::Stage::Illuminate), {0.8627451f, 0.1176471f, 0.1176471f});
    test::expect_vec_near(lit("0.25", cs1230::Stage::Intersect), {0.2f, 0.4f, 0.5f});  // no textures there
}

TEST(Cs1230TextureMapping, NearestTexelOfTheLookupFormula) {
    // A 4 × 2 image whose texel (c, r) is (10c, 100r, 7): column ⌊u·U·w⌋ mod w, row ⌊(1 − v)·V·h⌋ mod h.
    TextureImage img;
    img.width = 4;
    img.height = 2;
    for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 4; ++c) img.push_back({std::uint8_t(10 * c), std::uint8_t(100 * r), 7});
    auto texel = [&](float u, float v, float U = 1, float V = 1) {
        const glm::vec3 t = cs1230::nearest_texel(img, {u, v}, U, V) * 255.0f;
        return glm::ivec2(int(std::lround(t.x)) / 10, int(std::lround(t.y)) / 100);
    };
    EXPECT_EQ(texel(0.0f, 1.0f), glm::ivec2(0, 0));    // top left
    EXPECT_EQ(texel(0.26f, 0.2f), glm::ivec2(1, 1));   // ⌊1.04⌋, ⌊1.6⌋
    EXPECT_EQ(texel(0.74f, 0.51f), glm::ivec2(2, 0));  // ⌊2.96⌋, ⌊0.98⌋
    EXPECT_EQ(texel(1.0f, 0.0f), glm::ivec2(3, 1));    // u = 1, 1 − v = 1: the last column and row
    EXPECT_EQ(texel(0.3f, 0.9f, 3, 2), glm::ivec2(3, 0));  // ⌊0.3·3·4⌋ = 3, ⌊0.1·2·2⌋ = 0
    EXPECT_EQ(texel(0.5f, 0.7f, 3, 2), glm::ivec2(2, 1));  // ⌊6⌋ mod 4 = 2, ⌊0.3·2·2⌋ = 1
}

TEST(Cs1230TextureMapping, GifIsReadForTheseFilesOnly) {
    // A 1 × 1 GIF89a whose only pixel is palette entry 0, red.
    const std::string gif("GIF89a\x01\x00\x01\x00\x80\x00\x00\xff\x00\x00\x00\x00\x00"
                          ",\x00\x00\x00\x00\x01\x00\x01\x00\x00\x02\x02\x44\x01\x00;",
                          35);
    TextureImage img;
    TextureLimits limits;
    EXPECT_NE(decode_texture(gif, limits, img).find("GIF"), std::string::npos);  // §8: refused
    limits.gif = true;
    ASSERT_EQ(decode_texture(gif, limits, img), "");
    ASSERT_EQ(img.width, 1);
    ASSERT_EQ(img.height, 1);
    EXPECT_EQ(img.texel(0), glm::vec3(1, 0, 0));
}

}  // namespace
}  // namespace whitted
