// Textures from bytes another process read (whitted-mpi's ranks get rank 0's files): the files
// kept by one load, given to another with no file on disk, give the same textures.
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>

#include "texture/texture_loader.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

using namespace whitted::test;

struct Load {
    std::vector<std::unique_ptr<ObjectDesc>> objects;
    FlattenResult flat;
    std::vector<Diagnostic> diagnostics;
    std::vector<MissingTexture> missing;
    TextureFiles kept;
};

std::unique_ptr<Load> load(const std::vector<std::string>& names, const std::string& scene, const TextureOptions& o) {
    auto r = std::make_unique<Load>();
    for (std::size_t i = 0; i < names.size(); ++i) {
        auto obj = std::make_unique<ObjectDesc>();
        obj->material.texture = TextureRef{names[i], 1, 1, SourceLoc{scene, int(i) + 1, 7}};
        r->flat.scene.materials.push_back(Material{});
        r->flat.material_sources.push_back(obj.get());
        r->objects.push_back(std::move(obj));
    }
    r->missing = load_textures(r->flat, scene, o, r->diagnostics, &r->kept);
    return r;
}

using TexturePreread = PrivateTextureDirs;

TEST_F(TexturePreread, KeptBytesGiveTheSameTexturesWithoutTheFiles) {
    ASSERT_TRUE(write_png(dir_ + "/t.png", distinct_picture(5, 3)));
    ASSERT_TRUE(write_ppm(dir_ + "/u.ppm", quadrant_picture(8)));
    // "./t.png" is another spelling of t.png: decoded once here, and its name must travel too.
    const std::vector<std::string> names{"t.png", "u.ppm", "./t.png"};
    TextureOptions keep;
    keep.keep_files = true;
    auto first = load(names, scene_, keep);
    ASSERT_TRUE(first->missing.empty());
    ASSERT_EQ(first->kept.size(), 3u);
    EXPECT_EQ(first->kept.at("t.png"), first->kept.at("./t.png"));
    EXPECT_EQ(first->kept.at("u.ppm").size(), std::filesystem::file_size(dir_ + "/u.ppm"));

    std::filesystem::remove_all(dir_);  // the other process has no files
    TextureOptions given;
    given.preread = &first->kept;
    auto second = load(names, scene_, given);
    ASSERT_TRUE(second->missing.empty());
    for (std::size_t m = 0; m < names.size(); ++m) {
        const TextureImage& a = first->flat.scene.textures[std::size_t(first->flat.scene.materials[m].texture)];
        const TextureImage& b = second->flat.scene.textures[std::size_t(second->flat.scene.materials[m].texture)];
        ASSERT_EQ(a.width, b.width);
        ASSERT_EQ(a.height, b.height);
        EXPECT_EQ(a.rgb, b.rgb) << names[m];
    }
}

TEST_F(TexturePreread, ANameNotReceivedIsMissingOrAChecker) {
    const TextureFiles none;
    TextureOptions given;
    given.preread = &none;
    auto r = load({"t.png"}, scene_, given);
    ASSERT_EQ(r->missing.size(), 1u);
    EXPECT_TRUE(has_errors(r->diagnostics));
    given.missing = MissingTexturePolicy::Checker;
    auto c = load({"t.png"}, scene_, given);
    EXPECT_FALSE(has_errors(c->diagnostics));
    EXPECT_EQ(c->flat.scene.textures.at(0).rgb, checker_texture().rgb);
}

}  // namespace
}  // namespace whitted
