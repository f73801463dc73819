// Packet traversal of the 4-wide BVH. The SIMD lanes are rays: at a node, each child box is
// tested against all the packet's rays at once (four SSE registers of four rays, or two AVX2
// registers of eight where the CPU has AVX2: SseLanes, Avx2Lanes), and a child is
// visited if any lane still wanting it enters it no farther than that lane's nearest hit so far.
// Every lane keeps its own nearest hit, and its box test is the single-ray test
// (bvh_traverse.cpp) evaluated in another lane, so a lane visits every box its single ray would
// have to visit to find its answer; the leaves compute the same intervals as the single-ray code
// (bvh_ray.h, bvh_packet_shapes.h) and keep the same nearest hit of what they see. The extra
// boxes a lane is taken into only cost time.
// Camera packets (one origin, one direction sign per axis) first cull the node's children with
// one test for the whole packet (frustum_slots), then test the lanes on the children left.
#include "accel/bvh_packet.h"

#include <cstddef>
#include <limits>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define WHITTED_BVH_SSE 1
#endif

#include "shapes/unit_shape_math4.h"
#include "shapes/unit_shape_math8.h"
#include "accel/bvh_box_test_avx2.h"
#include "accel/bvh_mesh_leaf.h"
#include "accel/bvh_ray.h"
#include "accel/mesh_bvh.h"

namespace whitted {
namespace {

// The lanes one at a time: the single-ray query, lane by lane (a scene without SSE, and a scene
// with meshes, whose top level is 8-wide: bvh_node.h).
unsigned one_by_one(const Bvh& bvh, const std::vector<Instance>& instances, const Ray (&rays)[kPacketSize],
                           unsigned active, float t_min, float t_max, Hit (&hits)[kPacketSize],
                           const std::vector<MeshBvh>* meshes) {
    unsigned result = 0;
    for (int l = 0; l < kPacketSize; ++l)
        if (((active >> l) & 1) && intersect_nearest(bvh, instances, rays[l], t_min, t_max, hits[l], meshes))
            result |= 1u << l;
    return result;
}

}  // namespace

#ifdef WHITTED_BVH_SSE
namespace {

using bvh_detail::kStackSize;
constexpr int kGroups = kPacketSize / 4;  // SSE registers per packet quantity
static_assert(kPacketSize % 4 == 0 && kPacketSize <= 32);

inline int lowest_bit(unsigned mask) { return __builtin_ctz(mask); }

// All-ones in the lanes whose bit is set: four bits of a lane mask as an SSE mask.
struct LaneMasks {
    alignas(16) std::uint32_t m[16][4];
    constexpr LaneMasks() : m{} {
        for (int b = 0; b < 16; ++b)
            for (int l = 0; l < 4; ++l) m[b][l] = (b >> l & 1) ? 0xffffffffu : 0u;
    }
};
constexpr LaneMasks kLaneMasks;
inline __m128 lane_mask(unsigned bits) { return _mm_load_ps(reinterpret_cast<const float*>(kLaneMasks.m[bits & 15])); }

// The packet's rays as the box test wants them, structure of arrays. Inactive lanes have a NaN
// reciprocal direction: every comparison with their distances is false, so they enter no box.
struct PacketRays {
    __m128 o[kGroups][3], d[kGroups][3];  // per group of four lanes: x, y, z
    __m128 inv[3][kGroups];
    // When every lane's direction has the same sign per axis (most camera packets): the box rows
    // of the near and far planes per axis, as in the single-ray test.
    int near_row[3], far_row[3];
    bool same_signs;
    // When every lane starts at the same point (camera rays): box - origin is the same for all
    // lanes, computed once per node for four children.
    bool common_origin;
    __m128 origin[3];  // broadcast
    // The smallest and largest reciprocal direction per axis over the active lanes (broadcast).
    __m128 inv_lo[3], inv_hi[3];

