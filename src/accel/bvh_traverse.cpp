// Traversal of the 4-wide BVH: one SSE test gives a ray's entry distance into all four child
// boxes, the hit children are visited nearest first (nearest-hit queries) with a small fixed
// stack, and a nearer hit found meanwhile prunes what is left on the stack. Shadow queries
// visit in any order and stop at the first opaque blocker.
#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__) || defined(_M_X64)
#include <emmintrin.h>
#define WHITTED_BVH_SSE 1
#endif

#include "accel/bvh.h"
#include "accel/bvh_ray.h"

namespace whitted {
namespace {

using bvh_detail::intersect_instance;
using bvh_detail::kStackSize;
constexpr float kInf = std::numeric_limits<float>::infinity();

// The ray as the box test wants it: origin, reciprocal direction (bvh_ray.h) and which box row
// is the near plane per axis.
struct BoxRay {
    float o[3], inv[3];
    int near_row[3], far_row[3];
    explicit BoxRay(const Ray& r) {
        for (int a = 0; a < 3; ++a) {
            o[a] = r.origin[a];
            inv[a] = bvh_detail::safe_reciprocal(r.direction[a]);
            const bool neg = std::signbit(inv[a]);
            near_row[a] = neg ? 3 + a : a;
            far_row[a] = neg ? a : 3 + a;
        }
    }
};

// Entry distances of the ray into the node's four boxes (t_near[i]); returns the mask of the
// boxes entered within (t_min, t_max). Near/far planes are chosen by the direction's sign, so no
// min/max per axis is needed.
#ifdef WHITTED_BVH_SSE
struct BoxTester {
    __m128 o[3], inv[3];
    const BoxRay& r;
    explicit BoxTester(const BoxRay& ray) : r(ray) {
        for (int a = 0; a < 3; ++a) {
            o[a] = _mm_set1_ps(ray.o[a]);
            inv[a] = _mm_set1_ps(ray.inv[a]);
        }
    }
    int test(const Bvh4Node& n, float t_min, float t_max, float t_near[4]) const {
        const __m128 nx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.box[r.near_row[0]]), o[0]), inv[0]);
        const __m128 ny = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.box[r.near_row[1]]), o[1]), inv[1]);
        const __m128 nz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.box[r.near_row[2]]), o[2]), inv[2]);
        const __m128 fx = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.box[r.far_row[0]]), o[0]), inv[0]);
        const __m128 fy = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.box[r.far_row[1]]), o[1]), inv[1]);
        const __m128 fz = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(n.box[r.far_row[2]]), o[2]), inv[2]);
        const __m128 enter = _mm_max_ps(_mm_max_ps(nx, ny), _mm_max_ps(nz, _mm_set1_ps(t_min)));
        const __m128 leave = _mm_min_ps(_mm_min_ps(fx, fy), _mm_min_ps(fz, _mm_set1_ps(t_max)));
        _mm_storeu_ps(t_near, enter);
        return _mm_movemask_ps(_mm_cmple_ps(enter, leave));
    }
};
#else
struct BoxTester {
    const BoxRay& r;
    explicit BoxTester(const BoxRay& ray) : r(ray) {}
    int test(const Bvh4Node& n, float t_min, float t_max, float t_near[4]) const {
        int mask = 0;
        for (int s = 0; s < 4; ++s) {
            float enter = t_min, leave = t_max;
            for (int a = 0; a < 3; ++a) {
                enter = std::max((n.box[r.near_row[a]][s] - r.o[a]) * r.inv[a], enter);
                leave = std::min((n.box[r.far_row[a]][s] - r.o[a]) * r.inv[a], leave);
            }
            t_near[s] = enter;
            mask |= int(enter <= leave) << s;
        }
        return mask;
    }
};
#endif

inline int lowest_bit(int mask) { return __builtin_ctz(unsigned(mask)); }

struct StackEntry {
    std::uint32_t ref;
    float t;  // entry distance of its box, to skip it once a nearer hit is known
};

}  // namespace

