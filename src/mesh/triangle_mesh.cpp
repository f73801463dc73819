#include "mesh/triangle_mesh.h"

#include <cmath>

namespace whitted {

template <class V>
static std::size_t bytes_of(const std::vector<V>& v) {
    return v.capacity() * sizeof(V);
}

std::size_t TriangleMesh::memory_bytes() const {
    return bytes_of(positions) + bytes_of(triangles) + bytes_of(normals) + bytes_of(normal_indices) + bytes_of(uvs) +
           bytes_of(uv_indices) + bytes_of(bvh.nodes) + bytes_of(blocks) +
           bytes_of(block_first_triangle) + sizeof(*this);
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
    if (!mesh.normal_indices.empty()) {
        const TriangleIndices& c = mesh.normal_indices[t];
        if (c[0] != TriangleMesh::kNone) {
            const glm::vec3 n = (1.0f - u - v) * mesh.normals[c[0]] + u * mesh.normals[c[1]] + v * mesh.normals[c[2]];
            const float len = glm::length(n);
            if (len > 0.0f && std::isfinite(len)) return n / len;
        }
    }
    return glm::normalize(triangle_geometric_normal(mesh, t));
}

glm::vec2 mesh_uv(const TriangleMesh& mesh, std::uint32_t t, float u, float v) {
    if (mesh.uv_indices.empty()) return glm::vec2(0.0f);
    const TriangleIndices& c = mesh.uv_indices[t];
    if (c[0] == TriangleMesh::kNone) return glm::vec2(0.0f);
    const glm::vec2 st = (1.0f - u - v) * mesh.uvs[c[0]] + u * mesh.uvs[c[1]] + v * mesh.uvs[c[2]];
    return {st.x, 1.0f - st.y};
}

}  // namespace whitted