    PacketRays(const Ray (&rays)[kPacketSize], unsigned active) {
        static_assert(offsetof(Ray, origin) == 0 && offsetof(Ray, direction) == 3 * sizeof(float));  // read as floats 0-5
        const int first = __builtin_ctz(active);
        const __m128 sign = _mm_set1_ps(-0.0f), tiny = _mm_set1_ps(1e-30f), one = _mm_set1_ps(1.0f);
        const __m128 nan = _mm_set1_ps(std::numeric_limits<float>::quiet_NaN());
        const float* first_ray = reinterpret_cast<const float*>(&rays[first]);
        for (int a = 0; a < 3; ++a) origin[a] = _mm_set1_ps(first_ray[a]);
        unsigned negative[3] = {0, 0, 0}, same_origin = 0;
        for (int g = 0; g < kGroups; ++g) {
            // Four rays to structure of arrays: (ox, oy, oz, dx) and (oz, dx, dy, dz) of each,
            // transposed. Inactive lanes take the first active lane's ray (any finite ray).
            __m128 head[4], tail[4];
            for (int k = 0; k < 4; ++k) {
                const int l = 4 * g + k;
                const float* ray = reinterpret_cast<const float*>(&rays[((active >> l) & 1) ? l : first]);
                head[k] = _mm_loadu_ps(ray);
                tail[k] = _mm_loadu_ps(ray + 2);
            }
            _MM_TRANSPOSE4_PS(head[0], head[1], head[2], head[3]);
            _MM_TRANSPOSE4_PS(tail[0], tail[1], tail[2], tail[3]);
            const __m128 on = lane_mask(active >> (4 * g));
            __m128 same = on;
            for (int a = 0; a < 3; ++a) {
                o[g][a] = head[a];
                d[g][a] = tail[1 + a];
                same = _mm_and_ps(same, _mm_castsi128_ps(_mm_cmpeq_epi32(_mm_castps_si128(o[g][a]),
                                                                         _mm_castps_si128(origin[a]))));
                negative[a] |= unsigned(_mm_movemask_ps(_mm_and_ps(on, d[g][a]))) << (4 * g);  // = sign of 1/d
                // bvh_detail::safe_reciprocal: 1 / (|d| > 1e-30 ? d : copysign(1e-30, d)).
                const __m128 big = _mm_cmpgt_ps(_mm_andnot_ps(sign, d[g][a]), tiny);
                const __m128 safe =
                    _mm_or_ps(_mm_and_ps(big, d[g][a]), _mm_andnot_ps(big, _mm_or_ps(_mm_and_ps(sign, d[g][a]), tiny)));
                const __m128 rcp = _mm_div_ps(one, safe);  // inactive lanes: an active lane's
                inv_lo[a] = g == 0 ? rcp : _mm_min_ps(inv_lo[a], rcp);
                inv_hi[a] = g == 0 ? rcp : _mm_max_ps(inv_hi[a], rcp);
                inv[a][g] = _mm_or_ps(_mm_and_ps(on, rcp), _mm_andnot_ps(on, nan));
            }
            same_origin |= unsigned(_mm_movemask_ps(same)) << (4 * g);
        }
        common_origin = same_origin == active;  // bit for bit
        same_signs = true;
        for (int a = 0; a < 3; ++a) {
            inv_lo[a] = _mm_min_ps(inv_lo[a], _mm_shuffle_ps(inv_lo[a], inv_lo[a], _MM_SHUFFLE(2, 3, 0, 1)));
            inv_lo[a] = _mm_min_ps(inv_lo[a], _mm_shuffle_ps(inv_lo[a], inv_lo[a], _MM_SHUFFLE(1, 0, 3, 2)));
            inv_hi[a] = _mm_max_ps(inv_hi[a], _mm_shuffle_ps(inv_hi[a], inv_hi[a], _MM_SHUFFLE(2, 3, 0, 1)));
            inv_hi[a] = _mm_max_ps(inv_hi[a], _mm_shuffle_ps(inv_hi[a], inv_hi[a], _MM_SHUFFLE(1, 0, 3, 2)));
            same_signs = same_signs && (negative[a] == 0 || negative[a] == active);
            near_row[a] = negative[a] != 0 ? 3 + a : a;
            far_row[a] = negative[a] != 0 ? a : 3 + a;
        }
    }
};

template <int c>
inline __m128 broadcast(__m128 v) {
    return _mm_shuffle_ps(v, v, _MM_SHUFFLE(c, c, c, c));
}

// The node's box planes as test_child wants them: rows[a] the near and rows[3 + a] the far
// planes of axis a for the four children (kSameSigns; else the lo and hi rows), minus the
// origin when all lanes share it.
template <bool kSameSigns, bool kCommonOrigin>
inline void load_planes(const Bvh4Node& n, const PacketRays& r, __m128 (&rows)[6]) {
    for (int a = 0; a < 3; ++a) {
        rows[a] = _mm_load_ps(n.box[kSameSigns ? r.near_row[a] : a]);
        rows[3 + a] = _mm_load_ps(n.box[kSameSigns ? r.far_row[a] : 3 + a]);
        if (kCommonOrigin) {
            rows[a] = _mm_sub_ps(rows[a], r.origin[a]);
            rows[3 + a] = _mm_sub_ps(rows[3 + a], r.origin[a]);
        }
    }
}

// Tests every lane against one child box, given its planes (broadcast; test_child_planes):
// returns the lanes that enter the box within (t_min, limit) and stores their entry distances;
// `key` gets the smallest of those (+inf for the others), to order the children. The arithmetic
// is the single-ray test's, lane by lane: (plane - origin) · reciprocal; kSameSigns picks the
// planes by rows as it does, otherwise each lane takes the nearer and farther of the two, which
// is the same for a finite box (unused slots, +inf..-inf, must then be masked off by the caller).
template <bool kSameSigns, bool kCommonOrigin>
inline unsigned test_child(const PacketRays& r, const __m128 (&plane)[6], const __m128 (&limit)[kGroups], __m128 tmin,
                           float* enter_out, __m128& key) {
    const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());
    unsigned hit = 0;
    key = inf;
    for (int g = 0; g < kGroups; ++g) {
        __m128 t_near[3], t_far[3];
        for (int a = 0; a < 3; ++a) {
            const __m128 rel0 = kCommonOrigin ? plane[a] : _mm_sub_ps(plane[a], r.o[g][a]);
            const __m128 rel1 = kCommonOrigin ? plane[3 + a] : _mm_sub_ps(plane[3 + a], r.o[g][a]);
            const __m128 t0 = _mm_mul_ps(rel0, r.inv[a][g]);
            const __m128 t1 = _mm_mul_ps(rel1, r.inv[a][g]);
            t_near[a] = kSameSigns ? t0 : _mm_min_ps(t0, t1);
            t_far[a] = kSameSigns ? t1 : _mm_max_ps(t0, t1);
        }
        // The single-ray test's entry and exit (min and max are exact, so their order only
        // decides how NaN spreads: ordered so that NaN (an inactive lane) in gives NaN out).
        const __m128 enter = _mm_max_ps(_mm_max_ps(tmin, t_near[0]), _mm_max_ps(t_near[1], t_near[2]));
        const __m128 leave = _mm_min_ps(_mm_min_ps(limit[g], t_far[0]), _mm_min_ps(t_far[1], t_far[2]));
        const __m128 in = _mm_cmple_ps(enter, leave);
        hit |= unsigned(_mm_movemask_ps(in)) << (4 * g);
        _mm_store_ps(enter_out + 4 * g, enter);
        key = _mm_min_ps(key, _mm_max_ps(enter, _mm_andnot_ps(in, inf)));
    }
    return hit;
}

// test_child for slot c, its planes taken from the node's rows with register shuffles.
template <bool kSameSigns, bool kCommonOrigin, int c>
inline unsigned test_slot(const PacketRays& r, const __m128 (&rows)[6], const __m128 (&limit)[kGroups], __m128 tmin,
                          float* enter_out, __m128& key) {
    __m128 plane[6];
    for (int k = 0; k < 6; ++k) plane[k] = broadcast<c>(rows[k]);
    return test_child<kSameSigns, kCommonOrigin>(r, plane, limit, tmin, enter_out, key);
}

// For packets with one origin and one sign per axis: the slots whose boxes some lane may enter,
// from the whole packet at once (interval arithmetic over the lanes). With the origin shared,
// a lane's plane distance is rel · inv_l for the same rel, and rounding is monotonic, so the
// smallest over the lanes is rel · (smallest or largest inv) exactly: the bounds are lanes' own
// values, never tighter, so no lane that would enter a box is culled.
inline unsigned frustum_slots(const PacketRays& r, const __m128 (&rows)[6], __m128 tmin, __m128 limit_max) {
    __m128 near_min[3], far_max[3];
    for (int a = 0; a < 3; ++a) {
        near_min[a] = _mm_min_ps(_mm_mul_ps(rows[a], r.inv_lo[a]), _mm_mul_ps(rows[a], r.inv_hi[a]));
        far_max[a] = _mm_max_ps(_mm_mul_ps(rows[3 + a], r.inv_lo[a]), _mm_mul_ps(rows[3 + a], r.inv_hi[a]));
    }
    const __m128 enter = _mm_max_ps(_mm_max_ps(tmin, near_min[0]), _mm_max_ps(near_min[1], near_min[2]));
    const __m128 leave = _mm_min_ps(_mm_min_ps(limit_max, far_max[0]), _mm_min_ps(far_max[1], far_max[2]));
    return unsigned(_mm_movemask_ps(_mm_cmple_ps(enter, leave)));
}

inline float horizontal_min(__m128 v) {
    v = _mm_min_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1)));
    v = _mm_min_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 0, 3, 2)));
    return _mm_cvtss_f32(v);
}

