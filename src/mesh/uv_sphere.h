#pragma once
// A closed UV sphere as a triangle mesh, generated: for tests and benchmarks that need a closed,
// consistently wound mesh of a chosen size without a file.
#include <functional>

#include "data/triangle_mesh.h"

namespace whitted {

// `rings` latitude bands (>= 2) and `segments` longitude ones (>= 3); the vertex in unit direction d
// is placed at radius(d) · d. Shared vertices (each pole once), counter-clockwise seen from outside
// (for a star-shaped radius), no normals or uvs; 2·segments·(rings − 1) triangles.
TriangleMesh uv_sphere_mesh(int rings, int segments, const std::function<float(const glm::vec3&)>& radius);

}  // namespace whitted
