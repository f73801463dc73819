// Finding and decoding texture files (scene-format.md §8): every format, the lookup order,
// both separators, one decode per file, the missing-texture report and the checker fallback.
#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <memory>
#include <thread>

#include "support/run_process.h"
#include "texture/texture_loader.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

namespace fs = std::filesystem;
using namespace whitted::test;

// load_textures on a hand-made flattened scene: one material per name, no parser involved.
struct TextureLoad {
    std::vector<std::unique_ptr<ObjectDesc>> objects;
    FlattenResult flat;
    std::vector<MissingTexture> missing;
    std::vector<Diagnostic> diagnostics;
    std::string messages() const {
        std::string s;
        for (const auto& d : diagnostics) s += d.str() + "\n";
        return s;
    }
};

std::unique_ptr<TextureLoad> load_names(const std::vector<std::string>& names, const std::string& scene_path,
                                        const TextureOptions& options = {}) {
    auto r = std::make_unique<TextureLoad>();
    for (std::size_t i = 0; i < names.size(); ++i) {
        auto obj = std::make_unique<ObjectDesc>();
        obj->material.texture = TextureRef{names[i], 1, 1, SourceLoc{scene_path, int(i) + 1, 7}};
        r->flat.scene.materials.push_back(Material{});
        r->flat.material_sources.push_back(obj.get());
        r->objects.push_back(std::move(obj));
    }
    r->missing = load_textures(r->flat, scene_path, options, r->diagnostics);
    return r;
}

glm::u8vec3 texel_byte(const TextureImage& img, int x, int y) {
    const glm::vec3 c = img.texel(std::size_t(y) * img.width + x) * 255.0f + 0.5f;
    return {std::uint8_t(c.x), std::uint8_t(c.y), std::uint8_t(c.z)};
}

void expect_same_picture(const TextureImage& img, const Picture& want, int tolerance = 0) {
    ASSERT_EQ(img.width, want.width);
    ASSERT_EQ(img.height, want.height);
    for (int y = 0; y < want.height; ++y)
        for (int x = 0; x < want.width; ++x) {
            const glm::u8vec3 got = texel_byte(img, x, y), w = want.at(x, y);
            for (int c = 0; c < 3; ++c)
                ASSERT_LE(std::abs(int(got[c]) - int(w[c])), tolerance)
                    << "texel (" << x << ", " << y << ") channel " << c << ": " << int(got[c]) << " vs " << int(w[c]);
        }
}

Picture one_texel(glm::u8vec3 c) {
    Picture p(1, 1);
    p.set(0, 0, c);
    return p;
}

using TextureLoader = PrivateTextureDirs;

// ---- formats ---------------------------------------------------------------------------------

TEST_F(TextureLoader, DecodesEveryFormatRowZeroAtTheTop) {
    const Picture pic = distinct_picture(5, 3);  // odd width: 24-bit BMP rows need padding
    struct Case {
        const char* file;
        bool (*write)(const std::string&, const Picture&);
    };
    const Case cases[] = {
        {"a.png", write_png},
        {"a.tga", write_tga},
        {"a.ppm", write_ppm},
        {"stb24.bmp", write_bmp_stb},
        {"bottom_up24.bmp", [](const std::string& p, const Picture& x) { return write_bmp(p, x, 24, false); }},
        {"top_down24.bmp", [](const std::string& p, const Picture& x) { return write_bmp(p, x, 24, true); }},
        {"bottom_up32.bmp", [](const std::string& p, const Picture& x) { return write_bmp(p, x, 32, false); }},
        {"top_down32.bmp", [](const std::string& p, const Picture& x) { return write_bmp(p, x, 32, true); }},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file);
        ASSERT_TRUE(c.write(dir_ + "/" + c.file, pic));
        auto r = load_names({c.file}, scene_);
        ASSERT_TRUE(r->missing.empty()) << r->messages();
        ASSERT_EQ(r->flat.scene.textures.size(), 1u);
        EXPECT_EQ(r->flat.scene.materials[0].texture, 0);
        expect_same_picture(r->flat.scene.textures[0], pic);
    }
}