// The largest of the four in every lane.
inline __m128 broadcast_max(__m128 v) {
    v = _mm_max_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_max_ps(v, _mm_shuffle_ps(v, v, _MM_SHUFFLE(1, 0, 3, 2)));
}

// Each lane's nearest hit so far (bvh_detail::offer_nearest's state).
struct Nearest {
    alignas(32) float best[kPacketSize];  // loaded eight lanes at a time by Avx2Lanes
    std::uint32_t index[kPacketSize];
    ShapePart part[kPacketSize];
    bool found[kPacketSize];
};

// bvh_detail::offer_nearest for the lanes of group g set in `lanes`, given their intervals
// along instance `index`.
inline void offer4(const packet_shapes::Span4& s, std::uint32_t index, int g, unsigned lanes, __m128 tmin, __m128 tmax,
                   Nearest& nearest) {
    using packet_shapes::select;
    // The first crossing beyond t_min, if before t_max.
    const __m128 first = _mm_cmpgt_ps(s.t0, tmin);
    const __m128 t = select(first, s.t0, s.t1);
    const __m128 ok = _mm_and_ps(s.ok, _mm_and_ps(_mm_cmpgt_ps(t, tmin), _mm_cmplt_ps(t, tmax)));
    const __m128 best = _mm_load_ps(&nearest.best[4 * g]);
    unsigned nearer = unsigned(_mm_movemask_ps(_mm_and_ps(ok, _mm_cmplt_ps(t, best)))) & lanes;
    unsigned tie = unsigned(_mm_movemask_ps(_mm_and_ps(ok, _mm_cmpeq_ps(t, best)))) & lanes;
    for (; tie != 0; tie &= tie - 1) {  // equal distances: the lowest index
        const int l = 4 * g + lowest_bit(tie);
        if (nearest.found[l] && index < nearest.index[l]) nearer |= 1u << (l - 4 * g);
    }
    if (nearer == 0) return;
    // One vector store: the next box test loads `best` as a vector, which would stall after
    // scalar stores.
    const __m128 take = lane_mask(nearer);
    _mm_store_ps(&nearest.best[4 * g], select(take, t, best));
    alignas(16) std::int32_t parts[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(parts), select(first, s.part0, s.part1));
    for (; nearer != 0; nearer &= nearer - 1) {
        const int k = lowest_bit(nearer), l = 4 * g + k;
        nearest.index[l] = index;
        nearest.part[l] = ShapePart(parts[k]);
        nearest.found[l] = true;
    }
}

