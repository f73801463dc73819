#include "mesh/obj_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <algorithm>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <unordered_map>

#include <tiny_obj_loader.h>

#include "base/read_file.h"

namespace whitted {
namespace {

// Calls f(line number, first non-blank character, end of line) for every line of the text.
template <class F>
void for_each_line(const std::string& text, F&& f) {
    int line = 0;
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        if (end == std::string::npos) end = text.size();
        ++line;
        const char* p = text.c_str() + pos;
        const char* e = text.c_str() + end;
        pos = end + 1;
        while (p < e && (*p == ' ' || *p == '\t')) ++p;
        if (!f(line, p, e)) return;
    }
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// Which of v (0), vt (1), vn (2) the line defines, or -1.
int definition(const char* p, const char* e) {
    if (e - p >= 2 && p[0] == 'v' && blank(p[1])) return 0;
    if (e - p >= 3 && p[0] == 'v' && (p[1] == 't' || p[1] == 'n') && blank(p[2])) return p[1] == 't' ? 1 : 2;
    return -1;
}

// tinyobjloader checks face indices only after the whole file, naming its last line, and reads
// out of bounds when it triangulates a polygon with a bad index: so every face is checked here
// first (OBJ indices are 1-based, positive ones against the whole file, negative ones count back
// from the last definition above the face). Returns the first bad face line (0 if none) and why.
int find_bad_face(const std::string& text, std::string& why) {
    long total[3] = {0, 0, 0}, counts[3] = {0, 0, 0};  // v, vt, vn
    const char* names[3] = {"vertex", "texture coordinate", "normal"};
    for_each_line(text, [&](int, const char* p, const char* e) {
        if (int k = definition(p, e); k >= 0) ++total[k];
        return true;
    });
    int bad = 0;
    for_each_line(text, [&](int line, const char* p, const char* e) {
        if (int k = definition(p, e); k >= 0) {
            ++counts[k];
            return true;
        }
        if (!(e - p >= 2 && p[0] == 'f' && blank(p[1]))) return true;
        p += 2;
        while (p < e) {
            while (p < e && blank(*p)) ++p;
            if (p >= e) break;
            for (int k = 0; k < 3 && p < e && !blank(*p); ++k) {
                if (*p != '/') {
                    errno = 0;
                    char* after = nullptr;
                    const long idx = std::strtol(p, &after, 10);
                    if (after == p) {
                        why = "expected a vertex index in the face, found '" + std::string(p, std::min<std::size_t>(e - p, 20)) + "'";
                        bad = line;
                        return false;
                    }
                    const long n = idx < 0 ? counts[k] : total[k];
                    if (idx == 0 || errno == ERANGE || (idx > 0 && idx > n) || (idx < 0 && -idx > n)) {
                        why = "face refers to " + std::string(names[k]) + " " + std::to_string(idx) + ", but the file " +
                              (idx < 0 ? "defines " + std::to_string(n) + " before this line" : "has " + std::to_string(n)) +
                              " (indices start at 1; negative ones count back)";
                        bad = line;
                        return false;
                    }
                    p = after;
                }
                if (p < e && *p == '/') ++p;
            }
            while (p < e && !blank(*p)) ++p;
        }
        return true;
    });
    return bad;
}

// tinyobjloader's messages end in "(line N.)" where it knows the line.
int line_in_message(const std::string& message) {
    const std::size_t at = message.find("line ");
    if (at == std::string::npos) return 0;
    return std::atoi(message.c_str() + at + 5);
}

std::string first_line(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    const std::size_t nl = s.find('\n');
    return nl == std::string::npos ? s : s.substr(0, nl);
}

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// A corner of the file: its v, vn and vt indices (kNoIndex for none).
constexpr std::uint32_t kNoIndex = 0xffffffffu;
struct CornerKey {
    std::uint32_t v, n, t;
    bool operator==(const CornerKey&) const = default;
};
struct CornerKeyHash {
    std::size_t operator()(const CornerKey& k) const {
        std::uint64_t h = k.v * 0x9E3779B97F4A7C15ull;
        h ^= (h >> 29) + k.n * 0xBF58476D1CE4E5B9ull;
        h ^= (h >> 31) + k.t * 0x94D049BB133111EBull;
        return std::size_t(h ^ (h >> 32));
    }
};

}  // namespace

ObjReadResult read_obj_text(const std::string& text, const std::string& name, TriangleMesh& mesh) {
    ObjReadResult result;
    std::string why;
    if (int line = find_bad_face(text, why)) {
        result.line = line;
        result.error = why;
        return result;
    }
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    std::string warn, err;
    std::istringstream in(text);
    // No material reader: `mtllib` and `usemtl` are ignored (the scene's material applies).
    const bool ok = tinyobj::LoadObj(&attrib, &shapes, &materials, &warn, &err, &in, nullptr, true);
    if (!ok || !err.empty()) {
        result.line = line_in_message(err);
        result.error = err.empty() ? "cannot parse the OBJ file" : first_line(err);
        return result;
    }

    mesh = TriangleMesh();
    mesh.path = name;
    const std::size_t nv = attrib.vertices.size() / 3, nn = attrib.normals.size() / 3, nt = attrib.texcoords.size() / 2;
    auto position = [&](int i) {
        return glm::vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
    };
    const bool with_normals = nn > 0, with_uvs = nt > 0;
    // One index per corner for position, normal and uv, as pbrt and Embree keep meshes: a vertex
    // per distinct (v, vn, vt) of the file's corners (split where a seam gives one position two
    // uvs), so a triangle costs one index triple, not three. A corner without a valid vn holds
    // the normal (0, 0, 0), without a valid vt the uv (NaN, NaN): its triangle then takes its
    // geometric normal, or uv (0, 0), as §9.3 says.
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertex_of;
    vertex_of.reserve(nv);
    auto vertex = [&](const tinyobj::index_t& c) {
        const bool has_n = with_normals && c.normal_index >= 0 && std::size_t(c.normal_index) < nn;
        const bool has_t = with_uvs && c.texcoord_index >= 0 && std::size_t(c.texcoord_index) < nt;
        const CornerKey key{std::uint32_t(c.vertex_index), has_n ? std::uint32_t(c.normal_index) : kNoIndex,
                            has_t ? std::uint32_t(c.texcoord_index) : kNoIndex};
        const auto [it, added] = vertex_of.try_emplace(key, std::uint32_t(mesh.positions.size()));
        if (!added) return it->second;
        mesh.positions.push_back(position(c.vertex_index));
        if (with_normals)
            mesh.normals.push_back(has_n ? glm::vec3(attrib.normals[3 * key.n], attrib.normals[3 * key.n + 1],
                                                     attrib.normals[3 * key.n + 2])
                                         : glm::vec3(0.0f));
        if (with_uvs)
            mesh.uvs.push_back(has_t ? glm::vec2(attrib.texcoords[2 * key.t], attrib.texcoords[2 * key.t + 1])
                                     : glm::vec2(std::numeric_limits<float>::quiet_NaN()));
        return it->second;
    };
    for (const tinyobj::shape_t& shape : shapes) {
        const std::vector<tinyobj::index_t>& idx = shape.mesh.indices;
        std::size_t corner = 0;
        for (unsigned char fv : shape.mesh.num_face_vertices) {
            if (fv != 3 || corner + 3 > idx.size()) {  // triangulation leaves only triangles
                corner += fv;
                continue;
            }
            const tinyobj::index_t* c = &idx[corner];
            corner += 3;
            const glm::vec3 a = position(c[0].vertex_index), b = position(c[1].vertex_index),
                            d = position(c[2].vertex_index);
            const glm::vec3 n = glm::cross(b - a, d - a);
            if (!finite(a) || !finite(b) || !finite(d) || !(glm::dot(n, n) > 0.0f)) {
                ++result.degenerate;
                continue;
            }
            mesh.triangles.push_back({vertex(c[0]), vertex(c[1]), vertex(c[2])});
        }
    }
    if (mesh.triangles.empty()) {
        result.error = result.degenerate > 0 ? "the file's " + std::to_string(result.degenerate) +
                                                   " triangles all have zero area: no triangle to draw"
                                             : "the file holds no triangle (no 'f' face with three or more vertices)";
        return result;
    }
    mesh.positions.shrink_to_fit();
    mesh.triangles.shrink_to_fit();
    mesh.normals.shrink_to_fit();
    mesh.uvs.shrink_to_fit();
    result.ok = true;
    return result;
}

ObjReadResult read_obj(const std::string& path, TriangleMesh& mesh, std::size_t max_bytes) {
    FileContents file = read_regular_file(path, max_bytes);
    if (!file.ok()) {
        ObjReadResult r;
        r.error = "cannot read '" + path + "': " + file.error;
        return r;
    }
    const std::string& text = file.bytes;
    return read_obj_text(text, path, mesh);
}

}  // namespace whitted
