// whitted's OBJ line parser against tinyobjloader's, the parser OBJ meshes were read with before
// (built from the Debian package's header in tinyobj_reference.cpp): on the same lines, the same
// vertices, normals, texture coordinates (to the bit) and face corners, in the same order. Lines
// are drawn from the words of real files and from the corners of the grammar (signs, exponents,
// indices past int's range, NULs, form feeds), and as random bytes of the characters that matter.
#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_obj_loader.h>

#include "mesh/obj_line.h"

namespace whitted {
namespace {

// What a parser made of some lines: one entry per vertex, normal, texture coordinate or face.
struct Event {
    char kind;  // 'v', 'n', 't', 'f'
    std::uint32_t bits[3] = {0, 0, 0};
    std::vector<int> corners;  // v, vt, vn of each corner
    bool operator==(const Event&) const = default;
};

std::uint32_t bits_of(float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
}

Event numbers(char kind, float x, float y, float z) { return {kind, {bits_of(x), bits_of(y), bits_of(z)}, {}}; }

std::vector<Event> by_tinyobjloader(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    std::istringstream in(text);
    std::vector<Event> events;
    tinyobj::callback_t cb;
    cb.vertex_cb = [](void* p, float x, float y, float z, float) {
        static_cast<std::vector<Event>*>(p)->push_back(numbers('v', x, y, z));
    };
    cb.normal_cb = [](void* p, float x, float y, float z) {
        static_cast<std::vector<Event>*>(p)->push_back(numbers('n', x, y, z));
    };
    // The third texture coordinate is read by no one (whitted keeps u and v).
    cb.texcoord_cb = [](void* p, float x, float y, float) {
        static_cast<std::vector<Event>*>(p)->push_back(numbers('t', x, y, 0.0f));
    };
    cb.index_cb = [](void* p, tinyobj::index_t* c, int n) {
        Event e{'f', {0, 0, 0}, {}};
        for (int k = 0; k < n; ++k) e.corners.insert(e.corners.end(), {c[k].vertex_index, c[k].texcoord_index, c[k].normal_index});
        static_cast<std::vector<Event>*>(p)->push_back(e);
    };
    std::string warn, err;
    tinyobj::LoadObjWithCallback(in, cb, &events, nullptr, &warn, &err);
    return events;
}

std::vector<Event> by_whitted(const std::vector<std::string>& lines) {
    std::vector<Event> events;
    ObjLine line;
    for (const std::string& l : lines) {
        parse_obj_line(l, line);
        switch (line.kind) {
        case ObjLineKind::Vertex: events.push_back(numbers('v', line.xyz[0], line.xyz[1], line.xyz[2])); break;
        case ObjLineKind::Normal: events.push_back(numbers('n', line.xyz[0], line.xyz[1], line.xyz[2])); break;
        case ObjLineKind::TexCoord: events.push_back(numbers('t', line.xyz[0], line.xyz[1], 0.0f)); break;
        case ObjLineKind::Face:
            if (!line.corners.empty()) {
                Event e{'f', {0, 0, 0}, {}};
                for (const ObjCorner& c : line.corners) e.corners.insert(e.corners.end(), {c.v, c.vt, c.vn});
                events.push_back(e);
            }
            break;
        case ObjLineKind::Other: break;
        }
    }
    return events;
}

void expect_same(const std::vector<std::string>& lines) {
    const std::vector<Event> want = by_tinyobjloader(lines), got = by_whitted(lines);
    ASSERT_EQ(got.size(), want.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        if (got[i] == want[i]) continue;
        std::string all;
        for (const std::string& l : lines) all += "[" + l + "] ";
        ADD_FAILURE() << "event " << i << " differs; lines: " << all;
        return;
    }
}

TEST(ObjLine, ReadsWhatTinyobjloaderReadsOnTheLinesOfRealFiles) {
    expect_same({"# Blender v2.79 OBJ File", "mtllib cube.mtl", "o Cube", "v 1.000000 -1.000000 -1.000000",
                 "v -0.999999 1.000000 1.000001", "vt 0.625000 0.500000", "vn 0.0000 -1.0000 0.0000", "usemtl Material",
                 "s off", "f 1/1/1 2/2/1 3/3/1", "f 5//2 6//2 7//2 8//2", "f -3 -2 -1", "f 1/2 3/4 5/6",
                 "  v\t0.5\t-0.25  1e-3", "vt 0.5", "v 1 2 3 0.5", "g group one", "l 1 2", "vp 0.1 0.2",
                 "v 123456789.123456789 0.1234567890123 -7.000000001e-05", "f 1 2 3 4 5 6 7 8 9 10"});
}

TEST(ObjLine, ReadsWhatTinyobjloaderReadsAtTheCornersOfTheGrammar) {
    expect_same({"v", "v ", "vn", "vt", "f", "f ", "vx 1 2 3", "v1 2 3", "fa 1 2 3", "v +1 -0 .5", "v -. . +.",
                 "v 1e 1e+ 1e-", "v 1.5abc 2x 0x1F", "v nan inf -inf", "v 1e2147483648 1e-2147483649 0e999",
                 "v 1e214748364 1e2147483647 2e-2147483648", "v 1.e2 1.E-2 -2.5E+3", "v 5 6 7 8 9 10 11",
                 "f 1/ 2 3", "f 1/2/3/4 5", "f /1 //2 ///3", "f 99999999999999999999 -99999999999999999999",
                 "f -9223372036854775808 9223372036854775807 2147483648 4294967297", "f 1x 2y/3z/4w",
                 "f +1 -2 \v3 \f4", std::string("v 1 2\0 3", 8), std::string("f 1 2\0 3", 8),
                 std::string("\0v 1 2 3", 8), "\t \tf\t1\t2\t3\t", "f 1//", "f 1/", "f 1/2/", "f //", "#v 1 2 3"});
}

TEST(ObjLine, ReadsWhatTinyobjloaderReadsOnRandomLines) {
    // Words of the grammar and noise, joined by blanks (or not), from a fixed seed.
    const std::vector<std::string> heads = {"v", "vn", "vt", "f", "#", "o", "g", "usemtl", "", "v", "f"};
    const std::vector<std::string> words = {
        "1", "-2", "3.25", ".5", "-.5", "+.5", "1e5", "1e", "1e+", "2E-3", "1.e2", "0x1F", "nan", "inf", ".",
        "-", "+", "1e2147483648", "99999999999999999999", "-9223372036854775808", "/", "//", "1/2", "1//3",
        "1/2/3", "-1/-1/-1", "\v", "\f", std::string(1, '\0'), "x", "123456789.123456789", "0.000000001234",
        "7/", "/8", "1/2/3/4", "00012", "-0", "1e-320", "4.9e-324", "1.7976931348623157e308", "3.4028236e38"};
    const std::string blanks[] = {" ", "\t", "  ", "", " \t"};
    std::mt19937 rng(12345);
    auto pick = [&](std::size_t n) { return std::size_t(rng() % n); };
    for (int trial = 0; trial < 4000; ++trial) {
        std::vector<std::string> lines;
        for (int l = 0; l < 4; ++l) {
            std::string line = pick(4) == 0 ? blanks[pick(5)] : "";
            line += heads[pick(heads.size())] + blanks[pick(5)];
            const std::size_t n = pick(9);
            for (std::size_t k = 0; k < n; ++k) line += words[pick(words.size())] + blanks[pick(5)];
            lines.push_back(line);
        }
        expect_same(lines);
        if (HasFailure()) return;
    }
    // Random bytes of the characters that matter.
    const char alphabet[] = "vntf 0123456789.eE+-/\t\v\f#x";
    for (int trial = 0; trial < 4000; ++trial) {
        std::string line(1, "vf"[pick(2)]);
        const std::size_t n = pick(24);
        for (std::size_t k = 0; k < n; ++k) line += alphabet[pick(sizeof alphabet - 1)];
        expect_same({line});
        if (HasFailure()) return;
    }
}

TEST(ObjLine, NumbersAreWhatTheySay) {
    double x = 7.0;
    ASSERT_TRUE(parse_obj_number("1.5", "1.5" + 3, x));
    EXPECT_EQ(x, 1.5);
    ASSERT_TRUE(parse_obj_number("-.5e1", "-.5e1" + 5, x));
    EXPECT_EQ(x, -5.0);
    ASSERT_TRUE(parse_obj_number("+25E-2", "+25E-2" + 6, x));
    EXPECT_EQ(x, 0.25);
    ASSERT_TRUE(parse_obj_number("12abc", "12abc" + 5, x));  // a number ends where it cannot go on
    EXPECT_EQ(x, 12.0);
    x = 7.0;
    EXPECT_FALSE(parse_obj_number("1e", "1e" + 2, x));
    EXPECT_FALSE(parse_obj_number("+", "+" + 1, x));
    EXPECT_FALSE(parse_obj_number("x1", "x1" + 2, x));
    EXPECT_FALSE(parse_obj_number("1", "1", x));  // nothing
    EXPECT_EQ(x, 7.0);  // untouched when there is no number

    ObjLine line;
    parse_obj_line("f 3/-1/2 4//5 -6 7/8", line);
    ASSERT_EQ(line.kind, ObjLineKind::Face);
    ASSERT_EQ(line.corners.size(), 4u);
    EXPECT_EQ(line.corners[0].v, 3);
    EXPECT_EQ(line.corners[0].vt, -1);
    EXPECT_EQ(line.corners[0].vn, 2);
    EXPECT_EQ(line.corners[1].vt, 0);
    EXPECT_EQ(line.corners[1].vn, 5);
    EXPECT_EQ(line.corners[2].v, -6);
    EXPECT_EQ(line.corners[3].vt, 8);
    parse_obj_line("vt 0.25", line);
    ASSERT_EQ(line.kind, ObjLineKind::TexCoord);
    EXPECT_EQ(line.xyz[0], 0.25f);
    EXPECT_EQ(line.xyz[1], 0.0f);  // missing: 0
}

}  // namespace
}  // namespace whitted