TEST_F(TextureLoader, DecodesJpeg) {
    const Picture pic = quadrant_picture(32);
    ASSERT_TRUE(write_jpg(dir_ + "/q.jpg", pic));
    auto r = load_names({"q.jpg"}, scene_);
    ASSERT_TRUE(r->missing.empty()) << r->messages();
    const TextureImage& img = r->flat.scene.textures.at(0);
    ASSERT_EQ(img.width, 32);
    ASSERT_EQ(img.height, 32);
    // Lossy: compare the middle of each quadrant, away from the colour edges.
    for (auto [x, y] : {std::pair{8, 8}, std::pair{24, 8}, std::pair{8, 24}, std::pair{24, 24}}) {
        const glm::u8vec3 got = texel_byte(img, x, y), want = pic.at(x, y);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 8) << x << " " << y << " channel " << c;
    }
}

// A texel is byte / 255, linear; alpha is ignored (not premultiplied); grey becomes r = g = b.
TEST_F(TextureLoader, TexelValuesAlphaAndGrey) {
    const std::uint8_t rgba[] = {255, 128, 0, 0, 10, 20, 30, 128};  // 2 × 1, alpha 0 and 128
    ASSERT_TRUE(stbi_write_png((dir_ + "/alpha.png").c_str(), 2, 1, 4, rgba, 8));
    const std::uint8_t grey[] = {0, 51, 255};
    ASSERT_TRUE(stbi_write_png((dir_ + "/grey.png").c_str(), 3, 1, 1, grey, 3));
    auto r = load_names({"alpha.png", "grey.png"}, scene_);
    ASSERT_TRUE(r->missing.empty()) << r->messages();
    const TextureImage& a = r->flat.scene.textures.at(r->flat.scene.materials[0].texture);
    EXPECT_EQ(a.texel(0), glm::vec3(1.0f, 128 / 255.0f, 0.0f));
    EXPECT_EQ(a.texel(1), glm::vec3(10, 20, 30) / 255.0f);
    const TextureImage& g = r->flat.scene.textures.at(r->flat.scene.materials[1].texture);
    EXPECT_EQ(g.texel(1), glm::vec3(0.2f));
    EXPECT_EQ(g.texel(2), glm::vec3(1.0f));
}

// ---- lookup order --------------------------------------------------------------------------------

// The places FILE is tried, in the spec's order, every one absolute.
TEST_F(TextureLoader, CandidatesInTheSpecOrder) {
    const std::string cwd = dir_ + "/cwd";
    fs::create_directories(cwd);
    ScopedCwd in(cwd);
    const auto c = texture_candidates("tex/t.png", dir_ + "/data/scenes/s.sc", {dir_ + "/extra1", dir_ + "/extra2"});
    const std::vector<std::string> want = {dir_ + "/data/scenes/tex/t.png", dir_ + "/data/tex/t.png",
                                           fs::current_path().string() + "/tex/t.png", dir_ + "/extra1/tex/t.png",
                                           dir_ + "/extra2/tex/t.png"};
    EXPECT_EQ(c, want);
    // `\` separates directories too, in FILE and in a search dir.
    EXPECT_EQ(texture_candidates("tex\\t.png", dir_ + "/data/scenes/s.sc", {dir_ + "\\extra1", dir_ + "/extra2"}), want);
    // A scene path relative to the current directory.
    EXPECT_EQ(texture_candidates("t.png", "s.sc", {})[0], fs::current_path().string() + "/t.png");
    // Absolute: only as written.
    EXPECT_EQ(texture_candidates(dir_ + "/abs.png", dir_ + "/data/scenes/s.sc", {dir_}),
              std::vector<std::string>{dir_ + "/abs.png"});
    EXPECT_EQ(texture_candidates(dir_ + "\\sub\\abs.png", "s.sc", {}), std::vector<std::string>{dir_ + "/sub/abs.png"});
    // A place reached twice is tried once (scene in the current directory).
    const auto once = texture_candidates("t.png", cwd + "/s.sc", {cwd});
    EXPECT_EQ(once, (std::vector<std::string>{cwd + "/t.png", dir_ + "/t.png"}));
}

