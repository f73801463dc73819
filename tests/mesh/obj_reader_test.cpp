// Reading OBJ files (scene-format.md §9.3): polygons triangulated, normals and texture coordinates
// kept per corner (a vertex per distinct v/vt/vn), degenerate triangles skipped, and every error with the OBJ line it is on.
#include <gtest/gtest.h>

#include "mesh/obj_reader.h"
#include "mesh_test_support.h"
#include "support/run_process.h"

namespace whitted {
namespace {

TEST(ObjReader, TriangulatesPolygonsAndKeepsCornerAttributes) {
    TriangleMesh m;
    const ObjReadResult r = read_obj_text(
        "# a quad and a triangle\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\n"
        "vn 0 0 1\nvn 0 1 0\n"
        "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
        "mtllib missing.mtl\nusemtl red\n"
        "f 1/1/1 2/2/1 3/3/1 4/4/1\n"
        "f 1//2 2//2 5//2\n",
        "quad.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.degenerate, 0u);
    ASSERT_EQ(m.triangles.size(), 3u);  // the quad in two, the triangle
    // A vertex per distinct v/vt/vn corner: the quad's four, and the triangle's three (v 1 and
    // v 2 come again with another normal and no uv).
    ASSERT_EQ(m.positions.size(), 7u);
    ASSERT_EQ(m.normals.size(), 7u);
    ASSERT_EQ(m.uvs.size(), 7u);
    // The last triangle is the file's v 1, 2, 5, all with vn 2 and no vt.
    const glm::vec3 want[3] = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(m.positions[m.triangles[2][k]], want[k]) << k;
        EXPECT_EQ(m.normals[m.triangles[2][k]], glm::vec3(0, 1, 0)) << k;
    }
    for (int k = 0; k < 3; ++k) EXPECT_EQ(m.normals[m.triangles[0][k]], glm::vec3(0, 0, 1)) << k;
    // uv at the quad's third corner (v 3, vt 1 1) is (1, 0) in the format's orientation (v down),
    // in whichever of the quad's triangles holds it, at whichever corner.
    bool found = false;
    for (std::uint32_t t = 0; t < 2; ++t)
        for (int k = 0; k < 3; ++k)
            if (m.positions[m.triangles[t][k]] == glm::vec3(1, 1, 0)) {
                const glm::vec2 uv = mesh_uv(m, t, k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f);
                EXPECT_FLOAT_EQ(uv.x, 1.0f);
                EXPECT_FLOAT_EQ(uv.y, 0.0f);
                found = true;
            }
    EXPECT_TRUE(found);
    // No uv: (0, 0); the file's normal where given.
    EXPECT_EQ(mesh_uv(m, 2, 0.3f, 0.3f), glm::vec2(0.0f));
    EXPECT_EQ(mesh_shading_normal(m, 2, 0.2f, 0.2f), glm::vec3(0, 1, 0));
}

TEST(ObjReader, NegativeIndicesCountBackAndAPentagonMakesThreeTriangles) {
    TriangleMesh m;
    const ObjReadResult r = read_obj_text("v 1 0 0\nv 0.3 0.95 0\nv -0.8 0.6 0\nv -0.8 -0.6 0\nv 0.3 -0.95 0\n"
                                          "f -5 -4 -3 -2 -1\n",
                                          "pentagon.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(m.triangles.size(), 3u);
    // Flat: the geometric normal, +z for the counter-clockwise pentagon.
    for (std::uint32_t t = 0; t < 3; ++t) EXPECT_EQ(mesh_shading_normal(m, t, 0.3f, 0.3f), glm::vec3(0, 0, 1));
    float area = 0;
    for (std::uint32_t t = 0; t < 3; ++t) area += triangle_area(m, t);
    // The shoelace formula over the five corners.
    const float x[5] = {1, 0.3f, -0.8f, -0.8f, 0.3f}, y[5] = {0, 0.95f, 0.6f, -0.6f, -0.95f};
    float shoelace = 0;
    for (int i = 0; i < 5; ++i) shoelace += x[i] * y[(i + 1) % 5] - x[(i + 1) % 5] * y[i];
    EXPECT_NEAR(area, 0.5f * shoelace, 1e-5f);
}

TEST(ObjReader, DegenerateTrianglesAreSkippedAndCounted) {
    TriangleMesh m;
    const ObjReadResult r = read_obj_text("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n"
                                          "f 1 2 3\nf 1 1 4\nf 1 2 4\n",
                                          "d.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.degenerate, 2u);  // collinear corners, a repeated corner
    EXPECT_EQ(m.triangles.size(), 1u);
}

TEST(ObjReader, BadFaceIndexNamesItsLine) {
    struct Case { const char* text; int line; const char* says; };
    const Case cases[] = {
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n", 5, "vertex 4"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 0 1 2\n", 5, "vertex 0"},
        {"v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", 3, "vertex -3"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n", 5, "texture coordinate 2"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n", 5, "normal 7"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", 4, "expected a vertex index"},
        // A polygon with a bad index (tinyobjloader would read out of bounds triangulating it).
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4 99 3\n", 5, "vertex 99"},
    };
    for (const Case& c : cases) {
        TriangleMesh m;
        const ObjReadResult r = read_obj_text(c.text, "bad.obj", m);
        EXPECT_FALSE(r.ok) << c.text;
        EXPECT_EQ(r.line, c.line) << c.text;
        EXPECT_NE(r.error.find(c.says), std::string::npos) << r.error;
    }
}

TEST(ObjReader, FileWithoutTrianglesIsAnError) {
    for (const char* text : {"", "# nothing\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "v 0 0 0\nv 1 0 0\nl 1 2\n",
                             "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"}) {
        TriangleMesh m;
        const ObjReadResult r = read_obj_text(text, "empty.obj", m);
        EXPECT_FALSE(r.ok) << text;
        EXPECT_NE(r.error.find("triangle"), std::string::npos) << r.error;
    }
}

TEST(ObjReader, MissingFileIsAnError) {
    TriangleMesh m;
    const ObjReadResult r = read_obj(test::make_temp_dir() + "/nothing-here.obj", m);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("nothing-here.obj"), std::string::npos) << r.error;
}

TEST(ObjReader, TheTestCubeIsTwelveOutwardTriangles) {
    TriangleMesh m;
    ASSERT_TRUE(read_obj_text(test::cube_obj(), "cube.obj", m).ok);
    ASSERT_EQ(m.triangles.size(), 12u);
    for (std::uint32_t t = 0; t < 12; ++t) {
        const glm::vec3 n = glm::normalize(triangle_geometric_normal(m, t));
        const TriangleIndices& c = m.triangles[t];
        const glm::vec3 centre = (m.positions[c[0]] + m.positions[c[1]] + m.positions[c[2]]) / 3.0f;
        EXPECT_GT(glm::dot(n, centre), 0.0f) << "triangle " << t << " faces inward";
        EXPECT_NEAR(triangle_area(m, t), 0.5f, 1e-6f);
    }
}

}  // namespace
}  // namespace whitted
