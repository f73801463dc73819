// Textures end to end: through the library's load_scene (parser locations, decode once, the
// viewer's retry), the `whitted` command (exit code 2 with FILE:LINE:COL and every path tried,
// --texture-path, --missing-textures=checker), the course's own textured scenes, and the
// bundled showcase scenes/textures.sc.
#include <algorithm>

#include <gtest/gtest.h>

#include <set>

#include "accel/scene.h"
#include "film/image_io.h"
#include "support/run_process.h"
#include "support/needs.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using namespace whitted::test;

// Line 4, column 7 holds the `texture` keyword; so does line 7, column 21.
const char* kTwoObjects =
    "camera [ eye 0 0 4 ]\n"                                    // 1
    "mastersubgraph root [\n"                                   // 2
    "  trans [ translate -0.6 0 0 object sphere [\n"           // 3
    "      texture TEX1 1 1 ] ]\n"                              // 4
    "  trans [ translate 0.6 0 0\n"                             // 5
    "    object cube [ diffuse 1 1 1\n"                         // 6
    "                    texture TEX2 2 3 ] ]\n"                // 7
    "]\n";

std::string two_objects(const std::string& tex1, const std::string& tex2) {
    std::string s = kTwoObjects;
    s.replace(s.find("TEX1"), 4, tex1);
    s.replace(s.find("TEX2"), 4, tex2);
    return s;
}

using TextureScene = PrivateTextureDirs;

// Two objects, one file: one decode (also reached by another spelling of the same path).
TEST_F(TextureScene, SameFileDecodedOncePerScene) {
    ASSERT_TRUE(write_png(dir_ + "/t.png", solid({200, 100, 50})));
    fs::create_directories(dir_ + "/sub");
    for (auto [a, b] : {std::pair{"t.png", "t.png"}, std::pair{"t.png", "sub/../t.png"}, std::pair{"./t.png", "sub\\..\\t.png"}}) {
        SCOPED_TRACE(std::string(a) + " and " + b);
        LoadResult r = load_scene_text(two_objects(a, b), scene_);
        ASSERT_TRUE(r.ok());
        EXPECT_EQ(r.scene->data.textures.size(), 1u);
        EXPECT_EQ(r.stats.textures, 1u);
        for (const Material& m : r.scene->data.materials) EXPECT_EQ(m.texture, 0);
        EXPECT_TRUE(r.missing_textures.empty());
        EXPECT_TRUE(r.diagnostics.empty());
    }
    // The repeat counts reach the material.
    LoadResult r = load_scene_text(two_objects("t.png", "t.png"), scene_);
    ASSERT_TRUE(r.ok());
    std::set<std::pair<float, float>> repeats;
    for (const Material& m : r.scene->data.materials) repeats.insert({m.repeat_u, m.repeat_v});
    EXPECT_EQ(repeats, (std::set<std::pair<float, float>>{{1, 1}, {2, 3}}));
}

// The report names the `texture` keyword's position; the viewer answers and loads again.
TEST_F(TextureScene, MissingTexturesAsDataAndRetry) {
    const std::string text = two_objects("maps/gone.png", "maps\\lost.bmp");
    LoadOptions options;
    options.textures.search_dirs = {dir_ + "/extra"};
    LoadResult r = load_scene_text(text, scene_, options);
    EXPECT_FALSE(r.ok());
    ASSERT_EQ(r.missing_textures.size(), 2u);
    const MissingTexture& a = r.missing_textures[0];
    EXPECT_EQ(a.name, "maps/gone.png");
    EXPECT_EQ(a.loc.file, scene_);
    EXPECT_EQ(a.loc.line, 4);
    EXPECT_EQ(a.loc.col, 7);
    EXPECT_EQ(a.tried, texture_candidates("maps/gone.png", scene_, options.textures.search_dirs));
    const MissingTexture& b = r.missing_textures[1];
    EXPECT_EQ(b.name, "maps\\lost.bmp");
    EXPECT_EQ(b.loc.line, 7);
    EXPECT_EQ(b.loc.col, 21);
    EXPECT_EQ(b.tried.front(), dir_ + "/maps/lost.bmp");
    EXPECT_NE(std::find(b.tried.begin(), b.tried.end(), dir_ + "/extra/maps/lost.bmp"), b.tried.end());
    // A Windows path: after the usual places, its last part alone, the last place last (§9.4).
    EXPECT_EQ(b.tried.back(), dir_ + "/extra/lost.bmp");

    // The user points at files for both names; the same text loads.
    ASSERT_TRUE(write_png(dir_ + "/answer1.png", solid({1, 2, 3})));
    ASSERT_TRUE(write_bmp(dir_ + "/answer2.bmp", solid({4, 5, 6}), 24, false));
    for (const MissingTexture& m : r.missing_textures)
        options.textures.overrides[m.name] = dir_ + (m.name == "maps/gone.png" ? "/answer1.png" : "/answer2.bmp");
    r = load_scene_text(text, scene_, options);
    ASSERT_TRUE(r.ok());
    EXPECT_TRUE(r.missing_textures.empty());
    EXPECT_EQ(r.scene->data.textures.size(), 2u);
}