// The same name in every place, each a different colour: the first place in the order wins;
// taking files away one by one walks down the list.
TEST_F(TextureLoader, FirstPlaceInTheOrderWins) {
    const std::string scene = dir_ + "/data/scenes/s.sc";
    const std::string cwd = dir_ + "/cwd";
    const std::vector<std::pair<std::string, glm::u8vec3>> places = {
        {dir_ + "/data/scenes/tex/t.png", {10, 0, 0}},  // the scene's directory
        {dir_ + "/data/tex/t.png", {20, 0, 0}},         // its parent
        {cwd + "/tex/t.png", {30, 0, 0}},               // the current directory
        {dir_ + "/extra1/tex/t.png", {40, 0, 0}},       // --texture-path, first
        {dir_ + "/extra2/tex/t.png", {50, 0, 0}},       // --texture-path, second
    };
    for (const auto& [path, colour] : places) {
        fs::create_directories(fs::path(path).parent_path());
        ASSERT_TRUE(write_png(path, one_texel(colour)));
    }
    fs::create_directories(dir_ + "/data/scenes");
    ScopedCwd in(cwd);
    TextureOptions options;
    options.search_dirs = {dir_ + "/extra1", dir_ + "/extra2"};
    for (const char* name : {"tex/t.png", "tex\\t.png"}) {
        for (std::size_t i = 0; i < places.size(); ++i) {
            SCOPED_TRACE(std::string(name) + " with " + places[i].first + " first");
            auto r = load_names({name}, scene, options);
            ASSERT_TRUE(r->missing.empty()) << r->messages();
            EXPECT_EQ(texel_byte(r->flat.scene.textures.at(0), 0, 0), places[i].second);
            fs::rename(places[i].first, places[i].first + ".hidden");
        }
        auto r = load_names({name}, scene, options);
        ASSERT_EQ(r->missing.size(), 1u);
        std::vector<std::string> all;
        for (const auto& [path, colour] : places) all.push_back(path);
        // A Windows path (`tex\t.png`) also tries its trailing parts (§9.4), after all of these.
        if (is_windows_path(name))
            for (const auto& c : loose_texture_candidates(name, scene, options.search_dirs)) all.push_back(c);
        EXPECT_EQ(r->missing[0].tried, all);
        for (const auto& [path, colour] : places) fs::rename(path + ".hidden", path);
    }
}

TEST_F(TextureLoader, AbsolutePathAndDotDot) {
    ASSERT_TRUE(write_png(dir_ + "/abs.png", one_texel({1, 2, 3})));
    fs::create_directories(dir_ + "/a/b");
    auto r = load_names({dir_ + "/abs.png", "../../abs.png"}, dir_ + "/a/b/s.sc");
    ASSERT_TRUE(r->missing.empty()) << r->messages();
    EXPECT_EQ(r->flat.scene.textures.size(), 1u);  // the same file by two names: decoded once
}

// ---- decode once --------------------------------------------------------------------------------

TEST_F(TextureLoader, EachFileIsDecodedOnce) {
    ASSERT_TRUE(write_png(dir_ + "/t.png", one_texel({1, 2, 3})));
    ASSERT_TRUE(write_png(dir_ + "/u.png", one_texel({4, 5, 6})));
    fs::create_directories(dir_ + "/sub");
    auto r = load_names({"t.png", "u.png", "t.png", "./sub/../t.png", "t.png", "u.png"}, scene_);
    ASSERT_TRUE(r->missing.empty()) << r->messages();
    const auto& s = r->flat.scene;
    ASSERT_EQ(s.textures.size(), 2u);
    const int t = s.materials[0].texture, u = s.materials[1].texture;
    EXPECT_NE(t, u);
    EXPECT_EQ(s.materials[2].texture, t);
    EXPECT_EQ(s.materials[3].texture, t);
    EXPECT_EQ(s.materials[4].texture, t);
    EXPECT_EQ(s.materials[5].texture, u);
}

// ---- missing textures -----------------------------------------------------------------------------

