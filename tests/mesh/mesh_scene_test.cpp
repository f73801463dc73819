// `object mesh` end to end (scene-format.md §9.3): the parser's `file` keyword, the lookup and its
// located errors, one mesh per file however many objects name it, and the 12-triangle cube
// rendering as `object cube` does in every mode.
#include <cstdlib>
#include <filesystem>

#include <gtest/gtest.h>

#include "accel/scene.h"
#include "mesh_test_support.h"
#include "render/load_scene.h"
#include "render/renderer.h"
#include "support/run_process.h"
#include "texture/texture_test_support.h"

namespace whitted {
namespace {

using MeshScene = test::PrivateTextureDirs;

std::string errors_of(const LoadResult& r) {
    std::string s;
    for (const Diagnostic& d : r.diagnostics) s += d.str() + "\n";
    return s;
}

TEST_F(MeshScene, OneMeshPerFileHoweverManyObjectsAndInstances) {
    test::write_file(dir_, "cube.obj", test::cube_obj());
    std::filesystem::create_directories(dir_ + "/models");
    test::write_file(dir_ + "/models", "cube.obj", test::cube_obj());
    const LoadResult r = load_scene_text(
        "mastersubgraph thing [ trans [ object mesh [ file cube.obj diffuse 1 0 0 ] ] ]\n"
        "mastersubgraph root [\n"
        "  trans [ translate 2 0 0 subgraph thing ]\n"
        "  trans [ translate -2 0 0 subgraph thing ]\n"
        "  trans [ object mesh [ file cube.obj diffuse 0 1 0 ] ]\n"
        "  trans [ object mesh [ file models/../cube.obj ] ]\n"
        "  trans [ object mesh [ file models/cube.obj ] ]\n"
        "]\n",
        scene_);
    ASSERT_TRUE(r.ok()) << errors_of(r);
    EXPECT_EQ(r.scene->data.instances.size(), 5u);
    EXPECT_EQ(r.scene->data.meshes.size(), 2u);  // cube.obj (three spellings) and models/cube.obj
    for (const Instance& inst : r.scene->data.instances) {
        EXPECT_EQ(inst.kind, ShapeKind::Mesh);
        EXPECT_LT(inst.mesh, 2u);
    }
}

TEST_F(MeshScene, MissingFileIsAnErrorAtTheFileKeywordWithEveryPathTried) {
    const LoadResult r = load_scene_text("mastersubgraph root [\n"
                                         "  trans [ object mesh [ diffuse 1 1 1\n"
                                         "      file nowhere.obj ] ]\n"
                                         "]\n",
                                         scene_);
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u) << errors_of(r);
    const Diagnostic& d = r.diagnostics[0];
    EXPECT_EQ(d.severity, Severity::Error);
    EXPECT_EQ(d.loc.line, 3);
    EXPECT_EQ(d.loc.col, 7);
    EXPECT_NE(d.message.find("nowhere.obj"), std::string::npos);
    EXPECT_NE(d.message.find("tried: " + dir_ + "/nowhere.obj"), std::string::npos) << d.message;
}

TEST_F(MeshScene, BadFaceIndexIsAnErrorAtTheFileKeywordNamingTheObjLine) {
    test::write_file(dir_, "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
    const LoadResult r = load_scene_text("mastersubgraph root [ trans [ object mesh [ file bad.obj ] ] ]\n", scene_);
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u) << errors_of(r);
    const Diagnostic& d = r.diagnostics[0];
    EXPECT_EQ(d.loc.line, 1);
    EXPECT_EQ(d.loc.col, 45);
    EXPECT_NE(d.message.find(dir_ + "/bad.obj:5: face refers to vertex 9"), std::string::npos) << d.message;
}

TEST_F(MeshScene, EmptyMeshIsAnErrorAndDegenerateTrianglesOneWarningPerFile) {
    test::write_file(dir_, "empty.obj", "v 0 0 0\n");
    LoadResult r = load_scene_text("mastersubgraph root [ trans [ object mesh [ file empty.obj ] ] ]\n", scene_);
    ASSERT_FALSE(r.ok());
    ASSERT_EQ(r.diagnostics.size(), 1u);
    EXPECT_NE(r.diagnostics[0].message.find("no triangle"), std::string::npos) << errors_of(r);

    test::write_file(dir_, "some.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 4\nf 2 3 3\n");
    r = load_scene_text("mastersubgraph root [ trans [ object mesh [ file some.obj ] object mesh [ file some.obj ] ] ]\n",
                        scene_);
    ASSERT_TRUE(r.ok()) << errors_of(r);
    ASSERT_EQ(r.diagnostics.size(), 1u) << errors_of(r);
    EXPECT_EQ(r.diagnostics[0].severity, Severity::Warning);
    EXPECT_NE(r.diagnostics[0].message.find("2 degenerate triangles"), std::string::npos) << errors_of(r);
}

TEST_F(MeshScene, FileKeywordBelongsToMeshesAndMeshesNeedIt) {
    LoadResult r = load_scene_text("mastersubgraph root [ trans [ object cube [ file a.obj ] ] ]\n", scene_);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].loc.col, 45);
    EXPECT_NE(r.diagnostics[0].message.find("'file'"), std::string::npos) << errors_of(r);
    r = load_scene_text("mastersubgraph root [ trans [\n  object mesh [ diffuse 1 0 0 ] ] ]\n", scene_);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.diagnostics[0].loc.line, 2);
    EXPECT_EQ(r.diagnostics[0].loc.col, 3);
    EXPECT_NE(r.diagnostics[0].message.find("file PATH"), std::string::npos) << errors_of(r);
}

