#pragma once
// Meshes made in code for the mesh tests: a closed tessellated sphere, random triangle soups, the
// 12-triangle unit cube (as an OBJ text, the corners of `object cube`).
#include <cmath>
#include <random>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "data/triangle_mesh.h"
#include "mesh/uv_sphere.h"

namespace whitted::test {

// A closed UV sphere of the given radius (mesh/uv_sphere.h) with its vertex normals.
inline TriangleMesh uv_sphere(int rings, int segments, float radius = 0.5f) {
    TriangleMesh m = uv_sphere_mesh(rings, segments, [radius](const glm::vec3&) { return radius; });
    m.normals.reserve(m.positions.size());
    for (const glm::vec3& p : m.positions) m.normals.push_back(glm::normalize(p));
    return m;
}

// n random triangles in [-1, 1]³ of sizes from tiny to large, each with its own three corners.
inline TriangleMesh random_soup(int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> pos(-1.0f, 1.0f), size(0.001f, 0.5f);
    TriangleMesh m;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 c(pos(rng), pos(rng), pos(rng));
        const float s = size(rng);
        const std::uint32_t base = std::uint32_t(m.positions.size());
        for (int k = 0; k < 3; ++k) m.positions.push_back(c + s * glm::vec3(pos(rng), pos(rng), pos(rng)));
        m.triangles.push_back({base, base + 1, base + 2});
    }
    return m;
}

// The unit cube of `object cube` as OBJ: 8 corners, 6 quads (triangulated on reading) wound
// counter-clockwise from outside, each face with the texture coordinates of §8's cube mapping
// written as OBJ vt (v up, so vt.v = 1 − the format's v).
inline std::string cube_obj() {
    return R"(# unit cube, faces at +-0.5
v -0.5 -0.5 -0.5
v  0.5 -0.5 -0.5
v  0.5  0.5 -0.5
v -0.5  0.5 -0.5
v -0.5 -0.5  0.5
v  0.5 -0.5  0.5
v  0.5  0.5  0.5
v -0.5  0.5  0.5
vt 0 0
vt 1 0
vt 1 1
vt 0 1
# front +z: u = x + .5, v = .5 - y
f 5/1 6/2 7/3 8/4
# back -z: u = .5 - x
f 2/1 1/2 4/3 3/4
# right +x: u = .5 - z
f 6/1 2/2 3/3 7/4
# left -x: u = z + .5
f 1/1 5/2 8/3 4/4
# top +y: u = x + .5, v = z + .5
f 8/1 7/2 3/3 4/4
# bottom -y: u = x + .5, v = .5 - z
f 1/1 2/2 6/3 5/4
)";
}

// Instance i of a 100 × 100 grid in the plane z = 0, spaced 2 apart.
inline glm::mat4 translate_scale_for_grid(int i) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(2.0f * float(i % 100), 2.0f * float(i / 100), 0.0f));
}

}  // namespace whitted::test