TEST_F(TextureLoader, MissingTextureIsReportedAsData) {
    ASSERT_TRUE(write_png(dir_ + "/here.png", one_texel({1, 2, 3})));
    TextureOptions options;
    options.search_dirs = {dir_ + "/extra"};
    auto r = load_names({"here.png", "gone.png", "gone.png", "lost/away.bmp"}, scene_, options);
    // One report per name, at the first `texture` that used it, each with every place tried.
    ASSERT_EQ(r->missing.size(), 2u);
    EXPECT_EQ(r->missing[0].name, "gone.png");
    EXPECT_EQ(r->missing[0].loc.line, 2);
    EXPECT_EQ(r->missing[0].loc.col, 7);
    EXPECT_EQ(r->missing[0].reason, "not found");
    EXPECT_EQ(r->missing[0].tried, texture_candidates("gone.png", scene_, options.search_dirs));
    EXPECT_EQ(r->missing[0].tried.size(), 4u);  // scene dir, parent, cwd, extra
    EXPECT_EQ(r->missing[1].name, "lost/away.bmp");
    EXPECT_EQ(r->missing[1].tried, texture_candidates("lost/away.bmp", scene_, options.search_dirs));
    EXPECT_EQ(r->flat.scene.materials[1].texture, -1);
    EXPECT_EQ(r->flat.scene.materials[2].texture, -1);
    // They are errors, each naming every path it tried.
    ASSERT_TRUE(has_errors(r->diagnostics));
    int errors = 0;
    for (const auto& d : r->diagnostics) {
        if (d.severity != Severity::Error) continue;
        ++errors;
        const MissingTexture& m = r->missing[errors - 1];
        EXPECT_NE(d.message.find(m.name), std::string::npos) << d.message;
        for (const auto& p : m.tried) EXPECT_NE(d.message.find(p), std::string::npos) << p << "\n" << d.message;
        EXPECT_EQ(d.loc.line, m.loc.line);
    }
    EXPECT_EQ(errors, 2);
}

// The viewer's retry: the user's answer for a name is tried first.
TEST_F(TextureLoader, OverridesAnswerAMissingTexture) {
    auto r = load_names({"gone.png"}, scene_);
    ASSERT_EQ(r->missing.size(), 1u);
    ASSERT_TRUE(write_png(dir_ + "/elsewhere.png", one_texel({7, 8, 9})));
    TextureOptions options;
    options.overrides[r->missing[0].name] = dir_ + "/elsewhere.png";
    r = load_names({"gone.png"}, scene_, options);
    ASSERT_TRUE(r->missing.empty()) << r->messages();
    EXPECT_EQ(texel_byte(r->flat.scene.textures.at(0), 0, 0), glm::u8vec3(7, 8, 9));
}

TEST_F(TextureLoader, UndecodableFile) {
    write_text(dir_ + "/bad.png", "this is not a PNG file");
    auto r = load_names({"bad.png"}, scene_);
    ASSERT_EQ(r->missing.size(), 1u);
    EXPECT_NE(r->missing[0].reason.find("cannot decode"), std::string::npos) << r->missing[0].reason;
    EXPECT_EQ(r->missing[0].tried, texture_candidates("bad.png", scene_, {}));
    EXPECT_TRUE(has_errors(r->diagnostics));

    // A good copy further down the list is used, with a warning about the bad one.
    fs::create_directories(dir_ + "/extra");
    ASSERT_TRUE(write_png(dir_ + "/extra/bad.png", one_texel({9, 9, 9})));
    TextureOptions options;
    options.search_dirs = {dir_ + "/extra"};
    r = load_names({"bad.png"}, scene_, options);
    ASSERT_TRUE(r->missing.empty()) << r->messages();
    EXPECT_FALSE(has_errors(r->diagnostics));
    ASSERT_EQ(r->diagnostics.size(), 1u);
    EXPECT_EQ(r->diagnostics[0].severity, Severity::Warning);
    EXPECT_EQ(texel_byte(r->flat.scene.textures.at(0), 0, 0), glm::u8vec3(9, 9, 9));
}

