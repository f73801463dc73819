#include "data/triangle_mesh.h"

#include <cmath>

namespace whitted {

template <class V, class A>
static std::size_t bytes_of(const std::vector<V, A>& v) {
    return v.capacity() * sizeof(V);
}

std::size_t TriangleMesh::memory_bytes() const {
    return bytes_of(positions) + bytes_of(triangles) + bytes_of(normals) + bytes_of(uvs) + sizeof(*this);
}

glm::vec3 triangle_geometric_normal(const TriangleMesh& mesh, std::uint32_t t) {
    const TriangleIndices& c = mesh.triangles[t];
    const glm::vec3 p0 = mesh.positions[c[0]];
    return glm::cross(mesh.positions[c[1]] - p0, mesh.positions[c[2]] - p0);
}

float triangle_area(const TriangleMesh& mesh, std::uint32_t t) {
    return 0.5f * glm::length(triangle_geometric_normal(mesh, t));
}

glm::vec3 mesh_shading_normal(const TriangleMesh& mesh, std::uint32_t t, float u, float v) {
    if (!mesh.normals.empty()) {
        const TriangleIndices& c = mesh.triangles[t];
        const glm::vec3 &n0 = mesh.normals[c[0]], &n1 = mesh.normals[c[1]], &n2 = mesh.normals[c[2]];
        const glm::vec3 zero(0.0f);
        if (n0 != zero && n1 != zero && n2 != zero) {  // every corner has the file's normal
            const glm::vec3 n = (1.0f - u - v) * n0 + u * n1 + v * n2;
            const float len = glm::length(n);
            if (len > 0.0f && std::isfinite(len)) return n / len;
        }
    }
    return glm::normalize(triangle_geometric_normal(mesh, t));
}

glm::vec2 mesh_uv(const TriangleMesh& mesh, std::uint32_t t, float u, float v) {
    if (mesh.uvs.empty()) return glm::vec2(0.0f);
    const TriangleIndices& c = mesh.triangles[t];
    const glm::vec2 &a = mesh.uvs[c[0]], &b = mesh.uvs[c[1]], &d = mesh.uvs[c[2]];
    if (std::isnan(a.x) || std::isnan(b.x) || std::isnan(d.x)) return glm::vec2(0.0f);  // a corner without vt
    const glm::vec2 st = (1.0f - u - v) * a + u * b + v * d;
    return {st.x, 1.0f - st.y};
}

}  // namespace whitted
