// What the CSCI 1230 reader makes of a file (scene-format.md §9.5): transforms in T·R·S·Matrix
// order whatever the key order, lights placed by their groups, the course's defaults, the global
// coefficients folded into the materials, templates, paths from the parent of the file's folder,
// and which files are this dialect.
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include "accel/instance_geometry.h"
#include "cs1230/cs1230_test_support.h"
#include "cs1230/detect.h"
#include "cs1230/scene_reader.h"
#include "mesh/mesh_test_support.h"
#include "support/run_process.h"

namespace whitted {
namespace {

using test::json_scene;
using test::light_group;
using test::primitive_group;

ParseResult read(const std::string& text, const std::string& path = "/nonexistent/scenes/test.json") {
    return cs1230::read_scene(text, path);
}

std::string messages(const ParseResult& r) {
    std::string s;
    for (const Diagnostic& d : r.diagnostics) s += d.str() + "\n";
    return s;
}

// The matrix of the first trans block of the root: the innermost group's, from the root down.
glm::vec3 placed(const ParseResult& r, const glm::vec3& p, std::size_t block = 0) {
    const TransDesc& t = r.scene.subgraphs.at(std::size_t(r.scene.root)).children.at(block);
    return glm::vec3(t.matrix * glm::vec4(p, 1.0f));
}

TEST(Cs1230Reader, GroupTransformsAreTranslateRotateScaleMatrixWhateverTheKeyOrder) {
    // Applied to (1, 0, 0), last first: matrix (translation 0 5 0) → (1, 5, 0); scale 2 1 1 →
    // (2, 5, 0); rotate 90° about z → (−5, 2, 0); translate 1 2 3 → (−4, 4, 3).
    const std::string keys[2] = {
        R"("translate": [1, 2, 3], "rotate": [0, 0, 1, 90], "scale": [2, 1, 1],
           "matrix": [[1, 0, 0, 0], [0, 1, 0, 5], [0, 0, 1, 0], [0, 0, 0, 1]], )",
        R"("matrix": [[1, 0, 0, 0], [0, 1, 0, 5], [0, 0, 1, 0], [0, 0, 0, 1]], "scale": [2, 1, 1],
           "translate": [1, 2, 3], "rotate": [0, 0, 1, 90], )"};
    for (const std::string& k : keys) {
        const ParseResult r = read(json_scene(primitive_group(R"("type": "cube")", k)));
        ASSERT_TRUE(r.ok()) << messages(r);
        test::expect_vec_near(placed(r, {1, 0, 0}), {-4, 4, 3}, 1e-5f);
    }
    // A child's matrix is its parent's times its own: the parent's translate 10 0 0 on top.
    const ParseResult nested =
        read(json_scene(R"({"translate": [10, 0, 0], "groups": [)" + primitive_group(R"("type": "cube")", keys[1]) + "]}"));
    ASSERT_TRUE(nested.ok()) << messages(nested);
    test::expect_vec_near(placed(nested, {1, 0, 0}), {6, 4, 3}, 1e-5f);
}

TEST(Cs1230Reader, LightsArePlacedByTheirGroupsMatrices) {
    // Position = CTM · (0, 0, 0, 1); direction = CTM · (d, 0).
    const ParseResult r = read(json_scene(
        light_group(R"("type": "point", "color": [1, 1, 1], "attenuationCoeff": [1, 0, 0])",
                    R"("translate": [1, 2, 3], "rotate": [0, 1, 0, 30], )") +
        "," +
        light_group(R"("type": "spot", "color": [1, 1, 1], "direction": [1, 0, 0], "angle": 30, "penumbra": 10,
                     "attenuationCoeff": [1, 0, 0])",
                    R"("rotate": [0, 0, 1, 90], )") +
        "," + light_group(R"("type": "directional", "color": [1, 1, 1], "direction": [1, 1, 0])", R"("scale": [1, 2, 1], )")));
    ASSERT_TRUE(r.ok()) << messages(r);
    ASSERT_EQ(r.scene.lights.size(), 3u);
    test::expect_vec_near(r.scene.lights[0].position, {1, 2, 3});
    EXPECT_EQ(r.scene.lights[1].type, LightType::Spot);
    test::expect_vec_near(r.scene.lights[1].direction, {0, 1, 0});
    EXPECT_FLOAT_EQ(r.scene.lights[1].aperture_deg, 30.0f);  // the outer half-angle
    EXPECT_FLOAT_EQ(r.scene.lights[1].penumbra_deg, 10.0f);
    test::expect_vec_near(r.scene.lights[2].direction, {1, 2, 0});
}

