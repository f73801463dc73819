#include "inspect/ray_tree.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "inspect/report_text.h"

namespace whitted {
namespace {

std::string num(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4f", double(v));
    return buf;
}

std::string paren(const glm::vec3& v) {
    std::string s = "(";
    s += num(v.x) + " " + num(v.y) + " " + num(v.z);
    s += ")";
    return s;
}

// Exact enough for a reader to put the points back (OBJ, JSON): 9 significant digits round-trip a float.
std::string exact(float v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", double(v));
    return buf;
}

std::string json_string(const std::string& s) {
    std::string out = "\"";
    for (const char c : s) {
        if (c == '"' || c == '\\') {
            out += '\\';
            out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\u%04x", unsigned(static_cast<unsigned char>(c)));
            out += buf;
        } else {
            out += c;
        }
    }
    return out + "\"";
}

std::string json_vec(const glm::vec3& v) {
    std::string s = "[";  // appended: GCC 12 warns falsely (-Wrestrict) on "[" + …
    s += exact(v.x);
    s += ",";
    s += exact(v.y);
    s += ",";
    s += exact(v.z);
    s += "]";
    return s;
}

// Image coordinates of a point at depth z > 0 (along forward) in front of the camera.
glm::vec2 to_image(const Camera& c, int width, int height, const glm::vec3& d, float z) {
    const float aspect = float(width) / float(height);
    const float sx = glm::dot(d, c.right) / z / (c.tan_half_fov * aspect);
    const float sy = glm::dot(d, c.up) / z / c.tan_half_fov;
    return {(sx + 1.0f) * 0.5f * float(width), (1.0f - sy) * 0.5f * float(height)};
}

}  // namespace

const char* ray_kind_name(RayKind kind) {
    switch (kind) {
        case RayKind::Camera: return "camera";
        case RayKind::Reflected: return "reflected";
        case RayKind::Refracted: return "refracted";
        case RayKind::Shadow: return "shadow";
    }
    return "?";
}

const char* shadow_state_name(ShadowState state) {
    switch (state) {
        case ShadowState::Lit: return "lit";
        case ShadowState::Blocked: return "blocked";
        case ShadowState::Tinted: return "tinted";
    }
    return "?";
}

int RayTree::deepest() const {
    int d = 0;
    for (const RaySegment& s : segments) d = std::max(d, s.depth);
    return d;
}

std::optional<glm::vec2> project_point(const Camera& camera, int width, int height, const glm::vec3& p) {
    const glm::vec3 d = p - camera.eye;
    const float z = glm::dot(d, camera.forward);
    if (!(z > 0.0f) || width <= 0 || height <= 0) return std::nullopt;
    return to_image(camera, width, height, d, z);
}

std::optional<ImageSegment> project_segment(const Camera& camera, int width, int height, const glm::vec3& from,
                                            const glm::vec3& to) {
    if (width <= 0 || height <= 0) return std::nullopt;
    glm::vec3 a = from - camera.eye, b = to - camera.eye;
    float za = glm::dot(a, camera.forward), zb = glm::dot(b, camera.forward);
    // The part in front of the camera: from a plane just before the eye (a ray from the eye itself
    // then lands on the pixel it goes through).
    const float near = 1e-5f * std::max({1.0f, glm::length(a), glm::length(b)});
    if (za < near && zb < near) return std::nullopt;
    if (za < near) a += (b - a) * ((near - za) / (zb - za)), za = near;
    if (zb < near) b += (a - b) * ((near - zb) / (za - zb)), zb = near;
    const glm::vec2 pa = to_image(camera, width, height, a, za), pb = to_image(camera, width, height, b, zb);
    // Cut to the image (Liang-Barsky): t in [t0, t1] along pa → pb stays inside.
    const glm::vec2 d = pb - pa;
    float t0 = 0.0f, t1 = 1.0f;
    const float p[4] = {-d.x, d.x, -d.y, d.y};
    const float q[4] = {pa.x, float(width) - pa.x, pa.y, float(height) - pa.y};
    for (int i = 0; i < 4; ++i) {
        if (p[i] == 0.0f) {
            if (q[i] < 0.0f) return std::nullopt;
            continue;
        }
        const float r = q[i] / p[i];
        if (p[i] < 0.0f) t0 = std::max(t0, r);
        else t1 = std::min(t1, r);
    }
    if (t0 > t1) return std::nullopt;
    return ImageSegment{pa + t0 * d, pa + t1 * d};
}

std::string ray_tree_text(const RayTree& tree, const std::string& base_dir) {
    std::ostringstream out;
    out << "ray tree of that sample: " << tree.segments.size() << (tree.segments.size() == 1 ? " segment" : " segments")
        << ", " << tree.deepest() << (tree.deepest() == 1 ? " bounce" : " bounces") << "\n";
    for (std::size_t i = 0; i < tree.segments.size(); ++i) {
        const RaySegment& s = tree.segments[i];
        char head[64];
        std::snprintf(head, sizeof head, "  %2zu %-9s depth %d", i, ray_kind_name(s.kind), s.depth);
        out << head;
        if (s.parent >= 0) out << ", after " << s.parent;
        if (s.kind == RayKind::Shadow) out << ", to light " << s.light + 1;
        if (s.total_internal_reflection) out << " (total internal reflection)";
        if (s.inside) out << " (inside)";
        out << ": " << paren(s.from) << " to " << paren(s.to) << ": ";
        if (s.kind == RayKind::Shadow) {
            if (s.shadow == ShadowState::Blocked)
                out << "blocked by " << shape_name(s.shape) << " at " << display_loc(s.object, base_dir);
            else if (s.shadow == ShadowState::Tinted)
                out << "reaches the light through glass, tint " << paren(s.tint);
            else
                out << "reaches the light";
        } else if (s.hit) {
            out << "hits " << shape_name(s.shape) << " at " << display_loc(s.object, base_dir);
        } else {
            out << "leaves the scene";
        }
        out << "\n";
    }
    return out.str();
}

std::string ray_tree_obj(const RayTree& tree, const std::string& title) {
    std::ostringstream out;
    out << "# " << title << "\n# " << tree.segments.size()
        << " segments (camera, reflected, refracted and shadow rays), each an object of one line\n";
    for (std::size_t i = 0; i < tree.segments.size(); ++i) {
        const RaySegment& s = tree.segments[i];
        out << "o " << i << "_" << ray_kind_name(s.kind) << "_depth" << s.depth << "\n";
        for (const glm::vec3& v : {s.from, s.to}) out << "v " << exact(v.x) << " " << exact(v.y) << " " << exact(v.z) << "\n";
        out << "l " << 2 * i + 1 << " " << 2 * i + 2 << "\n";
    }
    return out.str();
}

std::string ray_tree_json(const RayTree& tree, int x, int y, const std::string& base_dir) {
    std::ostringstream out;
    const Camera& c = tree.camera;
    out << "{\"pixel\":[" << x << "," << y << "],\"image\":[" << tree.width << "," << tree.height << "],"
        << "\"camera\":{\"eye\":" << json_vec(c.eye) << ",\"forward\":" << json_vec(c.forward)
        << ",\"right\":" << json_vec(c.right) << ",\"up\":" << json_vec(c.up)
        << ",\"tan_half_fov\":" << exact(c.tan_half_fov) << "},\"segments\":[";
    for (std::size_t i = 0; i < tree.segments.size(); ++i) {
        const RaySegment& s = tree.segments[i];
        out << (i ? "," : "") << "\n {\"kind\":\"" << ray_kind_name(s.kind) << "\",\"depth\":" << s.depth
            << ",\"parent\":" << s.parent << ",\"from\":" << json_vec(s.from) << ",\"to\":" << json_vec(s.to)
            << ",\"hit\":" << (s.hit ? "true" : "false") << ",\"escaped\":" << (s.escaped ? "true" : "false");
        if (s.hit) out << ",\"object\":" << json_string(display_loc(s.object, base_dir)) << ",\"shape\":\"" << shape_name(s.shape) << "\"";
        if (s.total_internal_reflection) out << ",\"total_internal_reflection\":true";
        if (s.inside) out << ",\"inside\":true";
        if (s.kind == RayKind::Shadow)
            out << ",\"light\":" << s.light << ",\"shadow\":\"" << shadow_state_name(s.shadow) << "\",\"tint\":" << json_vec(s.tint);
        out << "}";
    }
    out << "\n]}\n";
    return out.str();
}

}  // namespace whitted
