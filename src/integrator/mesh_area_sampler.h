#pragma once
// Points drawn uniformly by area over a placed mesh's surface: what a path tracer needs to sample
// an emissive mesh as an area light (next-event estimation, scene-format.md §9.2). A triangle is
// picked with probability proportional to its world-space area (the instance's matrix may stretch
// some triangles more than others), then a point uniformly inside it.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "data/triangle_mesh.h"

namespace whitted {

struct AreaSample {
    glm::vec3 point;       // world space
    glm::vec3 normal;      // world space, unit: the triangle's geometric normal
    std::uint32_t triangle;
    float pdf_area;        // probability density per unit world area: 1 / total area
};

class MeshAreaSampler {
public:
    // For `mesh` placed by the affine `object_to_world`. Triangles of zero world area are never drawn.
    MeshAreaSampler(const TriangleMesh& mesh, const glm::mat4& object_to_world);

    float total_area() const { return total_; }
    // u in [0, 1)³: u.x picks the triangle, (u.y, u.z) the point in it.
    AreaSample sample(const glm::vec3& u) const;

private:
    const TriangleMesh& mesh_;
    glm::mat4 to_world_;
    std::vector<float> cdf_;  // cdf_[i] = area of triangles [0, i] / total
    float total_ = 0.0f;
};

}  // namespace whitted