TEST(Cs1230Reader, GlobalCoefficientsAreFoldedIntoTheMaterials) {
    // ka 0.2, kd 0.4, ks 0.6, kt 0.8.
    const ParseResult r = read(json_scene(
        primitive_group(R"("type": "sphere", "ambient": [1, 0.5, 0], "diffuse": [0.5, 1, 0.25], "specular": [1, 1, 0.5],
                         "shininess": 10, "reflective": [0.5, 0, 1], "transparent": [1, 0.5, 0.5], "ior": 1.5)"),
        0.2f, 0.4f, 0.6f, 0.8f));
    ASSERT_TRUE(r.ok()) << messages(r);
    const MaterialDesc& m = r.scene.subgraphs[std::size_t(r.scene.root)].children.at(0).objects.at(0).material;
    test::expect_vec_near(m.ambient, {0.2f, 0.1f, 0.0f});
    test::expect_vec_near(m.diffuse, {0.2f, 0.4f, 0.1f});
    test::expect_vec_near(m.specular, {0.6f, 0.6f, 0.3f});
    test::expect_vec_near(m.reflect, {0.3f, 0.0f, 0.6f});
    test::expect_vec_near(m.transparent, {0.8f, 0.4f, 0.4f});
    EXPECT_FLOAT_EQ(m.shine, 10.0f);
    EXPECT_FLOAT_EQ(m.ior, 1.5f);
    EXPECT_EQ(r.scene.lighting, LightingModel::Cs1230);
    EXPECT_EQ(r.scene.dialect, Dialect::Cs1230);
}

TEST(Cs1230Reader, TheCoursesDefaults) {
    // A primitive of only its type: diffuse 1 1 1 (times kd 0.5), everything else 0; without a
    // shininess there is no highlight at all; transparentCoeff defaults to 0; textureU, V to 1,
    // blend to 0.
    std::string text = json_scene(primitive_group(R"("type": "cube")") + "," +
                                  primitive_group(R"("type": "cube", "specular": [1, 1, 1], "textureFile": "t.png")"));
    const std::string no_kt = ", \"transparentCoeff\": 0.000000";
    text.erase(text.find(no_kt), no_kt.size());
    const ParseResult r = read(text);
    ASSERT_TRUE(r.ok()) << messages(r);
    const auto& blocks = r.scene.subgraphs[std::size_t(r.scene.root)].children;
    const MaterialDesc& plain = blocks.at(0).objects.at(0).material;
    test::expect_vec_near(plain.diffuse, glm::vec3(0.5f));
    test::expect_vec_near(plain.ambient, glm::vec3(0.0f));
    test::expect_vec_near(plain.reflect, glm::vec3(0.0f));
    EXPECT_FALSE(plain.texture);
    const MaterialDesc& textured = blocks.at(1).objects.at(0).material;
    test::expect_vec_near(textured.specular, glm::vec3(0.0f));  // shininess 0
    ASSERT_TRUE(textured.texture);
    EXPECT_EQ(textured.texture->repeat_u, 1.0f);
    EXPECT_EQ(textured.texture->repeat_v, 1.0f);
    ASSERT_TRUE(textured.blend);
    EXPECT_EQ(*textured.blend, 0.0f);
}

TEST(Cs1230Reader, TemplatesArePlacedWhereGroupsNameThem) {
    // Template "pair": its own translate 0 1 0, two cubes at x = ±1 and a light at its origin.
    // Used at the top and under translate 5 0 0 (by a group whose own translate is ignored,
    // with a warning): cubes at (±1, 1, 0) and (5 ± 1, 1, 0), lights at (0, 1, 0) and (5, 1, 0).
    const std::string pair = R"({"name": "pair", "translate": [0, 1, 0],
        "lights": [{"type": "point", "color": [1, 1, 1], "attenuationCoeff": [1, 0, 0]}],
        "groups": [)" + primitive_group(R"("type": "cube")", R"("translate": [-1, 0, 0], )") + "," +
                             primitive_group(R"("type": "cube")", R"("translate": [1, 0, 0], )") + "]}";
    const std::string text = json_scene(
        R"({"name": "pair"}, {"translate": [5, 0, 0], "groups": [{"name": "pair", "translate": [100, 0, 0]}]})", 0.5f,
        0.5f, 0.5f, 0.0f, "", pair);
    const LoadResult loaded = test::load_json(text);
    ASSERT_TRUE(loaded.ok()) << test::diagnostics_text(loaded);
    std::vector<glm::vec3> centres;
    for (const Instance& inst : loaded.scene->data.instances)
        centres.push_back(glm::vec3(object_to_world(inst) * glm::vec4(0, 0, 0, 1)));
    std::sort(centres.begin(), centres.end(), [](const glm::vec3& a, const glm::vec3& b) { return a.x < b.x; });
    ASSERT_EQ(centres.size(), 4u);
    const glm::vec3 want[4] = {{-1, 1, 0}, {1, 1, 0}, {4, 1, 0}, {6, 1, 0}};
    for (int i = 0; i < 4; ++i) test::expect_vec_near(centres[std::size_t(i)], want[i], 1e-5f);
    ASSERT_EQ(loaded.scene->data.lights.size(), 2u);
    test::expect_vec_near(loaded.scene->data.lights[0].position, {0, 1, 0});
    test::expect_vec_near(loaded.scene->data.lights[1].position, {5, 1, 0});
    // The ignored translate is named where it is.
    const std::string warnings = test::diagnostics_text(loaded);
    EXPECT_NE(warnings.find("its other keys are ignored"), std::string::npos) << warnings;
}