// Offers instance `index` to the lanes in `mask`: four lanes at a time for the shapes that
// bvh_packet_shapes.h has, one lane at a time (bvh_ray.h) for the cone and for an instance scaled
// so far that its directions are rescaled (Instance::rescale). (A scene with meshes has
// an 8-wide top level and no packet walk: bvh_node.h.)
inline void offer_instance(const Instance& inst, std::uint32_t index, const Ray (&rays)[kPacketSize],
                           const PacketRays& r, unsigned mask, float t_min, float t_max, __m128 tmin, __m128 tmax,
                           Nearest& nearest) {
    if (inst.kind == ShapeKind::Cone || inst.rescale) {
        for (unsigned m = mask; m != 0; m &= m - 1) {
            const int l = lowest_bit(m);
            bvh_detail::offer_nearest(bvh_detail::intersect_instance(inst, rays[l]), index, t_min, t_max,
                                      nearest.best[l], nearest.index[l], nearest.part[l], nearest.found[l]);
        }
        return;
    }
    for (int g = 0; g < kGroups; ++g) {
        const unsigned lanes = (mask >> (4 * g)) & 15u;
        if (lanes == 0) continue;
        __m128 o[3], d[3];
        packet_shapes::to_object_space4(inst, r.o[g], r.d[g], o, d);
        switch (inst.kind) {
            case ShapeKind::Sphere: offer4(packet_shapes::sphere4(o, d, int(lanes)), index, g, lanes, tmin, tmax, nearest); break;
            case ShapeKind::Cube: offer4(packet_shapes::cube4(o, d), index, g, lanes, tmin, tmax, nearest); break;
            case ShapeKind::Cylinder: offer4(packet_shapes::cylinder4(o, d), index, g, lanes, tmin, tmax, nearest); break;
            case ShapeKind::Ellipsoid: offer4(packet_shapes::ellipsoid4(o, d, int(lanes)), index, g, lanes, tmin, tmax, nearest); break;
            case ShapeKind::Cone: case ShapeKind::Mesh: break;
        }
    }
}

// The box tests of a node's children for the packet's lanes, four lanes per SSE step: the lanes
// that enter each child (hit), their entry distances (enter_t) and, per child, a vector whose
// smallest value is the nearest entry (key; +inf where no lane enters); and the leaves'
// instances offered to the lanes (offer).
struct SseLanes {
    using Key = __m128;
    const PacketRays& r;
    explicit SseLanes(const PacketRays& rays) : r(rays) {}
    static float smallest(Key k) { return horizontal_min(k); }
    void offer(const Instance& inst, std::uint32_t index, const Ray (&rays)[kPacketSize], unsigned mask, float t_min,
               float t_max, Nearest& nearest) const {
        offer_instance(inst, index, rays, r, mask, t_min, t_max, _mm_set1_ps(t_min), _mm_set1_ps(t_max), nearest);
    }