TEST_F(TextureLoader, TruncatedFilesAreReportedNotDrawnBlack) {
    // stb_image fills the missing end of a BMP, TGA or PPM with zeros and says it succeeded; a
    // texture cut short must be reported like any file that cannot be decoded.
    const Picture pic = quadrant_picture(16);
    struct Case {
        const char* file;
        bool (*write)(const std::string&, const Picture&);
    };
    const Case cases[] = {
        {"t.png", write_png},
        {"t.tga", write_tga},
        {"t.ppm", write_ppm},
        {"t.jpg", write_jpg},
        {"t24.bmp", [](const std::string& p, const Picture& x) { return write_bmp(p, x, 24, false); }},
        {"t32.bmp", [](const std::string& p, const Picture& x) { return write_bmp(p, x, 32, true); }},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.file);
        const std::string path = dir_ + "/" + c.file;
        ASSERT_TRUE(c.write(path, pic));
        auto whole = load_names({c.file}, scene_);
        ASSERT_TRUE(whole->missing.empty()) << whole->messages();
        // Cut off the last 40%: the header is intact, the pixels are not all there.
        fs::resize_file(path, fs::file_size(path) * 6 / 10);
        auto cut = load_names({c.file}, scene_);
        ASSERT_EQ(cut->missing.size(), 1u) << cut->messages();
        EXPECT_NE(cut->missing[0].reason.find("cannot decode"), std::string::npos) << cut->missing[0].reason;
        EXPECT_TRUE(has_errors(cut->diagnostics));
    }
}

TEST_F(TextureLoader, DeclinedNamesAreCheckeredAndTheOthersStillErrors) {
    // The viewer's user pressed Cancel for gone.png: it is a checkerboard from then on, while a
    // texture missing for the first time still stops the load (so that it can be asked about).
    TextureOptions options;
    options.checker_names = {"gone.png"};
    auto r = load_names({"gone.png", "new.png"}, scene_, options);
    ASSERT_EQ(r->missing.size(), 2u);  // both still reported as data
    ASSERT_EQ(r->diagnostics.size(), 2u) << r->messages();
    EXPECT_EQ(r->diagnostics[0].severity, Severity::Warning);
    EXPECT_NE(r->diagnostics[0].message.find("'gone.png': not found (drawn as a checkerboard)"), std::string::npos)
        << r->diagnostics[0].message;
    EXPECT_EQ(r->diagnostics[1].severity, Severity::Error);
    EXPECT_NE(r->diagnostics[1].message.find("'new.png'"), std::string::npos) << r->diagnostics[1].message;
    options.checker_names.insert("new.png");
    r = load_names({"gone.png", "new.png"}, scene_, options);
    EXPECT_FALSE(has_errors(r->diagnostics)) << r->messages();
}

TEST_F(TextureLoader, CheckerFallback) {
    TextureOptions options;
    options.missing = MissingTexturePolicy::Checker;
    auto r = load_names({"gone.png", "also_gone.png", "gone.png"}, scene_, options);
    EXPECT_EQ(r->missing.size(), 2u);  // still reported as data
    EXPECT_FALSE(has_errors(r->diagnostics)) << r->messages();
    ASSERT_EQ(r->diagnostics.size(), 2u);
    EXPECT_EQ(r->diagnostics[0].severity, Severity::Warning);
    EXPECT_NE(r->diagnostics[0].message.find("checker"), std::string::npos);
    ASSERT_EQ(r->flat.scene.textures.size(), 1u);  // one shared checkerboard
    for (const auto& m : r->flat.scene.materials) EXPECT_EQ(m.texture, 0);
    // Magenta and black squares, big enough that bilinear filtering leaves them solid.
    const TextureImage& c = r->flat.scene.textures[0];
    int magenta = 0, black = 0;
    const std::size_t texels = std::size_t(c.width) * c.height;
    for (std::size_t i = 0; i < texels; ++i)
        magenta += c.texel(i) == glm::vec3(1, 0, 1), black += c.texel(i) == glm::vec3(0);
    EXPECT_EQ(magenta + black, int(texels));
    EXPECT_EQ(magenta, black);
    EXPECT_EQ(checker_texture().rgb, c.rgb);
}

