#include "mesh/uv_sphere.h"

#include <cmath>

namespace whitted {

TriangleMesh uv_sphere_mesh(int rings, int segments, const std::function<float(const glm::vec3&)>& radius) {
    TriangleMesh m;
    const float pi = 3.14159265358979f;
    auto place = [&](const glm::vec3& d) { m.positions.push_back(radius(d) * d); };
    place({0, 1, 0});
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const float theta = pi * float(r) / float(rings), phi = 2 * pi * float(s) / float(segments);
            place({std::sin(theta) * std::cos(phi), std::cos(theta), -std::sin(theta) * std::sin(phi)});
        }
    place({0, -1, 0});
    const std::uint32_t south = std::uint32_t(m.positions.size() - 1);
    auto at = [&](int r, int s) { return std::uint32_t(1 + (r - 1) * segments + (s % segments)); };
    for (int s = 0; s < segments; ++s) m.triangles.push_back({0, at(1, s), at(1, s + 1)});
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            m.triangles.push_back({at(r, s), at(r + 1, s), at(r + 1, s + 1)});
            m.triangles.push_back({at(r, s), at(r + 1, s + 1), at(r, s + 1)});
        }
    for (int s = 0; s < segments; ++s) m.triangles.push_back({at(rings - 1, s), south, at(rings - 1, s + 1)});
    m.positions.shrink_to_fit();  // exact sizes, as the OBJ reader leaves them
    m.triangles.shrink_to_fit();
    return m;
}

}  // namespace whitted