TEST(Cs1230Reader, ATemplateUsesOnlyTheTemplatesBeforeIt) {
    // "a" has a group named "b" before "b" is defined: a plain group, drawing its own sphere;
    // "b" (a cube) is a template for the groups after it.
    const std::string templates =
        R"({"name": "a", "groups": [{"name": "b", "primitives": [{"type": "sphere"}]}]},
           {"name": "b", "primitives": [{"type": "cube"}]})";
    const LoadResult loaded = test::load_json(json_scene(R"({"name": "a"}, {"name": "b"})", 0.5f, 0.5f, 0.5f, 0.0f, "", templates));
    ASSERT_TRUE(loaded.ok()) << test::diagnostics_text(loaded);
    std::vector<ShapeKind> kinds;
    for (const Instance& i : loaded.scene->data.instances) kinds.push_back(i.kind);
    std::sort(kinds.begin(), kinds.end());
    EXPECT_EQ(kinds, (std::vector<ShapeKind>{ShapeKind::Cube, ShapeKind::Sphere}));
}

TEST(Cs1230Reader, TexturesAndMeshesAreNamedFromTheParentOfTheFilesFolder) {
    const ParseResult r = read(json_scene(""), "/course/illuminate/required/x.json");
    EXPECT_EQ(r.scene.asset_anchor, "/course/illuminate/x.json");
    // A mesh in <dir>/meshes/, the scene in <dir>/scenes/: found.
    const std::string dir = test::make_temp_dir();
    std::filesystem::create_directories(dir + "/meshes");
    test::write_file(dir + "/meshes", "cube.obj", test::cube_obj());
    const LoadResult loaded = test::load_json(
        json_scene(primitive_group(R"("type": "mesh", "meshFile": "meshes/cube.obj")")), dir + "/scenes/m.json");
    ASSERT_TRUE(loaded.ok()) << test::diagnostics_text(loaded);
    EXPECT_EQ(loaded.scene->data.meshes.size(), 1u);
}

TEST(Cs1230Reader, TheDialectIsToldByTheFileNameOrItsFirstByte) {
    EXPECT_TRUE(cs1230::is_json_scene("a/scene.json", ""));
    EXPECT_TRUE(cs1230::is_json_scene("a/SCENE.Json", "camera ["));
    EXPECT_TRUE(cs1230::is_json_scene("scene.sc", " \r\n\t{ \"globalData\""));
    EXPECT_TRUE(cs1230::is_json_scene("scene", "\xEF\xBB\xBF{"));
    EXPECT_FALSE(cs1230::is_json_scene("scene.sc", "camera [ eye 0 0 5 ]"));
    EXPECT_FALSE(cs1230::is_json_scene("json", "# {"));
    // A JSON scene under another name is read as JSON, from disk too.
    const std::string dir = test::make_temp_dir();
    const std::string path = test::write_file(dir, "named.sc", json_scene(primitive_group(R"("type": "cube")")));
    EXPECT_TRUE(cs1230::is_json_scene_file(path));
    LoadOptions o;
    o.threads = 1;
    const LoadResult loaded = load_scene(path, o);
    ASSERT_TRUE(loaded.ok()) << test::diagnostics_text(loaded);
    EXPECT_EQ(loaded.stats.dialect, Dialect::Cs1230);
    EXPECT_STREQ(dialect_name(loaded.stats.dialect), "Brown CSCI 1230 (JSON)");
}

}  // namespace
}  // namespace whitted
