#include "mesh/polygon_split.h"

#include <cmath>

namespace whitted {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

void fan(std::uint32_t n, Triangles& out) {
    for (std::uint32_t k = 1; k + 1 < n; ++k) out.push_back({0, k, k + 1});
}

// Twice the signed area of the 2D triangle (a, b, c): positive counter-clockwise.
double cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Ear clipping (Eberly, "Triangulation by ear clipping") on the polygon projected along the
// largest axis of its Newell normal, wound counter-clockwise there. Ears are known ahead: clipping
// one changes only whether its two neighbours are ears (for a simple polygon), so the whole costs
// O(n²). A polygon with no ear left (self-intersecting, or folded) is clipped where the walk is,
// so that any input still gives n − 2 triangles.
void clip_ears(const glm::vec3* corners, std::uint32_t n, Triangles& out) {
    glm::dvec3 normal(0.0);
    for (std::uint32_t i = 0; i < n; ++i) {
        const glm::dvec3 a(corners[i]), b(corners[(i + 1) % n]);
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    const glm::dvec3 m = glm::abs(normal);
    const int drop = m.x >= m.y && m.x >= m.z ? 0 : m.y >= m.z ? 1 : 2;
    if (!(m[drop] > 0.0) || !std::isfinite(m[drop])) return fan(n, out);  // no plane to work in
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    const double flip = normal[drop] > 0.0 ? 1.0 : -1.0;  // counter-clockwise in (u, v) after it
    std::vector<glm::dvec2> p(n);
    for (std::uint32_t i = 0; i < n; ++i) p[i] = {double(corners[i][u]), flip * double(corners[i][v])};

    std::vector<std::uint32_t> prev(n), next(n);
    for (std::uint32_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
    auto is_ear = [&](std::uint32_t i) {
        const glm::dvec2 &a = p[prev[i]], &b = p[i], &c = p[next[i]];
        if (!(cross(a, b, c) > 0.0)) return false;  // reflex or flat
        for (std::uint32_t j = next[next[i]]; j != prev[i]; j = next[j]) {
            const glm::dvec2& q = p[j];
            if (q == a || q == b || q == c) continue;  // a corner repeated
            if (cross(a, b, q) >= 0.0 && cross(b, c, q) >= 0.0 && cross(c, a, q) >= 0.0) return false;
        }
        return true;
    };
    std::vector<char> ear(n);
    for (std::uint32_t i = 0; i < n; ++i) ear[i] = is_ear(i);
    std::uint32_t at = 0;
    for (std::uint32_t left = n; left > 3; --left) {
        std::uint32_t i = at;
        for (std::uint32_t k = 0; k < left && !ear[i]; ++k) i = next[i];
        // (none found: i is back at `at`, clipped anyway)
        out.push_back({prev[i], i, next[i]});
        const std::uint32_t a = prev[i], c = next[i];
        next[a] = c;
        prev[c] = a;
        ear[a] = is_ear(a);
        ear[c] = is_ear(c);
        at = c;
    }
    out.push_back({prev[at], at, next[at]});
}

}  // namespace

void split_polygon(const glm::vec3* corners, std::uint32_t n, Triangles& out) {
    if (n == 3) {
        out.push_back({0, 1, 2});
    } else if (n == 4) {
        // The shorter diagonal, as tinyobjloader splits quads.
        const glm::vec3 d02 = corners[2] - corners[0], d13 = corners[3] - corners[1];
        if (glm::dot(d02, d02) < glm::dot(d13, d13)) {
            out.push_back({0, 1, 2});
            out.push_back({0, 2, 3});
        } else {
            out.push_back({0, 1, 3});
            out.push_back({1, 2, 3});
        }
    } else if (n <= kEarClipCorners) {
        clip_ears(corners, n, out);
    } else {
        fan(n, out);
    }
}

}  // namespace whitted