    template <bool kSameSigns, bool kCommonOrigin>
    void test(const __m128 (&rows)[6], const float* best, __m128 tmin, unsigned (&hit)[4],
              float (&enter_t)[4][kPacketSize], Key (&key)[4]) const {
        __m128 limit[kGroups];
        for (int g = 0; g < kGroups; ++g) limit[g] = _mm_load_ps(&best[4 * g]);
        if constexpr (kSameSigns && kCommonOrigin) {
            // Cull the slots no lane can enter first, then test the lanes on the rest.
            __m128 limit_max = limit[0];
            for (int g = 1; g < kGroups; ++g) limit_max = _mm_max_ps(limit_max, limit[g]);
            const unsigned slots = frustum_slots(r, rows, tmin, broadcast_max(limit_max));
            alignas(16) float row_values[6][4];
            for (int k = 0; k < 6; ++k) _mm_store_ps(row_values[k], rows[k]);
            hit[0] = hit[1] = hit[2] = hit[3] = 0;
            for (unsigned rest = slots; rest != 0; rest &= rest - 1) {
                const int c = lowest_bit(rest);
                __m128 plane[6];
                for (int k = 0; k < 6; ++k) plane[k] = _mm_set1_ps(row_values[k][c]);
                hit[c] = test_child<kSameSigns, kCommonOrigin>(r, plane, limit, tmin, enter_t[c], key[c]);
            }
        } else {
            // All four children without a branch between them: four independent chains.
            hit[0] = test_slot<kSameSigns, kCommonOrigin, 0>(r, rows, limit, tmin, enter_t[0], key[0]);
            hit[1] = test_slot<kSameSigns, kCommonOrigin, 1>(r, rows, limit, tmin, enter_t[1], key[1]);
            hit[2] = test_slot<kSameSigns, kCommonOrigin, 2>(r, rows, limit, tmin, enter_t[2], key[2]);
            hit[3] = test_slot<kSameSigns, kCommonOrigin, 3>(r, rows, limit, tmin, enter_t[3], key[3]);
        }
    }
};

#ifdef WHITTED_BVH_AVX2
// The same tests, and the leaves' shapes (shapes/unit_shape_math8.h), eight lanes per AVX2 step:
// the same operations lane by lane (no fused multiply-add), so the same masks, entry distances
// and hits. Its functions carry GCC's target attribute; the walk that uses it is compiled into a
// function with the same attribute and [[gnu::flatten]] (dispatch_avx2), run only where the CPU
// has AVX2.
struct Avx2Lanes {
    static constexpr int kOctets = kPacketSize / 8;
    static_assert(kPacketSize % 8 == 0);
    using Key = float;
    const PacketRays& r;
    __m256 o[kOctets][3], d[kOctets][3], inv[3][kOctets];
    [[gnu::target("avx2")]] explicit Avx2Lanes(const PacketRays& rays) : r(rays) {
        for (int h = 0; h < kOctets; ++h)
            for (int a = 0; a < 3; ++a) {
                o[h][a] = _mm256_set_m128(rays.o[2 * h + 1][a], rays.o[2 * h][a]);
                d[h][a] = _mm256_set_m128(rays.d[2 * h + 1][a], rays.d[2 * h][a]);
                inv[a][h] = _mm256_set_m128(rays.inv[a][2 * h + 1], rays.inv[a][2 * h]);
            }
    }
    static float smallest(Key k) { return k; }

    // All-ones in the lanes whose bit is set.
    [[gnu::target("avx2")]] static __m256 lane_mask8(unsigned bits) {
        const __m256i bit = _mm256_setr_epi32(1, 2, 4, 8, 16, 32, 64, 128);
        return _mm256_castsi256_ps(_mm256_cmpeq_epi32(_mm256_and_si256(_mm256_set1_epi32(int(bits)), bit), bit));
    }

    // offer4 for the eight lanes of octet h.
    [[gnu::target("avx2")]] static void offer8(const packet_shapes::Span8& s, std::uint32_t index, int h,
                                               unsigned lanes, __m256 tmin, __m256 tmax, Nearest& nearest) {
        using packet_shapes::select;
        const __m256 first = _mm256_cmp_ps(s.t0, tmin, _CMP_GT_OS);
        const __m256 t = select(first, s.t0, s.t1);
        const __m256 ok = _mm256_and_ps(
            s.ok, _mm256_and_ps(_mm256_cmp_ps(t, tmin, _CMP_GT_OS), _mm256_cmp_ps(t, tmax, _CMP_LT_OS)));
        const __m256 best = _mm256_load_ps(&nearest.best[8 * h]);
        unsigned nearer = unsigned(_mm256_movemask_ps(_mm256_and_ps(ok, _mm256_cmp_ps(t, best, _CMP_LT_OS)))) & lanes;
        unsigned tie = unsigned(_mm256_movemask_ps(_mm256_and_ps(ok, _mm256_cmp_ps(t, best, _CMP_EQ_OQ)))) & lanes;
        for (; tie != 0; tie &= tie - 1) {  // equal distances: the lowest index
            const int l = 8 * h + lowest_bit(tie);
            if (nearest.found[l] && index < nearest.index[l]) nearer |= 1u << (l - 8 * h);
        }
        if (nearer == 0) return;
        _mm256_store_ps(&nearest.best[8 * h], select(lane_mask8(nearer), t, best));
        alignas(32) std::int32_t parts[8];
        _mm256_store_si256(reinterpret_cast<__m256i*>(parts), select(first, s.part0, s.part1));
        for (; nearer != 0; nearer &= nearer - 1) {
            const int k = lowest_bit(nearer), l = 8 * h + k;
            nearest.index[l] = index;
            nearest.part[l] = ShapePart(parts[k]);
            nearest.found[l] = true;
        }
    }

