// Object blocks: shape types and materials (scene-format.md §7, §8).
#include <gtest/gtest.h>

#include "parse_test_util.h"

namespace whitted {
namespace {

using parse_test::error_at;
using parse_test::parse;
using parse_test::parsed_ok;

ParseResult object(const std::string& body) {
    return parse("mastersubgraph root [ trans [\nobject " + body + " ] ]");
}

const ObjectDesc& first_object(const ParseResult& r) {
    return r.scene.subgraphs.at(r.scene.root).children.at(0).objects.at(0);
}

TEST(ParseMaterial, Defaults) {
    const auto r = object("sphere [ ]");
    ASSERT_TRUE(parsed_ok(r));
    const ObjectDesc& o = first_object(r);
    EXPECT_EQ(o.kind, ShapeKind::Sphere);
    EXPECT_EQ(o.loc.line, 2);
    EXPECT_EQ(o.loc.col, 1);
    EXPECT_EQ(o.material.diffuse, glm::vec3(1));
    EXPECT_EQ(o.material.ambient, glm::vec3(0));
    EXPECT_EQ(o.material.specular, glm::vec3(0));
    EXPECT_EQ(o.material.shine, 1.0f);
    EXPECT_EQ(o.material.ior, 1.0f);
    EXPECT_FALSE(o.material.texture.has_value());
}

TEST(ParseMaterial, AllShapeTypes) {
    const std::pair<const char*, ShapeKind> cases[] = {{"cube", ShapeKind::Cube},
                                                       {"cylinder", ShapeKind::Cylinder},
                                                       {"cone", ShapeKind::Cone},
                                                       {"sphere", ShapeKind::Sphere}};
    for (const auto& [name, kind] : cases) {
        const auto r = object(std::string(name) + " [ ]");
        ASSERT_TRUE(parsed_ok(r));
        EXPECT_EQ(first_object(r).kind, kind);
    }
}

TEST(ParseMaterial, AllKeywordsLaterWins) {
    const auto r = object(
        "cone [ ambient .1 .2 .3 diffuse 0 0 0 diffuse .4 .5 .6 specular 1 1 1 reflect .5 .5 .5 "
        "transparent .9 .8 .7 emit 0 1 0 shine 20 ior 1.5\n   texture scenes/earth.bmp 2 3 ]");
    ASSERT_TRUE(parsed_ok(r));
    const MaterialDesc& m = first_object(r).material;
    EXPECT_EQ(m.ambient, glm::vec3(.1f, .2f, .3f));
    EXPECT_EQ(m.diffuse, glm::vec3(.4f, .5f, .6f));
    EXPECT_EQ(m.specular, glm::vec3(1));
    EXPECT_EQ(m.reflect, glm::vec3(.5f));
    EXPECT_EQ(m.transparent, glm::vec3(.9f, .8f, .7f));
    EXPECT_EQ(m.emit, glm::vec3(0, 1, 0));
    EXPECT_EQ(m.shine, 20.0f);
    EXPECT_EQ(m.ior, 1.5f);
    ASSERT_TRUE(m.texture.has_value());
    EXPECT_EQ(m.texture->file, "scenes/earth.bmp");
    EXPECT_EQ(m.texture->repeat_u, 2.0f);
    EXPECT_EQ(m.texture->repeat_v, 3.0f);
    EXPECT_EQ(m.texture->loc.file, "t.sc");
    EXPECT_EQ(m.texture->loc.line, 3);
    EXPECT_EQ(m.texture->loc.col, 4);
}

TEST(ParseMaterial, TextureFileIsKeptAsWritten) {
    const auto r = object("cube [ texture C:\\data\\wood.bmp 1 1 ]");
    ASSERT_TRUE(parsed_ok(r));
    EXPECT_EQ(first_object(r).material.texture->file, "C:\\data\\wood.bmp");
}

TEST(ParseMaterial, RangeErrorsAtTheValue) {
    EXPECT_TRUE(error_at(object("cube [ ior 0 ]"), 2, 19, "'ior' must be > 0"));
    EXPECT_TRUE(error_at(object("cube [ ior -1.5 ]"), 2, 19, "'ior' must be > 0"));
    EXPECT_TRUE(
        error_at(object("cube [ texture a.bmp 0 1 ]"), 2, 29, "repeat count u must be > 0"));
    EXPECT_TRUE(
        error_at(object("cube [ texture a.bmp 1 -2 ]"), 2, 31, "repeat count v must be > 0"));
    EXPECT_TRUE(error_at(object("cube [ texture ]"), 2, 23, "expected a texture file name"));
}

TEST(ParseMaterial, ObjectTypeErrors) {
    EXPECT_TRUE(error_at(object("teapot [ ]"), 2, 8,
                         "unknown object type 'teapot' (expected one of: cube, cylinder, cone, "
                         "sphere, ellipsoid, mesh); use --lenient"));
    EXPECT_TRUE(error_at(object("]"), 2, 8, "expected an object type after 'object'"));
    EXPECT_TRUE(error_at(object("Cube"), 2, 8, "unknown object type 'Cube'"));  // case-sensitive
}

TEST(ParseMaterial, UnknownKeywordAndStrayNumber) {
    EXPECT_TRUE(error_at(object("cube [ diffuse 1 1 1 opacity 0.9 ]"), 2, 29,
                         "unknown keyword 'opacity' in object block (expected one of: ambient, "
                         "diffuse, specular, reflect, transparent, emit, shine, ior, gloss, texture, alpha, file); use "
                         "--lenient to skip unknown keywords"));
    EXPECT_TRUE(error_at(object("cube [ diffuse 1 1 1 1 ]"), 2, 29,
                         "unexpected number '1' in object block"));
}

}  // namespace
}  // namespace whitted