TEST_F(TextureScene, CheckerFallbackRendersMagentaAndBlack) {
    LoadOptions options;
    options.textures.missing = MissingTexturePolicy::Checker;
    const std::string text =
        "camera [ eye 0 0 1.2 ]\n"
        "mastersubgraph root [ trans [ object cube [ texture nowhere.png 1 1 ] ] ]\n";
    Rendered r = render_scene_text(text, scene_, 64, 64, RenderMode::Raycast, options);
    ASSERT_TRUE(r.load.ok()) << r.messages;
    ASSERT_EQ(r.load.missing_textures.size(), 1u);
    ASSERT_EQ(r.load.diagnostics.size(), 1u);
    EXPECT_EQ(r.load.diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(r.load.diagnostics[0].loc.line, 2);
    int magenta = 0, black = 0;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) {
            const glm::u8vec3 c = r.image.at(x, y);
            magenta += c == glm::u8vec3(255, 0, 255);
            black += c == glm::u8vec3(0);
        }
    // The front face fills the picture: 8 × 8 squares, half of each.
    EXPECT_GT(magenta, 64 * 64 / 3);
    EXPECT_GT(black, 64 * 64 / 3);
}

// ---- the command line ---------------------------------------------------------------------------

TEST_F(TextureScene, CliMissingTextureExitsTwoWithLocationAndEveryPath) {
    write_text(scene_, two_objects("maps/gone.png", "also_gone.png"));
    const std::string out = dir_ + "/out.png";
    auto r = run_process({cli_path(), scene_, "-o", out, "--width", "8", "--height", "8", "-q", "--texture-path",
                          dir_ + "/a", "--texture-path", dir_ + "/b"});
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find(scene_ + ":4:7:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(scene_ + ":7:21:"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("maps/gone.png"), std::string::npos);
    for (const auto& p : texture_candidates("maps/gone.png", scene_, {dir_ + "/a", dir_ + "/b"}))
        EXPECT_NE(r.output.find(p), std::string::npos) << p << "\n" << r.output;
    for (const auto& p : texture_candidates("also_gone.png", scene_, {dir_ + "/a", dir_ + "/b"}))
        EXPECT_NE(r.output.find(p), std::string::npos) << p << "\n" << r.output;
    EXPECT_NE(r.output.find("--missing-textures=checker"), std::string::npos) << r.output;  // the way out
    EXPECT_FALSE(fs::exists(out));
}

TEST_F(TextureScene, CliCheckerFallback) {
    write_text(scene_, "camera [ eye 0 0 1.2 ]\n"
                       "mastersubgraph root [ trans [ object cube [ texture nowhere.png 1 1 ] ] ]\n");
    const std::string out = dir_ + "/out.png";
    auto r = run_process({cli_path(), scene_, "-o", out, "--width", "32", "--height", "32", "-q", "--mode", "raycast",
                          "--missing-textures=checker"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("warning"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(scene_ + ":2:"), std::string::npos) << r.output;
    Image img;
    ASSERT_EQ(read_image(out, img), "");
    int magenta = 0;
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) magenta += img.at(x, y) == glm::u8vec3(255, 0, 255);
    EXPECT_GT(magenta, 32 * 32 / 3);
}

// --texture-path is repeatable and tried in the order given; `\` in FILE works.
TEST_F(TextureScene, CliTexturePath) {
    fs::create_directories(dir_ + "/scenes");
    const std::string scene = dir_ + "/scenes/s.sc";
    write_text(scene, "camera [ eye 0 0 1.6 ]\n"
                      "mastersubgraph root [ trans [ object cube [ texture img\\t.png 1 1 ] ] ]\n");
    fs::create_directories(dir_ + "/second/img");
    ASSERT_TRUE(write_png(dir_ + "/second/img/t.png", solid({0, 200, 0})));
    const std::string out = dir_ + "/out.png";
    auto run = [&] {
        return run_process({cli_path(), scene, "-o", out, "--width", "8", "--height", "8", "-q", "--mode", "raycast",
                            "--texture-path", dir_ + "/first", "--texture-path", dir_ + "/second"});
    };
    auto r = run();
    ASSERT_EQ(r.exit_code, 0) << r.output;
    Image img;
    ASSERT_EQ(read_image(out, img), "");
    EXPECT_EQ(img.at(4, 4), glm::u8vec3(0, 200, 0));
    // A copy in the first directory wins over the second …
    fs::create_directories(dir_ + "/first/img");
    ASSERT_TRUE(write_png(dir_ + "/first/img/t.png", solid({0, 0, 200})));
    ASSERT_EQ(run().exit_code, 0);
    ASSERT_EQ(read_image(out, img), "");
    EXPECT_EQ(img.at(4, 4), glm::u8vec3(0, 0, 200));
    // … and one in the scene's parent directory wins over both.
    fs::create_directories(dir_ + "/img");
    ASSERT_TRUE(write_png(dir_ + "/img/t.png", solid({200, 0, 0})));
    ASSERT_EQ(run().exit_code, 0);
    ASSERT_EQ(read_image(out, img), "");
    EXPECT_EQ(img.at(4, 4), glm::u8vec3(200, 0, 0));
}

// The course's textured scenes name `texture scenes/x.bmp` from data/scenes/: found through the
// parent directory, with no option, from any current directory.
TEST_F(TextureScene, CliWildScenesFindTheirTextures) {
    const std::string shared = shared_dir();
    WHITTED_NEEDS(test::kSkipSharedTests,
                  shared.empty() ? "the shared folder is not here: set WHITTED_SHARED_DIR or place it at <source>/../shared"
                                 : "");
    const std::string dir = shared + "/scenes/wild/citelao__cse452-computer-graphics/data/scenes";
    ASSERT_TRUE(fs::is_directory(dir)) << dir << " is not in the shared corpus";
    ScopedCwd in(dir_);
    for (const char* name : {"test_texture.sc", "go_board.sc", "test_refraction.sc"}) {
        SCOPED_TRACE(name);
        const std::string out = dir_ + "/" + name + ".png";
        auto r = run_process({cli_path(), dir + "/" + name, "-o", out, "--width", "64", "--height", "48", "-q"});
        EXPECT_EQ(r.exit_code, 0) << r.output;
        EXPECT_EQ(r.output.find("texture"), std::string::npos) << r.output;
        LoadResult loaded = load_scene(dir + "/" + name);
        ASSERT_TRUE(loaded.ok());
        EXPECT_TRUE(loaded.missing_textures.empty());
        EXPECT_GE(loaded.scene->data.textures.size(), 1u);
    }
    // test_texture.sc names four files (earth, darkwood twice, wood twice, pattern1 thrice).
    LoadResult loaded = load_scene(dir + "/test_texture.sc");
    ASSERT_TRUE(loaded.ok());
    EXPECT_EQ(loaded.scene->data.textures.size(), 4u);
}

// ---- the showcase --------------------------------------------------------------------------------

TEST(TextureShowcase, LoadsCleanlyWithTexturesOnAllFourShapes) {
    const std::string path = source_dir() + "/scenes/textures.sc";
    LoadResult r = load_scene(path);
    std::string messages;
    for (const auto& d : r.diagnostics) messages += d.str() + "\n";
    ASSERT_TRUE(r.ok()) << messages;
    EXPECT_TRUE(r.diagnostics.empty()) << messages;
    const SceneData& s = r.scene->data;
    EXPECT_EQ(s.textures.size(), 5u);
    std::set<ShapeKind> textured;
    for (const Instance& i : s.instances)
        if (s.materials[i.material].texture >= 0) textured.insert(i.kind);
    EXPECT_EQ(textured, (std::set<ShapeKind>{ShapeKind::Cube, ShapeKind::Sphere, ShapeKind::Cylinder, ShapeKind::Cone}));
}

}  // namespace
}  // namespace whitted
