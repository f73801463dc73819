// libFuzzer target: any bytes as an OBJ file (scene-format.md §9.3), read into a mesh, its BVH
// built and rays cast at it. Must never crash, read out of bounds or hang: every index a face
// names is checked before it is used, whatever the line endings.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "accel/mesh_bvh.h"
#include "mesh/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace whitted;
    ObjLimits limits;
    limits.max_bytes = std::size_t(256) << 20;  // within libFuzzer's memory limit
    TriangleMesh mesh;
    const ObjReadResult r = read_obj_text(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.obj", mesh,
                                          limits);
    if (!r.ok) return 0;
    // What the rest of whitted relies on: every corner a vertex, attributes per vertex or none.
    for (const TriangleIndices& t : mesh.triangles)
        for (std::uint32_t c : t)
            if (c >= mesh.positions.size()) __builtin_trap();
    if ((!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size()) ||
        (!mesh.uvs.empty() && mesh.uvs.size() != mesh.positions.size()))
        __builtin_trap();
    const MeshBvh bvh = build_mesh_bvh(mesh, 1);
    const glm::vec3 centre = mesh.box.centre();
    float sum = 0;
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 from = centre + glm::vec3(i & 1 ? 3.0f : -3.0f, i & 2 ? 2.0f : -2.0f, i & 4 ? 5.0f : -5.0f) *
                                            (1.0f + glm::length(mesh.box.hi - mesh.box.lo));
        MeshHit hit;
        if (mesh_intersect_nearest(bvh, Ray{from, centre - from}, 0.0f, 1e30f, hit)) {
            sum += hit.t + mesh_shading_normal(mesh, hit.triangle, hit.u, hit.v).x + mesh_uv(mesh, hit.triangle, hit.u, hit.v).x;
        }
    }
    __asm__ volatile("" : : "r"(sum));  // keep the work
    return 0;
}