bool intersect_nearest(const Bvh& bvh, const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                       Hit& hit) {
    if (bvh.nodes.empty()) return false;
    const BoxRay box_ray(ray);
    const BoxTester tester(box_ray);
    const Bvh4Node* nodes = bvh.nodes.data();
    const Instance* inst = instances.data();
    bool found = false;
    float best = t_max;
    std::uint32_t best_index = 0;
    ShapePart best_part = kPartSide;

    StackEntry stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;  // the root (an inner node)
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            float tn[4];
            int mask = tester.test(nodes[ref], t_min, best, tn);
            const Bvh4Node& n = nodes[ref];
            if (mask != 0) {
                int i = lowest_bit(mask);
                mask &= mask - 1;
                if (mask == 0) {  // one child: go straight on
                    ref = n.child[i];
                    continue;
                }
                const int j = lowest_bit(mask);
                mask &= mask - 1;
                if (mask == 0) {  // two: the common case, no sorting loop
                    const bool swap = tn[j] < tn[i];
                    const int near = swap ? j : i, far = swap ? i : j;
                    stack[top++] = {n.child[far], tn[far]};
                    ref = n.child[near];
                    continue;
                }
                mask |= 1 << j;
                // Several: push all but the nearest, farthest first (insertion by distance).
                StackEntry hits[4];
                int count = 0;
                hits[count++] = {n.child[i], tn[i]};
                do {
                    i = lowest_bit(mask);
                    mask &= mask - 1;
                    StackEntry e{n.child[i], tn[i]};
                    int k = count++;
                    while (k > 0 && hits[k - 1].t < e.t) { hits[k] = hits[k - 1]; --k; }
                    hits[k] = e;
                } while (mask != 0);
                for (int k = 0; k < count - 1; ++k) stack[top++] = hits[k];
                ref = hits[count - 1].ref;
                continue;
            }
        } else {
            const std::uint32_t first = Bvh4Node::leaf_first(ref), end = first + Bvh4Node::leaf_count(ref);
            for (std::uint32_t i = first; i < end; ++i)
                bvh_detail::offer_nearest(intersect_instance(inst[i], ray), i, t_min, t_max, best, best_index, best_part,
                                          found);
        }
        // Pop, skipping boxes that a nearer hit found meanwhile has made irrelevant.
        for (;;) {
            if (top == 0) {
                if (found) hit = {best, best_index, best_part};
                return found;
            }
            const StackEntry& e = stack[--top];
            if (e.t <= best) {
                ref = e.ref;
                break;
            }
        }
    }
}

bool intersect_nearest_brute_force(const std::vector<Instance>& instances, const Ray& ray, float t_min, float t_max,
                                   Hit& hit) {
    bool found = false;
    float best = t_max;
    for (std::uint32_t i = 0; i < instances.size(); ++i) {
        float t;
        ShapePart part;
        if (nearest_hit(intersect_unit_shape(instances[i].kind, to_object_space(instances[i], ray)), t_min, best, t, part)) {
            best = t;
            hit = {t, i, part};
            found = true;
        }
    }
    return found;
}

namespace {

// Accumulates one instance into a shadow query; returns false once the light is blocked.
inline bool shadow_instance(const Instance& inst, const std::vector<Material>& materials, const Ray& ray, float t_min,
                            float t_max, glm::vec3& through) {
    const auto s = intersect_instance(inst, ray);
    if (s.count == 0) return true;
    const int crossings = (s.t[0] > t_min && s.t[0] < t_max) + (s.t[1] > t_min && s.t[1] < t_max);
    if (crossings == 0) return true;
    const Material& m = materials[inst.material];
    if (!m.is_transparent()) {
        through = glm::vec3(0.0f);
        return false;  // an opaque blocker: nothing else matters
    }
    through *= crossings == 2 ? m.transparent * m.transparent : m.transparent;
    return true;
}

}  // namespace

glm::vec3 transmittance(const Bvh& bvh, const std::vector<Instance>& instances, const std::vector<Material>& materials,
                        const Ray& ray, float t_min, float t_max) {
    glm::vec3 through(1.0f);
    if (bvh.nodes.empty()) return through;
    const BoxRay box_ray(ray);
    const BoxTester tester(box_ray);
    const Bvh4Node* nodes = bvh.nodes.data();
    const Instance* inst = instances.data();

    std::uint32_t stack[kStackSize];
    int top = 0;
    std::uint32_t ref = 0;
    for (;;) {
        if (!Bvh4Node::is_leaf(ref)) {
            float tn[4];
            const Bvh4Node& n = nodes[ref];
            int mask = tester.test(n, t_min, t_max, tn);
            if (mask != 0) {
                // Any order will do: go into the first, push the others.
                ref = n.child[lowest_bit(mask)];
                mask &= mask - 1;
                while (mask != 0) {
                    stack[top++] = n.child[lowest_bit(mask)];
                    mask &= mask - 1;
                }
                continue;
            }
        } else {
            const std::uint32_t first = Bvh4Node::leaf_first(ref), end = first + Bvh4Node::leaf_count(ref);
            for (std::uint32_t i = first; i < end; ++i)
                if (!shadow_instance(inst[i], materials, ray, t_min, t_max, through)) return through;
        }
        if (top == 0) return through;
        ref = stack[--top];
    }
}

glm::vec3 transmittance_brute_force(const std::vector<Instance>& instances, const std::vector<Material>& materials,
                                    const Ray& ray, float t_min, float t_max) {
    glm::vec3 through(1.0f);
    for (const Instance& inst : instances)
        if (!shadow_instance(inst, materials, ray, t_min, t_max, through)) break;
    return through;
}

}  // namespace whitted
