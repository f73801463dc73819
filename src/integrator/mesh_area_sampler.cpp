#include "integrator/mesh_area_sampler.h"

#include <algorithm>
#include <cmath>

namespace whitted {

namespace {
glm::vec3 world_corner(const TriangleMesh& mesh, const glm::mat4& m, std::uint32_t t, int k) {
    return glm::vec3(m * glm::vec4(mesh.positions[mesh.triangles[t][k]], 1.0f));
}
}  // namespace

MeshAreaSampler::MeshAreaSampler(const TriangleMesh& mesh, const glm::mat4& object_to_world)
    : mesh_(mesh), to_world_(object_to_world) {
    cdf_.resize(mesh.triangles.size());
    double sum = 0.0;  // in double: a million small areas summed in float would drift
    for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const glm::vec3 a = world_corner(mesh, to_world_, t, 0), b = world_corner(mesh, to_world_, t, 1),
                        c = world_corner(mesh, to_world_, t, 2);
        sum += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
        cdf_[t] = float(sum);
    }
    total_ = float(sum);
    if (sum > 0.0)
        for (float& f : cdf_) f = float(double(f) / sum);
}

AreaSample MeshAreaSampler::sample(const glm::vec3& u) const {
    // The first triangle whose cumulative share exceeds u.x (never one of zero area).
    const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), u.x);
    const std::uint32_t t = std::uint32_t(std::min<std::ptrdiff_t>(it - cdf_.begin(), std::ptrdiff_t(cdf_.size()) - 1));
    // Uniform in the triangle: b0 = 1 − √ξ1, b1 = √ξ1·(1 − ξ2), b2 = √ξ1·ξ2 (Shirley's warp; pbrt 4.3).
    const float r = std::sqrt(u.y);
    const float b1 = r * (1.0f - u.z), b2 = r * u.z;
    const glm::vec3 a = world_corner(mesh_, to_world_, t, 0), b = world_corner(mesh_, to_world_, t, 1),
                    c = world_corner(mesh_, to_world_, t, 2);
    AreaSample s;
    s.point = a + b1 * (b - a) + b2 * (c - a);
    s.normal = glm::normalize(glm::cross(b - a, c - a));
    s.triangle = t;
    s.pdf_area = total_ > 0.0f ? 1.0f / total_ : 0.0f;
    return s;
}

}  // namespace whitted
