#pragma once
// A triangle mesh in object space (scene-format.md §9.3), as read from an OBJ file: shared
// vertex positions, optional per-corner normals and texture coordinates. Geometry only: its BVH
// (accel/mesh_bvh.h) is the acceleration stage's, which puts the triangles in its leaf order.
// Stored once however many instances draw it.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "base/big_vector.h"
#include "base/bounds.h"

namespace whitted {

using TriangleIndices = std::array<std::uint32_t, 3>;

// What a triangle costs at the peak of building its mesh's BVH, besides the mesh itself: the build's
// boxes and nodes, then the BVH's nodes and blocks of four triangles kept (accel/mesh_bvh.h;
// bench/RESULTS.md: 28 bytes a triangle kept). Rounded up: an estimate must not be low.
constexpr std::size_t kMeshBvhBytesPerTriangle = 96;

struct TriangleMesh {
    // One index per corner for all of a vertex's attributes (the OBJ reader makes a vertex per
    // distinct v/vt/vn of the file's corners, as pbrt and Embree keep meshes).
    BigVector<glm::vec3> positions;
    BigVector<TriangleIndices> triangles;  // into positions, counter-clockwise seen from outside
    // Per vertex, as positions; empty when the file gives none. A vertex whose corner had no normal
    // holds (0, 0, 0) (its triangles take their geometric normal), one without vt (NaN, NaN) (its
    // triangles take uv (0, 0)).
    BigVector<glm::vec3> normals;
    BigVector<glm::vec2> uvs;
    Bounds box;    // of all positions used by triangles
    std::string path;  // the file it came from, for messages

    std::size_t triangle_count() const { return triangles.size(); }
    // Bytes of memory held by the geometry (the BVH counts its own: MeshBvh::memory_bytes).
    std::size_t memory_bytes() const;
};

// The geometric normal of triangle `t` (unnormalised: (p1 − p0) × (p2 − p0), outward for
// counter-clockwise corners) and its area.
glm::vec3 triangle_geometric_normal(const TriangleMesh& mesh, std::uint32_t t);
float triangle_area(const TriangleMesh& mesh, std::uint32_t t);

// The object-space shading normal at barycentrics (u, v) of triangle `t` (weights 1 − u − v, u, v
// of its corners): the file's normals interpolated where given, else the geometric normal. Unit.
glm::vec3 mesh_shading_normal(const TriangleMesh& mesh, std::uint32_t t, float u, float v);

// Texture coordinates at (u, v) of triangle `t`: the file's vt interpolated, with v flipped so
// that vt (0, 0) is the image's bottom-left corner as in every OBJ exporter; (0, 0) without vt.
glm::vec2 mesh_uv(const TriangleMesh& mesh, std::uint32_t t, float u, float v);

}  // namespace whitted