    // offer_instance, eight lanes at a time.
    [[gnu::target("avx2")]] void offer(const Instance& inst, std::uint32_t index, const Ray (&rays)[kPacketSize],
                                       unsigned mask, float t_min, float t_max, Nearest& nearest) const {
        if (inst.kind == ShapeKind::Cone || inst.rescale) {
            offer_instance(inst, index, rays, r, mask, t_min, t_max, _mm_set1_ps(t_min), _mm_set1_ps(t_max), nearest);
            return;
        }
        const __m256 tmin = _mm256_set1_ps(t_min), tmax = _mm256_set1_ps(t_max);
        for (int h = 0; h < kOctets; ++h) {
            const unsigned lanes = (mask >> (8 * h)) & 255u;
            if (lanes == 0) continue;
            __m256 oo[3], od[3];
            packet_shapes::to_object_space8(inst, o[h], d[h], oo, od);
            switch (inst.kind) {
                case ShapeKind::Sphere: offer8(packet_shapes::sphere8(oo, od, int(lanes)), index, h, lanes, tmin, tmax, nearest); break;
                case ShapeKind::Cube: offer8(packet_shapes::cube8(oo, od), index, h, lanes, tmin, tmax, nearest); break;
                case ShapeKind::Cylinder: offer8(packet_shapes::cylinder8(oo, od), index, h, lanes, tmin, tmax, nearest); break;
                case ShapeKind::Ellipsoid: offer8(packet_shapes::ellipsoid8(oo, od, int(lanes)), index, h, lanes, tmin, tmax, nearest); break;
                case ShapeKind::Cone: case ShapeKind::Mesh: break;
            }
        }
    }

    template <bool kSameSigns, bool kCommonOrigin>
    [[gnu::target("avx2")]] unsigned test_child8(const float (&plane)[6], const __m256 (&limit)[kOctets], __m256 tmin,
                                                 float* enter_out, Key& key) const {
        const __m256 inf = _mm256_set1_ps(std::numeric_limits<float>::infinity());
        unsigned hit = 0;
        __m256 k8 = inf;
        for (int h = 0; h < kOctets; ++h) {
            __m256 t_near[3], t_far[3];
            for (int a = 0; a < 3; ++a) {
                const __m256 p0 = _mm256_set1_ps(plane[a]), p1 = _mm256_set1_ps(plane[3 + a]);
                const __m256 rel0 = kCommonOrigin ? p0 : _mm256_sub_ps(p0, o[h][a]);
                const __m256 rel1 = kCommonOrigin ? p1 : _mm256_sub_ps(p1, o[h][a]);
                const __m256 t0 = _mm256_mul_ps(rel0, inv[a][h]);
                const __m256 t1 = _mm256_mul_ps(rel1, inv[a][h]);
                t_near[a] = kSameSigns ? t0 : _mm256_min_ps(t0, t1);
                t_far[a] = kSameSigns ? t1 : _mm256_max_ps(t0, t1);
            }
            // test_child's order of operands, so that NaN (an inactive lane) spreads as there.
            const __m256 enter = _mm256_max_ps(_mm256_max_ps(tmin, t_near[0]), _mm256_max_ps(t_near[1], t_near[2]));
            const __m256 leave = _mm256_min_ps(_mm256_min_ps(limit[h], t_far[0]), _mm256_min_ps(t_far[1], t_far[2]));
            const __m256 in = _mm256_cmp_ps(enter, leave, _CMP_LE_OS);
            hit |= unsigned(_mm256_movemask_ps(in)) << (8 * h);
            _mm256_store_ps(enter_out + 8 * h, enter);
            k8 = _mm256_min_ps(k8, _mm256_max_ps(enter, _mm256_andnot_ps(in, inf)));
        }
        const __m128 k4 = _mm_min_ps(_mm256_castps256_ps128(k8), _mm256_extractf128_ps(k8, 1));
        key = horizontal_min(k4);
        return hit;
    }

