// Reading OBJ files (scene-format.md §9.3): polygons triangulated, normals and texture coordinates
// kept per corner (a vertex per distinct v/vt/vn), degenerate triangles skipped, and every error with the OBJ line it is on.
#include <sys/stat.h>

#include <atomic>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

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

TEST(ObjReader, FacesBeforeAndAfterOneNamingAVertexFurtherDownKeepTheirOrderAndCorners) {
    // The first face comes before any vn (its vertices get the normal (0, 0, 0) once the file has
    // normals), the second names v 4 before it is defined (kept until the file is read, as is every
    // face after it), the third is a quad by negative indices, split along a diagonal (equal ones:
    // 0-1-3 and 1-2-3, as tinyobjloader splits), sharing the vertex (v 3, vn 1) with the second.
    TriangleMesh m;
    const ObjReadResult r = read_obj_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nvn 0 0 1\nf 1//1 3//1 4//1\n"
                                          "v 0 1 0\nv 2 0 0\nv 2 1 0\nf -5//1 -2//1 -1//1 -4//1\n",
                                          "ahead.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    const std::vector<TriangleIndices> triangles{{0, 1, 2}, {3, 4, 5}, {6, 7, 4}, {7, 8, 4}};
    EXPECT_EQ(std::vector<TriangleIndices>(m.triangles.begin(), m.triangles.end()), triangles);
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 0}, {1, 1, 0},
                                           {0, 1, 0}, {1, 0, 0}, {2, 0, 0}, {2, 1, 0}};
    EXPECT_EQ(std::vector<glm::vec3>(m.positions.begin(), m.positions.end()), positions);
    const glm::vec3 none(0.0f), up(0, 0, 1);
    const std::vector<glm::vec3> normals{none, none, none, up, up, up, up, up, up};
    EXPECT_EQ(std::vector<glm::vec3>(m.normals.begin(), m.normals.end()), normals);
    EXPECT_TRUE(m.uvs.empty());
}

TEST(ObjReader, ReadingHoldsNoCopyOfTheFaces) {
    // A 200 x 200 grid of quads written as 80,000 triangles on 40,401 shared vertices. Beyond the
    // text and what the mesh keeps (its arrays and its BVH's estimate, r.bytes), reading it needs
    // the file's v (12 bytes a vertex), a vertex table (about 20 bytes a vertex) and the repeated-
    // triangle table (8 to 16 bytes a triangle): under 48 bytes a triangle. A copy of every corner
    // of the faces alone would be 36, and a heap node per vertex 64 more.
    constexpr int kN = 200;
    std::string text;
    for (int j = 0; j <= kN; ++j)
        for (int i = 0; i <= kN; ++i) text += "v " + std::to_string(i) + " " + std::to_string(j) + " 0\n";
    for (int j = 0; j < kN; ++j)
        for (int i = 0; i < kN; ++i) {
            const std::string a = std::to_string(j * (kN + 1) + i + 1), b = std::to_string(j * (kN + 1) + i + 2),
                              c = std::to_string((j + 1) * (kN + 1) + i + 2),
                              d = std::to_string((j + 1) * (kN + 1) + i + 1);
            text += "f " + a + " " + b + " " + c + "\nf " + a + " " + c + " " + d + "\n";
        }
    TriangleMesh m;
    const ObjReadResult all = read_obj_text(text, "grid.obj", m);
    ASSERT_TRUE(all.ok) << all.error;
    ASSERT_EQ(m.triangles.size(), std::size_t(2 * kN * kN));
    ASSERT_EQ(m.positions.size(), std::size_t((kN + 1) * (kN + 1)));
    ObjLimits limits;
    limits.max_bytes = text.size() + all.bytes + 48 * m.triangles.size();
    const ObjReadResult r = read_obj_text(text, "grid.obj", m, limits);
    EXPECT_TRUE(r.ok) << r.error;
    EXPECT_EQ(m.triangles.size(), std::size_t(2 * kN * kN));
    // Below what the finished mesh needs with the text: refused, with the same message as ever.
    limits.max_bytes = text.size() + all.bytes - 1;
    const ObjReadResult small = read_obj_text(text, "grid.obj", m, limits);
    EXPECT_FALSE(small.ok);
    EXPECT_NE(small.error.find("the mesh needs more than the"), std::string::npos) << small.error;
    EXPECT_NE(small.error.find("(--max-memory; a scene's objects, textures and meshes share it)"), std::string::npos);
}

