#pragma once
// One line of a Wavefront OBJ file, read as tinyobjloader reads it (the grammar whitted's meshes
// have always been read with, scene-format.md §9.3), without its istream, string copies and libc
// calls: `v x y z`, `vn x y z`, `vt u v` and `f` with corners `v`, `v/vt`, `v//vn` or `v/vt/vn`; every
// other line (comments, `o`, `g`, `s`, `usemtl`, `mtllib`, ...) is nothing. Numbers keep that
// parser's rules and its arithmetic, so a file gives the same bytes as before: a word that is no
// number is 0 (a missing w or texture v too), a number ends at the first character that cannot
// continue it ("1.5abc" is 1.5), a face index is read as C's atoi reads it, and the line ends at a
// NUL. The line given has no line break in it.
#include <string_view>
#include <vector>

namespace whitted {

// A corner of a face as written: 1-based, negative counting back, 0 for none (or no number).
struct ObjCorner {
    int v = 0, vt = 0, vn = 0;
};

enum class ObjLineKind { Other, Vertex, Normal, TexCoord, Face };

struct ObjLine {
    ObjLineKind kind = ObjLineKind::Other;
    float xyz[3] = {0.0f, 0.0f, 0.0f};  // Vertex, Normal (x y z) and TexCoord (u v, and 0)
    std::vector<ObjCorner> corners;     // Face: its corners (cleared for every line; reused)
};

// Reads `line` into `out`.
void parse_obj_line(std::string_view line, ObjLine& out);

// The number a word of an OBJ file stands for, by tinyobjloader's rules (a sign, digits, a
// fraction, an exponent; "1e" and "+" are none); false if it is none.
bool parse_obj_number(const char* begin, const char* end, double& value);

}  // namespace whitted