    template <bool kSameSigns, bool kCommonOrigin>
    [[gnu::target("avx2")]] void test(const __m128 (&rows)[6], const float* best, __m128 tmin, unsigned (&hit)[4],
                                      float (&enter_t)[4][kPacketSize], Key (&key)[4]) const {
        __m256 limit[kOctets];
        for (int h = 0; h < kOctets; ++h) limit[h] = _mm256_load_ps(&best[8 * h]);
        const __m256 tmin8 = _mm256_set_m128(tmin, tmin);
        unsigned slots = 15;
        if constexpr (kSameSigns && kCommonOrigin) {
            __m256 m = limit[0];
            for (int h = 1; h < kOctets; ++h) m = _mm256_max_ps(m, limit[h]);
            const __m128 limit_max = _mm_max_ps(_mm256_castps256_ps128(m), _mm256_extractf128_ps(m, 1));
            slots = frustum_slots(r, rows, tmin, broadcast_max(limit_max));
        }
        alignas(16) float row_values[6][4];
        for (int k = 0; k < 6; ++k) _mm_store_ps(row_values[k], rows[k]);
        hit[0] = hit[1] = hit[2] = hit[3] = 0;
        for (unsigned rest = slots; rest != 0; rest &= rest - 1) {
            const int c = lowest_bit(rest);
            const float plane[6] = {row_values[0][c], row_values[1][c], row_values[2][c],
                                    row_values[3][c], row_values[4][c], row_values[5][c]};
            hit[c] = test_child8<kSameSigns, kCommonOrigin>(plane, limit, tmin8, enter_t[c], key[c]);
        }
    }
};
#endif

// A box waiting on the stack, with the lanes that entered it and their entry distances (a lane
// whose nearest hit has meanwhile come closer than its entry is dropped when it is popped).
struct alignas(16) Entry {
    float t[kPacketSize];
    std::uint32_t ref;
    unsigned mask;
};

template <bool kSameSigns, bool kCommonOrigin, class Lanes>
unsigned traverse(const Bvh& bvh, const std::vector<Instance>& instances, const Ray (&rays)[kPacketSize],
                  const PacketRays& r, const Lanes& lanes, unsigned active, float t_min, float t_max,
                  Hit (&hits)[kPacketSize]) {
    const Bvh4Node* nodes = bvh.nodes.data();
    const Instance* inst = instances.data();
    const __m128 tmin = _mm_set1_ps(t_min);
    Nearest nearest;
    float* best = nearest.best;
    for (int l = 0; l < kPacketSize; ++l) {
        best[l] = t_max;
        nearest.index[l] = 0;
        nearest.part[l] = kPartSide;
        nearest.found[l] = false;
    }

    Entry stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;    // the root (an inner node)
    unsigned mask = active;   // the lanes that entered ref's box
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            const Bvh4Node& n = nodes[ref];
            alignas(32) float enter_t[4][kPacketSize];
            typename Lanes::Key key[4];
            unsigned hit[4];
            __m128 rows[6];
            load_planes<kSameSigns, kCommonOrigin>(n, r, rows);
            lanes.template test<kSameSigns, kCommonOrigin>(rows, best, tmin, hit, enter_t, key);
            if (!kSameSigns) {
                // Unused slots have lo = +inf > hi = -inf, which min/max made infinite boxes.
                const int used = _mm_movemask_ps(_mm_cmple_ps(_mm_load_ps(n.box[0]), _mm_load_ps(n.box[3])));
                for (int c = 0; c < 4; ++c) hit[c] &= 0u - unsigned((used >> c) & 1);
            }
            const unsigned children = unsigned(hit[0] != 0) | unsigned(hit[1] != 0) << 1 |
                                      unsigned(hit[2] != 0) << 2 | unsigned(hit[3] != 0) << 3;
            if (children != 0) {
                int c = lowest_bit(children);
                if ((children & (children - 1)) == 0) {  // one child: go straight on
                    ref = n.child[c];
                    mask = hit[c];
                    continue;
                }
                // Several: push all but the nearest (by the smallest entry of its lanes),
                // farthest first.
                struct Candidate { float key; int slot; } cand[4];
                int count = 0;
                for (unsigned rest = children; rest != 0; rest &= rest - 1) {
                    c = lowest_bit(rest);
                    const Candidate e{Lanes::smallest(key[c]), c};
                    int k = count++;
                    while (k > 0 && cand[k - 1].key < e.key) {
                        cand[k] = cand[k - 1];
                        --k;
                    }
                    cand[k] = e;
                }
                for (int k = 0; k < count - 1; ++k) {
                    Entry& e = stack[top++];
                    const int slot = cand[k].slot;
                    for (int g = 0; g < kGroups; ++g) _mm_store_ps(&e.t[4 * g], _mm_load_ps(&enter_t[slot][4 * g]));
                    e.ref = n.child[slot];
                    e.mask = hit[slot];
                }
                ref = n.child[cand[count - 1].slot];
                mask = hit[cand[count - 1].slot];
                continue;
            }
        } else {
            const std::uint32_t first = Bvh4Node::leaf_first(ref), end = first + Bvh4Node::leaf_count(ref);
            for (std::uint32_t i = first; i < end; ++i)
                lanes.offer(inst[i], i, rays, mask, t_min, t_max, nearest);
        }
        // Pop, dropping the lanes whose nearest hit is now closer than their entry into the box.
        for (;;) {
            if (top == 0) {
                unsigned result = 0;
                for (int l = 0; l < kPacketSize; ++l)
                    if (nearest.found[l]) {
                        hits[l] = Hit{best[l], nearest.index[l], nearest.part[l]};
                        result |= 1u << l;
                    }
                return result;
            }
            const Entry& e = stack[--top];
            unsigned still = 0;
            for (int g = 0; g < kGroups; ++g)
                still |= unsigned(_mm_movemask_ps(_mm_cmple_ps(_mm_load_ps(&e.t[4 * g]), _mm_load_ps(&best[4 * g]))))
                         << (4 * g);
            still &= e.mask;
            if (still != 0) {
                ref = e.ref;
                mask = still;
                break;
            }
        }
    }
}