// A texture is read only if it is a regular file, and its size is
// checked before a byte is read (an 8 GB file was read whole, byte by byte, then refused).
TEST_F(TextureLoader, ReadsOnlyRegularFilesWithinTheSizeLimit) {
    // A sparse file just over the 256 MiB limit: refused from its size, nothing read.
    const std::string big = dir_ + "/big.ppm";
    write_text(big, "P6 1 1 255\n");
    fs::resize_file(big, (std::uintmax_t(256) << 20) + 1);
    auto r = load_names({"big.ppm"}, scene_);
    ASSERT_EQ(r->missing.size(), 1u) << r->messages();
    EXPECT_NE(r->missing[0].reason.find("it is 268435457 bytes, more than the limit of 256.0 MiB"), std::string::npos)
        << r->missing[0].reason;
    // A device never ends: refused as what it is, not read.
    r = load_names({"/dev/zero"}, scene_);
    ASSERT_EQ(r->missing.size(), 1u) << r->messages();
    EXPECT_NE(r->missing[0].reason.find("not a regular file"), std::string::npos) << r->missing[0].reason;
}

}  // namespace
}  // namespace whitted

namespace whitted {
namespace {

// --untrusted: a file outside the folders and a file that is not there
// are one message (the answer must not tell which paths exist outside), and the lookup opens a
// texture beneath its folder in one step: a link swapped in after a check cannot lead out, as it
// did in 16 of 300 runs when a canonical name was checked and then opened again.
TEST_F(TextureLoader, ConfinedOutsideAndMissingAreOneMessage) {
    fs::create_directories(dir_ + "/class");
    const std::string scene = dir_ + "/class/s.sc";
    ASSERT_TRUE(write_png(dir_ + "/secret.png", one_texel({1, 2, 3})));
    TextureOptions options;
    options.confined = true;
    auto outside = load_names({"../secret.png"}, scene, options);
    auto missing = load_names({"../nothing.png"}, scene, options);
    ASSERT_EQ(outside->missing.size(), 1u);
    ASSERT_EQ(missing->missing.size(), 1u);
    EXPECT_EQ(outside->missing[0].reason, missing->missing[0].reason);
    EXPECT_NE(outside->missing[0].reason.find("not found inside the scene's folder"), std::string::npos)
        << outside->missing[0].reason;
    // A link out: the same.
    fs::create_symlink("../secret.png", dir_ + "/class/link.png");
    auto link = load_names({"link.png"}, scene, options);
    ASSERT_EQ(link->missing.size(), 1u);
    EXPECT_EQ(link->missing[0].reason, missing->missing[0].reason);
    // A link that stays inside is followed.
    ASSERT_TRUE(write_png(dir_ + "/class/real.png", one_texel({9, 9, 9})));
    fs::create_symlink("real.png", dir_ + "/class/alias.png");
    auto alias = load_names({"alias.png"}, scene, options);
    EXPECT_TRUE(alias->missing.empty()) << alias->messages();
}

TEST_F(TextureLoader, ConfinedLookupNeverReadsThroughALinkSwappedIn) {
    fs::create_directories(dir_ + "/class");
    const std::string scene = dir_ + "/class/s.sc", in = dir_ + "/class/";
    ASSERT_TRUE(write_png(dir_ + "/secret.png", Picture(3, 3)));  // outside: 3 × 3
    ASSERT_TRUE(write_png(in + "real.png", Picture(1, 1)));        // inside: 1 × 1
    ASSERT_EQ(link((in + "real.png").c_str(), (in + "t.png").c_str()), 0);
    std::atomic<bool> done{false};
    std::thread swapper([&] {
        // t.png is, in turn, the inside file and a link to the outside one: each swap one rename.
        for (int i = 0; !done; ++i) {
            const std::string next = in + "next";
            if (i % 2) {
                (void)!link((in + "real.png").c_str(), next.c_str());
            } else {
                (void)!symlink("../secret.png", next.c_str());
            }
            (void)!rename(next.c_str(), (in + "t.png").c_str());
        }
    });
    TextureOptions options;
    options.confined = true;
    int inside = 0, outside = 0;
    for (int run = 0; run < 300; ++run) {
        auto r = load_names({"t.png"}, scene, options);
        if (r->flat.scene.textures.empty()) continue;  // found as the link: refused, as it should be
        const int w = r->flat.scene.textures[0].width;
        (w == 1 ? inside : outside)++;
    }
    done = true;
    swapper.join();
    EXPECT_EQ(outside, 0) << "read the file outside the folder " << outside << " times";
    EXPECT_GT(inside, 0);
}

}  // namespace
}  // namespace whitted
