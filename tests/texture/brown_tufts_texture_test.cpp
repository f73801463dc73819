// The textures of the Brown/Tufts dialect (scene-format.md §9.4): `blend` against hand-computed
// pixels, the look-up of Windows paths and of names whose file exists under another extension,
// and the plain (P3) PPM files that course ships.
#include <algorithm>

#include <gtest/gtest.h>

#include "texture/ascii_ppm.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using namespace whitted::test;

using BrownTuftsTexture = PrivateTextureDirs;

// A wall facing the camera, lit head-on by a white directional light: N·L = 1, no ambient (the
// material's is 0), no specular, so a pixel is exactly the diffuse colour after blending.
std::string wall(const std::string& material) {
    return "camera [ eye 0 0 3 look 0 0 -1 angle 30 ]\n"
           "light [ number 0 direction 0 0 -1 color 1 1 1 ]\n"
           "trans [ scale 10 10 1 object cube [ " + material + " ] ]\n";
}

TEST_F(BrownTuftsTexture, BlendMixesTheDiffuseColourWithTheTexel) {
    ASSERT_TRUE(write_png(dir_ + "/t.png", solid({51, 102, 153})));  // texel (0.2, 0.4, 0.6)
    struct Case {
        const char* blend;
        glm::vec3 want;  // (1 − b)·(1, 0, 0) + b·(0.2, 0.4, 0.6)
    } cases[] = {
        {"blend 0", {1, 0, 0}},
        {"blend 0.5", {0.6f, 0.2f, 0.3f}},
        {"blend 1", {0.2f, 0.4f, 0.6f}},
        {"", {0.2f, 0, 0}},  // no blend: the texel multiplies the diffuse colour (§8)
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.blend);
        Rendered r = render_scene_text(wall(std::string("diffuse 1 0 0 texture t.png 1 1 ") + c.blend), scene_, 9, 9,
                                       RenderMode::Whitted);
        ASSERT_TRUE(r.load.ok()) << r.messages;
        const glm::u8vec3 got = r.image.at(4, 4);
        for (int k = 0; k < 3; ++k)  // ±1 for the rounding of x.5 values in float
            EXPECT_NEAR(int(got[k]), 255.0f * c.want[k], 1.0f) << "channel " << k;
    }
}

TEST_F(BrownTuftsTexture, WindowsPathLookupOrder) {
    const std::string name = "C:\\Users\\x\\image\\earth.bmp";
    fs::create_directories(dir_ + "/image");
    ASSERT_TRUE(write_png(dir_ + "/image/earth.ppm", solid({1, 2, 3})));  // a PNG in disguise decodes too
    ASSERT_TRUE(write_png(dir_ + "/earth.bmp", solid({4, 5, 6})));
    const auto c = loose_texture_candidates(name, scene_, {});
    auto at = [&](const std::string& p) { return std::find(c.begin(), c.end(), p) - c.begin(); };
    // The trailing parts, longest first, each in the usual places (scene dir first) ...
    ASSERT_FALSE(c.empty());
    EXPECT_EQ(c.front(), dir_ + "/Users/x/image/earth.bmp");
    EXPECT_LT(at(dir_ + "/x/image/earth.bmp"), at(dir_ + "/image/earth.bmp"));
    EXPECT_LT(at(dir_ + "/image/earth.bmp"), at(dir_ + "/earth.bmp"));
    // ... then other extensions of what exists, and only those.
    EXPECT_LT(at(dir_ + "/earth.bmp"), at(dir_ + "/image/earth.ppm"));
    EXPECT_EQ(c.back(), dir_ + "/image/earth.ppm");
    EXPECT_EQ(at(dir_ + "/image/earth.png"), std::ptrdiff_t(c.size()));

    // Through the loader: the bare name beside the scene comes before the other extension.
    const std::string scene = wall("texture " + name + " 1 1 blend 1");
    Rendered r = render_scene_text(scene, scene_, 5, 5, RenderMode::Whitted);
    ASSERT_TRUE(r.load.ok()) << r.messages;
    EXPECT_EQ(r.image.at(2, 2), glm::u8vec3(4, 5, 6));
    fs::remove(dir_ + "/earth.bmp");
    r = render_scene_text(scene, scene_, 5, 5, RenderMode::Whitted);
    ASSERT_TRUE(r.load.ok()) << r.messages;
    EXPECT_EQ(r.image.at(2, 2), glm::u8vec3(1, 2, 3));
}

TEST_F(BrownTuftsTexture, OtherExtensionsOnlyForBrownTuftsNamesAndWindowsPaths) {
    ASSERT_TRUE(write_png(dir_ + "/sun.ppm", solid({9, 9, 9})));
    // A Brown/Tufts file finds sun.ppm for sun.bmp ...
    EXPECT_TRUE(render_scene_text(wall("texture sun.bmp 1 1"), scene_, 3, 3).load.ok());
    // ... a labs file does not: its names mean what they say (§8).
    const std::string labs = "mastersubgraph root [ trans [ object cube [ texture sun.bmp 1 1 ] ] ]";
    EXPECT_FALSE(render_scene_text(labs, scene_, 3, 3).load.ok());
    // A Windows path in a labs file gets the look-up too.
    const std::string windows = "mastersubgraph root [ trans [ object cube [ texture D:\\maps\\sun.bmp 1 1 ] ] ]";
    EXPECT_TRUE(render_scene_text(windows, scene_, 3, 3).load.ok());
    EXPECT_TRUE(is_windows_path("C:/a.bmp"));
    EXPECT_TRUE(is_windows_path("a\\b.bmp"));
    EXPECT_FALSE(is_windows_path("image/a.bmp"));
}

TEST(AsciiPpm, DecodesPlainPpm) {
    TextureImage img;
    std::string why;
    ASSERT_TRUE(decode_ascii_ppm("P3\n# comment\n2 1\n100\n100 50 0   10 20 #c\n 30\n", img, why)) << why;
    ASSERT_EQ(img.width, 2);
    ASSERT_EQ(img.height, 1);
    // Kept as the nearest 8-bit values: v / 100 · 255 = 255, 127.5, 0, 25.5, 51, 76.5,
    // rounded half up to 255, 128, 0, 26, 51, 77.
    EXPECT_EQ(img.rgb, (std::vector<std::uint8_t>{255, 128, 0, 26, 51, 77}));
    EXPECT_NEAR(img.texel(1).x, 0.1f, 0.5f / 255.0f);
    EXPECT_FALSE(decode_ascii_ppm("P3 2 1 255 1 2 3 4 5", img, why));  // truncated
    EXPECT_NE(why.find("ends before its last pixel"), std::string::npos);
    EXPECT_FALSE(decode_ascii_ppm("P3 1 1 255 1 2 300", img, why));  // above maxval
    EXPECT_FALSE(decode_ascii_ppm("P3 99999 99999 255", img, why));  // absurd size, no allocation
    // The fuzzer's header: sides whose product does not fit in 64 bits (undefined behaviour when it
    // was computed first; UBSan stops this test in the sanitizer build).
    EXPECT_FALSE(decode_ascii_ppm("P3\n61000000000\n90000000000\n255\n", img, why));
    EXPECT_NE(why.find("61000000000x90000000000 texels: more than 16384 across or down"), std::string::npos) << why;
    EXPECT_FALSE(decode_ascii_ppm("P3 x", img, why));
    EXPECT_TRUE(is_ascii_ppm("P3\n1 1 1 0 0 0"));
    EXPECT_FALSE(is_ascii_ppm("P6\n1 1 255\n"));
}

}  // namespace
}  // namespace whitted