TEST_F(MeshScene, CliReportsAMissingMeshWithItsLocation) {
    test::write_file(dir_, "scene.sc", "mastersubgraph root [ trans [ object mesh [ file gone.obj ] ] ]\n");
    const std::string out = dir_ + "/out.png";
    const test::ProcessResult p = test::run_process({test::cli_path(), scene_, "-o", out});
    EXPECT_NE(p.exit_code, 0);
    EXPECT_NE(p.output.find(scene_ + ":1:45: error: mesh file 'gone.obj' not found"), std::string::npos) << p.output;
    EXPECT_FALSE(std::filesystem::exists(out));
}

// The same scene with `object cube` and with the OBJ cube in its place (same trans, same material).
std::string cube_scene(const std::string& shape, const std::string& extra_camera, const std::string& extra_light,
                       const std::string& material) {
    const std::string object = shape == "cube" ? "object cube [ " : "object mesh [ file cube.obj ";
    return "camera [ eye 2.2 1.6 3 focus 0 0 0 angle 40 " + extra_camera +
           " ]\n"
           "background [ color 0.1 0.1 0.2 ]\n"
           "light [ type point position 3 4 2 color 0.8 0.8 0.8 " + extra_light +
           " ]\n"
           "light [ type directional direction -1 -2 -1 color 0.3 0.3 0.3 ]\n"
           "mastersubgraph root [\n"
           "  trans [ rotate 0 1 0 20 scale 1 1.2 0.9 " + object + material +
           " ] ]\n"
           "  trans [ translate 0 -1 0 scale 6 0.2 6 object cube [ diffuse 0.8 0.8 0.8 ] ]\n"
           "  trans [ translate -1.3 0.2 -1.2 object sphere [ diffuse 0.9 0.2 0.2 ] ]\n"
           "]\n";
}

// Pixels whose colour differs by more than 2/255 in some channel.
int differing_pixels(const Image& a, const Image& b) {
    int n = 0;
    for (std::size_t i = 0; i < a.rgb.size(); i += 3)
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(a.rgb[i + c]) - int(b.rgb[i + c])) > 2) {
                ++n;
                break;
            }
    return n;
}

TEST_F(MeshScene, TwelveTriangleCubeRendersAsObjectCubeInEveryMode) {
    test::write_file(dir_, "cube.obj", test::cube_obj());
    ASSERT_TRUE(test::write_png(dir_ + "/quad.png", test::quadrant_picture(16)));
    struct Variant {
        const char* name;
        RenderMode mode;
        std::string material, camera, light;
        int spp;
    };
    const Variant variants[] = {
        {"whitted", RenderMode::Whitted, "diffuse 0.2 0.6 0.9 specular 0.5 0.5 0.5 shine 30", "", "", 1},
        {"textured", RenderMode::Whitted, "diffuse 1 1 1 texture quad.png 2 1", "", "", 1},
        {"mirror", RenderMode::Whitted, "diffuse 0.1 0.1 0.1 reflect 0.8 0.8 0.8", "", "", 1},
        {"glass", RenderMode::Whitted, "diffuse 0 0 0 transparent 0.9 0.9 0.9 ior 1.5", "", "", 1},
        {"raycast", RenderMode::Raycast, "diffuse 0.2 0.6 0.9", "", "", 1},
        {"normals", RenderMode::Normals, "diffuse 0.2 0.6 0.9", "", "", 1},
        {"depth", RenderMode::Depth, "diffuse 0.2 0.6 0.9", "", "", 1},
        {"effects", RenderMode::Whitted, "diffuse 0.3 0.3 0.3 reflect 0.6 0.6 0.6 gloss 200", "aperture 0.05",
         "radius 0.4", 4},
        {"path", RenderMode::Path, "diffuse 0.2 0.6 0.9 specular 0.3 0.3 0.3 shine 30", "", "", 4},
        {"path-glass", RenderMode::Path, "diffuse 0 0 0 transparent 0.9 0.9 0.9 ior 1.5", "", "", 4},
    };
    for (const Variant& v : variants) {
        Image images[2] = {Image(96, 72), Image(96, 72)};
        for (int k = 0; k < 2; ++k) {
            const LoadResult r = load_scene_text(cube_scene(k == 0 ? "cube" : "mesh", v.camera, v.light, v.material),
                                                 scene_);
            ASSERT_TRUE(r.ok()) << v.name << ": " << errors_of(r);
            RenderJob job;
            job.width = 96;
            job.height = 72;
            job.integrator.mode = v.mode;
            job.sampling.spp = v.spp;
            job.threads = 2;
            render(*r.scene, job, images[k]);
        }
        // The two differ only where a ray grazes an edge of the cube (the quadric slab test and
        // the triangles round differently there) or meets a texel boundary at a face's rim.
        const int diff = differing_pixels(images[0], images[1]);
        EXPECT_LE(diff, 12) << v.name;
        RecordProperty(v.name, diff);
        if (v.mode == RenderMode::Raycast) {
            // The camera looks at the cube's centre: the middle pixel is the unlit diffuse colour.
            const std::uint8_t* mid = &images[1].rgb[(36 * 96 + 48) * 3];
            EXPECT_EQ(int(mid[0]), 51);
            EXPECT_EQ(int(mid[1]), 153);
            EXPECT_EQ(int(mid[2]), 230);
        }
    }
}

}  // namespace
}  // namespace whitted