// The walk for the packet's kind of rays (one origin? one sign per axis?).
template <class Lanes>
unsigned dispatch_with(const Bvh& bvh, const std::vector<Instance>& instances, const Ray (&rays)[kPacketSize],
                       const PacketRays& r, const Lanes& lanes, unsigned active, float t_min, float t_max,
                       Hit (&hits)[kPacketSize]) {
    if (r.common_origin)
        return r.same_signs ? traverse<true, true>(bvh, instances, rays, r, lanes, active, t_min, t_max, hits)
                            : traverse<false, true>(bvh, instances, rays, r, lanes, active, t_min, t_max, hits);
    return r.same_signs ? traverse<true, false>(bvh, instances, rays, r, lanes, active, t_min, t_max, hits)
                        : traverse<false, false>(bvh, instances, rays, r, lanes, active, t_min, t_max, hits);
}

#ifdef WHITTED_BVH_AVX2
[[gnu::target("avx2"), gnu::flatten]] unsigned dispatch_avx2(const Bvh& bvh, const std::vector<Instance>& instances,
                                                             const Ray (&rays)[kPacketSize], const PacketRays& r,
                                                             unsigned active, float t_min, float t_max,
                                                             Hit (&hits)[kPacketSize]) {
    return dispatch_with(bvh, instances, rays, r, Avx2Lanes(r), active, t_min, t_max, hits);
}
#endif

unsigned dispatch(const Bvh& bvh, const std::vector<Instance>& instances, const Ray (&rays)[kPacketSize],
                  const PacketRays& r, unsigned active, float t_min, float t_max, Hit (&hits)[kPacketSize]) {
#ifdef WHITTED_BVH_AVX2
    // Where the CPU has AVX2 (the switch the walk tests turn): eight lanes per box test.
    if (mesh_detail::use_avx2) return dispatch_avx2(bvh, instances, rays, r, active, t_min, t_max, hits);
#endif
    return dispatch_with(bvh, instances, rays, r, SseLanes(r), active, t_min, t_max, hits);
}

}  // namespace

unsigned intersect_nearest_packet(const Bvh& bvh, const std::vector<Instance>& instances,
                                  const Ray (&rays)[kPacketSize], unsigned active, float t_min, float t_max,
                                  Hit (&hits)[kPacketSize], const std::vector<MeshBvh>* meshes) {
    active &= ~0u >> (32 - kPacketSize);
    if (bvh.empty() || active == 0) return 0;
    // A scene with meshes: its top level is 8-wide (bvh_node.h), walked one ray at a time.
    if (bvh.nodes.empty() || bvh_detail::has_meshes(meshes))
        return one_by_one(bvh, instances, rays, active, t_min, t_max, hits, meshes);
    return dispatch(bvh, instances, rays, PacketRays(rays, active), active, t_min, t_max, hits);
}

#else

// Without SSE: one ray at a time, which is exactly the single-ray query.
unsigned intersect_nearest_packet(const Bvh& bvh, const std::vector<Instance>& instances,
                                  const Ray (&rays)[kPacketSize], unsigned active, float t_min, float t_max,
                                  Hit (&hits)[kPacketSize], const std::vector<MeshBvh>* meshes) {
    return one_by_one(bvh, instances, rays, active, t_min, t_max, hits, meshes);
}

#endif

}  // namespace whitted
