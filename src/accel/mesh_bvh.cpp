#include "accel/mesh_bvh.h"

#include <algorithm>
#include <cmath>

#include "accel/bvh.h"
#include "base/parallel_for.h"

namespace whitted {
namespace {

// SAH costs for triangles, tested four at a time (watertight_triangle4.h): a leaf costs its
// count rounded up to whole groups of four, a traversal step two such groups; leaves of up to
// eight. Against counting single triangles (2.0, 8, block 1) on the 1M-triangle bench mesh
// (bench/RESULTS.md): less than half as many nodes (leaves of about four triangles, not two),
// 28 instead of 40 bytes per triangle with the mesh, a faster build, rays as fast or faster; and
// against traversal costs 0.5 to 4 and leaves of 4 to 16, as fast or faster within the noise.
constexpr BvhBuildCosts kTriangleCosts{2.0f, 8, 4};

template <class T>
std::size_t bytes_of(const BigVector<T>& v) {
    return v.capacity() * sizeof(T);
}

template <class T>
void permute(BigVector<T>& v, const std::vector<std::uint32_t>& order) {
    if (v.empty()) return;
    BigVector<T> out(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
    v.swap(out);
}

// The triangle's box, padded by a few ulps of its magnitude so that a hit computed with the
// shear of the watertight test (its own rounding) is never outside the box that leads to it.
Bounds padded_triangle_bounds(const TriangleMesh& mesh, std::uint32_t t) {
    Bounds b;
    for (std::uint32_t c : mesh.triangles[t]) b.grow(mesh.positions[c]);
    return b.padded(1e-6f);
}

// Copies every leaf's triangles into blocks of four (triangle_block.h), in the order of the
// triangles (so a ray walking neighbouring leaves reads neighbouring blocks), and points the
// leaves at their first block: a leaf's count stays its number of triangles. The copying runs on
// `threads` threads (each leaf's blocks are known before, so the result is the same).
void make_blocks(MeshBvh& out, const TriangleMesh& mesh, int threads) {
    std::vector<std::uint32_t*> leaves;
    for (Bvh8Node& n : out.bvh.nodes)
        for (std::uint32_t& ref : n.child)
            if (Bvh8Node::is_leaf(ref)) leaves.push_back(&ref);
    std::sort(leaves.begin(), leaves.end(), [](const std::uint32_t* a, const std::uint32_t* b) {
        return Bvh8Node::leaf_first(*a) < Bvh8Node::leaf_first(*b);
    });
    std::vector<std::uint32_t> first_block(leaves.size() + 1, 0);
    for (std::size_t l = 0; l < leaves.size(); ++l)
        first_block[l + 1] = first_block[l] + (Bvh8Node::leaf_count(*leaves[l]) + 3) / 4;
    out.blocks.resize(first_block.back());
    out.block_first_triangle.resize(first_block.back());
    constexpr std::size_t kChunk = 4096;  // leaves per work item
    const std::size_t chunks = (leaves.size() + kChunk - 1) / kChunk;
    parallel_for(chunks, worker_count(threads, chunks), [&](std::size_t c, int) {
        for (std::size_t l = c * kChunk; l < std::min(leaves.size(), (c + 1) * kChunk); ++l) {
            std::uint32_t& ref = *leaves[l];
            const std::uint32_t first = Bvh8Node::leaf_first(ref), n = Bvh8Node::leaf_count(ref);
            std::uint32_t block = first_block[l];
            ref = Bvh8Node::kLeafBit | (block << 4) | (n - 1);
            for (std::uint32_t k = 0; k < n; k += 4, ++block) {
                fill_triangle_block(out.blocks[block], mesh.positions.data(), mesh.triangles.data(), first + k,
                                    std::min<std::uint32_t>(n - k, 4));
                out.block_first_triangle[block] = first + k;
            }
        }
    });
}

}  // namespace

std::size_t MeshBvh::memory_bytes() const {
    return bytes_of(bvh.nodes) + bytes_of(blocks) + bytes_of(block_first_triangle) + sizeof(*this);
}

MeshBvh build_mesh_bvh(TriangleMesh& mesh, int threads, const std::atomic<bool>* cancel) {
    MeshBvh out;
    std::vector<std::uint32_t> order;
    out.bvh = build_bvh8_over_boxes(
        mesh.triangles.size(), [&](std::uint32_t t) { return padded_triangle_bounds(mesh, t); }, kTriangleCosts, threads,
        order, cancel);
    if (out.bvh.nodes.empty()) return out;  // cancelled
    // The build reserves for the worst case; a mesh lives long. Shrunk (a copy) before the
    // blocks are made, and the order let go before them, so that neither adds to their peak.
    out.bvh.nodes.shrink_to_fit();
    permute(mesh.triangles, order);
    std::vector<std::uint32_t>().swap(order);
    make_blocks(out, mesh, threads);
    mesh.box = out.bvh.box;
    return out;
}

namespace {

template <class Tester>
WHITTED_BVH_INLINE bool nearest_with(const MeshBvh& mesh, const Ray& ray, float t_min, float t_max, MeshHit& hit) {
    const WatertightRay wr(ray);
    const WatertightRay4 wr4(wr);
    const TriangleBlock* blocks = mesh.blocks.data();
    float best = t_max;
    float limit = t_max;  // up to `best` inclusive once found, for the tie rule: an equal t from a lower index wins
    bool found = false;
    const bvh_detail::BoxRay box_ray(ray);
    bvh_detail::walk_nearest_with(Tester(box_ray), mesh.bvh, t_min, best, [&](std::uint32_t first, std::uint32_t end) {
        // `first` is the leaf's first block, end − first its number of triangles.
        for (std::uint32_t b = first, left = end - first; left > 0; ++b, left -= left < 4 ? left : 4) {
            Triangle4Hits h;
            int mask = intersect_triangles4(wr4, blocks[b], left < 4 ? left : 4, t_min, limit, h);
            // In index order, as one triangle at a time: a hit must still beat the limit its
            // predecessors in the block have lowered.
            for (; mask != 0; mask &= mask - 1) {
                const int j = __builtin_ctz(unsigned(mask));
                if (!(h.t[j] < limit)) continue;
                const std::uint32_t i = mesh.block_first_triangle[b] + std::uint32_t(j);
                if (!found || h.t[j] < best || i < hit.triangle) {
                    best = h.t[j];
                    limit = std::nextafter(best, t_max);
                    hit = {h.t[j], h.u[j], h.v[j], i};
                    found = true;
                }
            }
        }
    });
    return found;
}

#ifdef WHITTED_BVH_AVX2
[[gnu::target("avx2"), gnu::flatten]] bool nearest_avx2(const MeshBvh& mesh, const Ray& ray, float t_min,
                                                        float t_max, MeshHit& hit) {
    return nearest_with<bvh_detail::BoxTesterAvx2>(mesh, ray, t_min, t_max, hit);
}
#endif

}  // namespace

bool set_mesh_walks_use_avx2(bool on) {
    mesh_detail::use_avx2 = on && mesh_detail::cpu_allows_avx2();
    return mesh_detail::use_avx2;
}

bool mesh_intersect_nearest(const MeshBvh& mesh, const Ray& ray, float t_min, float t_max, MeshHit& hit) {
#ifdef WHITTED_BVH_AVX2
    if (mesh_detail::use_avx2) return nearest_avx2(mesh, ray, t_min, t_max, hit);
#endif
    return nearest_with<bvh_detail::BoxTester>(mesh, ray, t_min, t_max, hit);
}

bool mesh_intersect_nearest_brute_force(const TriangleMesh& mesh, const Ray& ray, float t_min, float t_max,
                                        MeshHit& hit) {
    const WatertightRay wr(ray);
    bool found = false;
    for (std::uint32_t i = 0; i < mesh.triangles.size(); ++i) {
        const TriangleIndices& c = mesh.triangles[i];
        TriangleHit h;
        if (intersect_triangle(wr, mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]], t_min,
                               found ? hit.t : t_max, h)) {
            hit = {h.t, h.u, h.v, i};
            found = true;
        }
    }
    return found;
}

}  // namespace whitted
