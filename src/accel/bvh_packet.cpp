// Packet traversal of the 4-wide BVH. The SIMD lanes are rays: at a node, each of the four child
// boxes is tested against all the packet's rays at once (two SSE registers of four rays), and a
// child is visited if any lane still wanting it enters it no farther than that lane's nearest hit
// so far. Every lane keeps its own nearest hit, and its box test is the single-ray test
// (bvh_traverse.cpp) evaluated in another lane, so a lane visits every box its single ray
// would have to visit to find its answer, and the shared leaf code (bvh_ray.h) picks the same
// hit from what it visits. The extra boxes a lane is taken into only cost time.
#include "accel/bvh_packet.h"

#include <limits>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define WHITTED_BVH_SSE 1
#endif

#include "accel/bvh_ray.h"

namespace whitted {

#ifdef WHITTED_BVH_SSE
namespace {

using bvh_detail::kStackSize;
constexpr int kGroups = kPacketSize / 4;  // SSE registers per packet quantity
static_assert(kPacketSize % 4 == 0 && kPacketSize <= 32);

// All-ones in the lanes whose bit is set: turns four bits of a lane mask into an SSE mask.
struct LaneMasks {
    alignas(16) std::uint32_t m[16][4];
    constexpr LaneMasks() : m{} {
        for (int b = 0; b < 16; ++b)
            for (int l = 0; l < 4; ++l) m[b][l] = (b >> l & 1) ? 0xffffffffu : 0u;
    }
};
constexpr LaneMasks kLaneMasks;
inline __m128 lane_mask(unsigned bits) { return _mm_load_ps(reinterpret_cast<const float*>(kLaneMasks.m[bits & 15])); }

inline int lowest_bit(unsigned mask) { return __builtin_ctz(mask); }

// A box waiting on the stack, with the lanes that entered it and their entry distances (a lane
// whose nearest hit has meanwhile come closer than its entry is dropped when it is popped).
struct alignas(16) Entry {
    float t[kPacketSize];
    std::uint32_t ref;
    unsigned mask;
};

// A child box that lanes entered, for ordering: key = the smallest entry distance among them.
struct Candidate {
    float key;
    int slot;
    unsigned mask;
};

}  // namespace

unsigned intersect_nearest_packet(const Bvh& bvh, const std::vector<Instance>& instances,
                                  const Ray (&rays)[kPacketSize], unsigned active, float t_min, float t_max,
                                  Hit (&hits)[kPacketSize]) {
    active &= (kPacketSize == 32 ? ~0u : (1u << kPacketSize) - 1);
    if (bvh.nodes.empty() || active == 0) return 0;
    const Bvh4Node* nodes = bvh.nodes.data();
    const Instance* inst = instances.data();

    // The rays' origins and reciprocal directions, structure of arrays. Inactive lanes get a
    // harmless ray; their mask bits are never set, so they are never visited.
    __m128 org[3][kGroups], inv[3][kGroups];
    {
        alignas(16) float o[3][kPacketSize], r[3][kPacketSize];
        for (int l = 0; l < kPacketSize; ++l) {
            const bool on = (active >> l) & 1;
            for (int a = 0; a < 3; ++a) {
                o[a][l] = on ? rays[l].origin[a] : 0.0f;
                r[a][l] = on ? bvh_detail::safe_reciprocal(rays[l].direction[a]) : 1.0f;
            }
        }
        for (int a = 0; a < 3; ++a)
            for (int g = 0; g < kGroups; ++g) {
                org[a][g] = _mm_load_ps(&o[a][4 * g]);
                inv[a][g] = _mm_load_ps(&r[a][4 * g]);
            }
    }
    const __m128 tmin = _mm_set1_ps(t_min);
    const __m128 inf = _mm_set1_ps(std::numeric_limits<float>::infinity());

    // Each lane's nearest hit so far (bvh_detail::offer_nearest's state).
    alignas(16) float best[kPacketSize];
    std::uint32_t best_index[kPacketSize];
    ShapePart best_part[kPacketSize];
    bool found[kPacketSize];
    for (int l = 0; l < kPacketSize; ++l) {
        best[l] = t_max;
        best_index[l] = 0;
        best_part[l] = kPartSide;
        found[l] = false;
    }

    Entry stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;    // the root (an inner node)
    unsigned mask = active;   // the lanes that entered ref's box
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            const Bvh4Node& n = nodes[ref];
            __m128 near_limit[kGroups];
            for (int g = 0; g < kGroups; ++g) near_limit[g] = _mm_load_ps(&best[4 * g]);
            // Unused slots have lo = +inf > hi = -inf; the min/max below would turn them into
            // boxes of infinite extent, so they are skipped here instead.
            const int used = _mm_movemask_ps(_mm_cmple_ps(_mm_load_ps(n.box[0]), _mm_load_ps(n.box[3])));
            alignas(16) float enter_t[4][kPacketSize];
            Candidate cand[4];
            int count = 0;
            for (int c = 0; c < 4; ++c) {
                if (!((used >> c) & 1)) continue;
                __m128 lo[3], hi[3];
                for (int a = 0; a < 3; ++a) {
                    lo[a] = _mm_set1_ps(n.box[a][c]);
                    hi[a] = _mm_set1_ps(n.box[3 + a][c]);
                }
                unsigned hit = 0;
                __m128 key = inf;
                for (int g = 0; g < kGroups; ++g) {
                    // Per lane the near plane is the nearer of the two: for a finite box this
                    // is exactly the single-ray test's sign-selected plane.
                    __m128 enter = tmin, leave = near_limit[g];
                    for (int a = 0; a < 3; ++a) {
                        const __m128 t0 = _mm_mul_ps(_mm_sub_ps(lo[a], org[a][g]), inv[a][g]);
                        const __m128 t1 = _mm_mul_ps(_mm_sub_ps(hi[a], org[a][g]), inv[a][g]);
                        enter = _mm_max_ps(enter, _mm_min_ps(t0, t1));
                        leave = _mm_min_ps(leave, _mm_max_ps(t0, t1));
                    }
                    const __m128 in = _mm_and_ps(_mm_cmple_ps(enter, leave), lane_mask(mask >> (4 * g)));
                    hit |= unsigned(_mm_movemask_ps(in)) << (4 * g);
                    _mm_store_ps(&enter_t[c][4 * g], enter);
                    key = _mm_min_ps(key, _mm_or_ps(_mm_and_ps(in, enter), _mm_andnot_ps(in, inf)));
                }
                if (hit == 0) continue;
                key = _mm_min_ps(key, _mm_shuffle_ps(key, key, _MM_SHUFFLE(2, 3, 0, 1)));
                key = _mm_min_ps(key, _mm_shuffle_ps(key, key, _MM_SHUFFLE(1, 0, 3, 2)));
                // Insert, farthest first.
                const Candidate e{_mm_cvtss_f32(key), c, hit};
                int k = count++;
                while (k > 0 && cand[k - 1].key < e.key) {
                    cand[k] = cand[k - 1];
                    --k;
                }
                cand[k] = e;
            }
            if (count != 0) {
                // Push all but the nearest, go on with the nearest.
                for (int k = 0; k < count - 1; ++k) {
                    Entry& e = stack[top++];
                    for (int g = 0; g < kGroups; ++g)
                        _mm_store_ps(&e.t[4 * g], _mm_load_ps(&enter_t[cand[k].slot][4 * g]));
                    e.ref = n.child[cand[k].slot];
                    e.mask = cand[k].mask;
                }
                ref = n.child[cand[count - 1].slot];
                mask = cand[count - 1].mask;
                continue;
            }
        } else {
            const std::uint32_t first = Bvh4Node::leaf_first(ref), end = first + Bvh4Node::leaf_count(ref);
            for (std::uint32_t i = first; i < end; ++i)
                for (unsigned m = mask; m != 0; m &= m - 1) {
                    const int l = lowest_bit(m);
                    bvh_detail::offer_nearest(bvh_detail::intersect_instance(inst[i], rays[l]), i, t_min, t_max,
                                              best[l], best_index[l], best_part[l], found[l]);
                }
        }
        // Pop, dropping the lanes whose nearest hit is now closer than their entry into the box.
        for (;;) {
            if (top == 0) {
                unsigned result = 0;
                for (int l = 0; l < kPacketSize; ++l)
                    if (found[l]) {
                        hits[l] = {best[l], best_index[l], best_part[l]};
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

#else

// Without SSE: one ray at a time, which is exactly the single-ray query.
unsigned intersect_nearest_packet(const Bvh& bvh, const std::vector<Instance>& instances,
                                  const Ray (&rays)[kPacketSize], unsigned active, float t_min, float t_max,
                                  Hit (&hits)[kPacketSize]) {
    unsigned result = 0;
    for (int l = 0; l < kPacketSize; ++l)
        if (((active >> l) & 1) && intersect_nearest(bvh, instances, rays[l], t_min, t_max, hits[l])) result |= 1u << l;
    return result;
}

#endif

}  // namespace whitted