TEST(ObjReader, AFileReadInPiecesGivesTheSameMeshAndTheSameErrorLines) {
    // Over 200 KiB (a file is parsed 64 KiB at a time): lines ending in \n, \r\n and a lone \r
    // in turn, a \r\n split across the first piece boundary (its \r the piece's last byte), and
    // the first face naming a later vertex past that boundary, so that its line is counted with
    // the pieces before read again.
    std::string text;
    int lines = 0;
    auto line = [&](const std::string& s) {
        static const char* const ends[3] = {"\n", "\r\n", "\r"};
        text += s + ends[lines % 3];
        ++lines;
    };
    int vertices = 0;
    auto quad = [&](float x) {
        for (int k = 0; k < 4; ++k) line("v " + std::to_string(x + (k == 1 || k == 2)) + " " + std::to_string(k / 2) + " 0");
        vertices += 4;
        line("vn 0 0 1");
        line("f -4//-1 -3//-1 -2//-1 -1//-1");
    };
    constexpr std::size_t kPiece = 64 << 10;
    for (int q = 0; text.size() < kPiece - 200; ++q) quad(float(q));
    while (lines % 3 != 1) line("# to a \\r\\n ending");
    // A comment whose \r\n ending puts the \r at the piece's last byte.
    std::string comment(kPiece - 1 - text.size(), '-');
    comment[0] = '#';
    line(comment);
    ASSERT_EQ(text[kPiece - 1], '\r');
    ASSERT_EQ(text[kPiece], '\n');
    for (int q = 0; text.size() < 2 * kPiece; ++q) quad(1000.0f + float(q));
    line("f " + std::to_string(vertices + 1) + " " + std::to_string(vertices + 2) + " " + std::to_string(vertices + 3));
    for (int k = 0; k < 3; ++k) line("v " + std::to_string(k == 1) + " " + std::to_string(k == 2) + " 5");
    vertices += 3;
    for (int q = 0; text.size() < 3 * kPiece + 5000; ++q) quad(2000.0f + float(q));
    const std::string dir = test::make_temp_dir();
    const std::string good = test::write_file(dir, "good.obj", text);
    TriangleMesh from_text, from_file;
    const ObjReadResult a = read_obj_text(text, "good.obj", from_text);
    const ObjReadResult b = read_obj(good, from_file);
    ASSERT_TRUE(a.ok) << a.error;
    ASSERT_TRUE(b.ok) << b.error;
    const std::size_t quads = std::size_t(vertices - 3) / 4;
    EXPECT_EQ(from_file.triangles.size(), 2 * quads + 1);
    EXPECT_EQ(std::vector<TriangleIndices>(from_file.triangles.begin(), from_file.triangles.end()),
              std::vector<TriangleIndices>(from_text.triangles.begin(), from_text.triangles.end()));
    EXPECT_EQ(std::vector<glm::vec3>(from_file.positions.begin(), from_file.positions.end()),
              std::vector<glm::vec3>(from_text.positions.begin(), from_text.positions.end()));
    EXPECT_EQ(std::vector<glm::vec3>(from_file.normals.begin(), from_file.normals.end()),
              std::vector<glm::vec3>(from_text.normals.begin(), from_text.normals.end()));

    // A face naming vertex 0 on line `lines + 1`, in the fourth piece; and a face naming a vertex
    // never defined after it, whose error is not the first.
    const int bad_line = lines + 1;
    line("f 1 0 2");
    line("f 1 2 " + std::to_string(vertices + 100));
    const std::string bad = test::write_file(dir, "bad.obj", text);
    TriangleMesh m;
    const ObjReadResult c = read_obj(bad, m);
    EXPECT_FALSE(c.ok);
    EXPECT_EQ(c.line, bad_line) << c.error;
    EXPECT_NE(c.error.find("vertex index 0"), std::string::npos) << c.error;
    EXPECT_EQ(read_obj_text(text, "bad.obj", m).line, bad_line);
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
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 0 1 2\n", 5, "vertex index 0"},
        {"v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", 3, "vertex -3"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/2 3/1\n", 5, "texture coordinate 2"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//7\n", 5, "normal 7"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n", 4, "no number where a vertex index belongs"},
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

// Found by fuzzing: tinyobjloader ends a line at a lone \r too, which the old check of
// the text (lines split at \n) did not, so a bad index slipped through and was read out of bounds
// (SIGSEGV). Every index it returns is now checked, whatever the line endings.
TEST(ObjReader, EveryIndexIsCheckedWhateverTheLineEndings) {
    struct Case { const char* text; int line; const char* says; };
    const Case cases[] = {
        // Old Mac line endings: four lines, the face's third vertex beyond the three.
        {"v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 99999\r", 4, "vertex 99999, but the file has 3"},
        // A bare `v` (no coordinates) is no vertex to tinyobjloader: the text had four `v` lines.
        {"v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv\r\nf 1 2 4\r\n", 5, "vertex 4, but the file has 3"},
        // Counting back past the first vertex, on a line ended by \r.
        {"v 0 0 0\rv 1 0 0\rf -1 -2 -3\rv 0 1 0\r", 3, "vertex -3"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\rf 1//1 2//1 3//2\n", 5, "normal 2, but the file has 1"},
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\r\nf 1/2 2/1 3/1\r\n", 5, "texture coordinate 2"},
        // An index past int's range.
        {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2147483648\n", 4, "vertex"},
    };
    for (const Case& c : cases) {
        TriangleMesh m;
        const ObjReadResult r = read_obj_text(c.text, "bad.obj", m);
        EXPECT_FALSE(r.ok) << c.text;
        EXPECT_EQ(r.line, c.line) << c.text;
        EXPECT_NE(r.error.find(c.says), std::string::npos) << r.error;
    }
    // A reference to a vertex defined further down is fine (OBJ allows it), with any line ending.
    TriangleMesh m;
    const ObjReadResult r = read_obj_text("v 0 0 0\rf 1 2 3\rv 1 0 0\rv 0 1 0\r", "ahead.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(m.triangles.size(), 1u);
}

// Found by fuzzing (the OBJ target's first minute): tinyobjloader's number parser
// overflowed an int on the exponent 2147483648 (undefined behaviour; it checks the multiplication,
// not the addition after it). Built with -fwrapv, that number is a garbage value like any other.
TEST(ObjReader, ANumberWithAHugeExponentIsJustABadNumber) {
    TriangleMesh m;
    const ObjReadResult r = read_obj_text("v 1e2147483648 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"
                                          "v 0 0 0\nv 1 0 0\nv 0 1e-2147483649 1\nf 4 5 6\n",
                                          "huge.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_GE(m.triangles.size(), 1u);
}

// A file from others may be anything: its words are never quoted in a message (a secret named as
// a mesh would otherwise be printed a word at a time).
TEST(ObjReader, MessagesQuoteNothingOfTheFile) {
    for (const char* text : {"SECRET_TOKEN_1 SECRET_TOKEN_2\n", "v 0 0 0\nf SECRET_TOKEN 1 2\n",
                             "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/SECRET_TOKEN/x 2 9\n"}) {
        TriangleMesh m;
        const ObjReadResult r = read_obj_text(text, "secret.txt", m);
        EXPECT_FALSE(r.ok);
        EXPECT_EQ(r.error.find("SECRET"), std::string::npos) << r.error;
    }
}

// A polygon of 64,000 corners (a 9 MB file of them took 430 s: tinyobjloader's ear clipping is
// quadratic) is split as a fan from its first corner, and said so; small ones are ear-clipped, which
// is right for a concave polygon where a fan is not.
TEST(ObjReader, HugePolygonsAreFansSmallOnesAreEarClipped) {
    std::string text;
    constexpr int kCorners = 64000;
    for (int i = 0; i < kCorners; ++i) {
        const double a = 2 * 3.14159265358979 * i / kCorners;
        text.append("v ").append(std::to_string(std::cos(a))).append(" ").append(std::to_string(std::sin(a))).append(" 0\n");
    }
    text += "f";
    for (int i = 1; i <= kCorners; ++i) text.append(" ").append(std::to_string(i));
    text += "\n";
    TriangleMesh m;
    ObjReadResult r = read_obj_text(text, "disc.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.fans, 1u);
    EXPECT_EQ(m.triangles.size() + r.degenerate, std::size_t(kCorners - 2));
    for (const TriangleIndices& t : m.triangles) EXPECT_EQ(m.positions[t[0]], glm::vec3(1, 0, 0));

    // An arrow head (concave at its 4th corner): a fan from corner 1 would cover the notch.
    //   5 ---------- 4 is the notch at (2, 1): the polygon is 1 (0,0) 2 (4,0) 3 (4,3) 4 (2,1) 5 (0,3).
    r = read_obj_text("v 0 0 0\nv 4 0 0\nv 4 3 0\nv 2 1 0\nv 0 3 0\nf 1 2 3 4 5\n", "notch.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(r.fans, 0u);
    ASSERT_EQ(m.triangles.size(), 3u);
    float area = 0;
    for (std::uint32_t t = 0; t < 3; ++t) {
        area += triangle_area(m, t);
        // Counter-clockwise like the polygon, so facing +z.
        EXPECT_GT(triangle_geometric_normal(m, t).z, 0.0f) << t;
    }
    // The outline's 4 × 3 = 12 less the notch's triangle (4,3)-(2,1)-(0,3), 4 (a fan would give 10).
    EXPECT_NEAR(area, 8.0f, 1e-5f);
}

// A million copies of one triangle made every ray that met it test them all (6.6 ms a ray): a
// triangle with the same three corners in the same order as an earlier one is the same triangle to
// every ray (the same arithmetic, and of equal hits the first wins), so it is kept once.
TEST(ObjReader, RepeatedTrianglesAreKeptOnce) {
    std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (int i = 0; i < 1000; ++i) text += i % 2 ? "f 1 2 3\n" : "f 4 5 6\n";  // the same corners, other vertices
    text += "f 2 3 1\nf 3 2 1\n";  // turned or reversed: another triangle to the arithmetic, kept
    TriangleMesh m;
    const ObjReadResult r = read_obj_text(text, "copies.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    EXPECT_EQ(m.triangles.size(), 3u);
    EXPECT_EQ(r.duplicates, 999u);
}

// A position named with many normals is as many vertices, each with its own normal: a fan of N
// triangles around a centre, each face with a normal of its own, makes the centre N vertices and
// each rim position between two faces two (3N in all, far more than the file's N + 2 positions).
TEST(ObjReader, APositionWithManyNormalsIsAVertexForEach) {
    constexpr int kFan = 1000;
    std::string text = "v 0 0 0\n";
    for (int i = 0; i <= kFan; ++i) {
        const double a = 6.0 * i / kFan;
        text += "v " + std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " 0\n";
    }
    for (int i = 1; i <= kFan; ++i) text += "vn 0 0 " + std::to_string(i) + "\n";
    for (int i = 1; i <= kFan; ++i) {
        const std::string n = "//" + std::to_string(i) + " ";
        text += "f 1" + n + std::to_string(i + 1) + n + std::to_string(i + 2) + n + "\n";
    }
    TriangleMesh m;
    const ObjReadResult r = read_obj_text(text, "fan.obj", m);
    ASSERT_TRUE(r.ok) << r.error;
    ASSERT_EQ(m.triangles.size(), std::size_t(kFan));
    EXPECT_EQ(m.positions.size(), std::size_t(3 * kFan));
    for (int t = 0; t < kFan; ++t)
        for (int k = 0; k < 3; ++k) {
            EXPECT_EQ(m.normals[m.triangles[t][k]], glm::vec3(0, 0, float(t + 1))) << t << " " << k;
            if (HasFailure()) return;
        }
    EXPECT_EQ(m.positions[m.triangles[kFan - 1][0]], glm::vec3(0.0f));
}

// The memory a mesh needs (its text, what the parse keeps, the triangles with their BVH) is counted
// as it is read: over the limit it is refused instead of taking gigabytes (a 64 MB file took 1.48 GB).
TEST(ObjReader, RefusesWhatNeedsMoreMemoryThanTheLimit) {
    std::string text;
    for (int i = 0; i < 20000; ++i) {
        const std::string x = std::to_string(i);
        text += "v " + x + " 0 0\nv " + x + " 1 0\nv " + x + " 0 1\nf -3 -2 -1\n";
    }
    TriangleMesh m;
    ObjLimits limits;
    const ObjReadResult all = read_obj_text(text, "big.obj", m, limits);
    ASSERT_TRUE(all.ok) << all.error;
    // What it needs: at least its triangles with their BVH estimate.
    EXPECT_GE(all.bytes, m.triangles.size() * (sizeof(TriangleIndices) + kMeshBvhBytesPerTriangle));
    limits.max_bytes = all.bytes - 1;
    const ObjReadResult r = read_obj_text(text, "big.obj", m, limits);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("needs more than the"), std::string::npos) << r.error;
    EXPECT_TRUE(m.triangles.empty());
    // Far below: refused while the text is read.
    limits.max_bytes = text.size() + 1000;
    EXPECT_FALSE(read_obj_text(text, "big.obj", m, limits).ok);
}

TEST(ObjReader, StopsWhenCancelledAndReadsOnlyRegularFilesWithinTheLimit) {
    const std::atomic<bool> cancel{true};
    TriangleMesh m;
    ObjLimits limits;
    limits.cancel = &cancel;
    const ObjReadResult r = read_obj_text(test::cube_obj(), "cube.obj", m, limits);
    EXPECT_TRUE(r.cancelled);
    EXPECT_FALSE(r.ok);
    EXPECT_TRUE(r.error.empty()) << r.error;

    const std::string dir = test::make_temp_dir();
    const std::string path = test::write_file(dir, "cube.obj", test::cube_obj());
    ObjLimits small;
    small.max_file_bytes = 100;
    const ObjReadResult big = read_obj(path, m, small);
    EXPECT_NE(big.error.find("more than the limit of 100 bytes"), std::string::npos) << big.error;
    ASSERT_EQ(mkfifo((dir + "/fifo.obj").c_str(), 0600), 0);
    const ObjReadResult fifo = read_obj(dir + "/fifo.obj", m);  // no writer: would block if opened for reading
    EXPECT_NE(fifo.error.find("not a regular file"), std::string::npos) << fifo.error;
}

TEST(ObjReader, FileWithoutTrianglesIsAnError) {
    for (const char* text : {"", "# nothing\n", "v 0 0 0\nv 1 0 0\nv 0 1 0\n", "v 0 0 0\nv 1 0 0\nl 1 2\n",
                             "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"}) {
        TriangleMesh m;
        const ObjReadResult r = read_obj_text(text, "empty.obj", m);
        EXPECT_FALSE(r.ok) << text;
        EXPECT_NE(r.error.find("triangle"), std::string::npos) << r.error;
    }
    // No text at all, not even an empty string's pointer (nothing may be searched at null).
    TriangleMesh m;
    const ObjReadResult r = read_obj_text(std::string_view(), "none.obj", m);
    EXPECT_FALSE(r.ok);
    EXPECT_NE(r.error.find("triangle"), std::string::npos) << r.error;
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
