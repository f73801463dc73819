// Binned surface-area-heuristic build (Wald 2007) of a binary tree: per node, centroids are
// binned along the widest centroid axis and the cheapest of the bin boundaries is chosen.
// O(n log n) time, O(n) memory. The binary tree is then collapsed into the 4- or 8-wide node
// arrays that traversal reads (each wide node adopts the largest-area grandchildren until it has
// four or eight children), and the instances are reordered to leaf order.
#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <functional>
#include <stdexcept>

#include "accel/bvh.h"
#include "accel/bvh_box_test_avx2.h"
#include "accel/instance_geometry.h"
#include "base/big_vector.h"
#include "base/parallel_for.h"

namespace whitted {
namespace {

constexpr int kBins = 16;
constexpr std::uint32_t kMaxInstanceLeaf = 8;  // <= Bvh4Node::kMaxLeafSize
// SAH cost of a traversal step relative to one instance test (an object-space transform plus a
// quadric). A 4-wide box test is cheaper than that while the tree sits in the caches; once the
// node array is far larger than them (hundreds of thousands of instances) every step is mostly
// a cache miss, and bigger leaves (fewer, shallower nodes) win. Measured on the bench scenes:
// 0.5 is best for 1k instances (2.0 is 20% slower there), 2.0 is 8% faster for 1M.
constexpr float kTraversalCostCached = 0.5f;
constexpr float kTraversalCostLarge = 2.0f;
constexpr std::uint32_t kLargeScene = 200000;
// Below this depth SAH splits are replaced by median splits, which bounds the depth (and so
// the traversal stack, see bvh_traverse.cpp) even for pathological inputs.
constexpr std::uint32_t kSahDepthLimit = 64;
// Below this many instances the build stays on one thread.
constexpr std::uint32_t kParallelBuildMin = 50000;

// Four floats in one SIMD register (GCC/Clang vector extension: SSE on x86, NEON on ARM).
typedef float V4 __attribute__((vector_size(16)));
inline V4 vmin(V4 a, V4 b) { return a < b ? a : b; }
inline V4 vmax(V4 a, V4 b) { return a > b ? a : b; }
constexpr float kInf = std::numeric_limits<float>::infinity();

// lo.w carries the instance index (bit pattern), hi.w is unused; the centre is (lo + hi) / 2,
// kept doubled as lo + hi.
struct PrimRef {
    V4 lo, hi;
    std::uint32_t index() const {
        std::uint32_t i;
        float f = lo[3];
        std::memcpy(&i, &f, 4);
        return i;
    }
};

struct Box {
    V4 lo = {kInf, kInf, kInf, kInf}, hi = {-kInf, -kInf, -kInf, -kInf};
    void grow(V4 l, V4 h) { lo = vmin(lo, l); hi = vmax(hi, h); }
    void grow(const Box& b) { grow(b.lo, b.hi); }
    float area() const {
        if (!(lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2])) return 0.0f;
        const V4 e = hi - lo;
        return 2.0f * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0]);
    }
    Bounds bounds() const { return Bounds{{lo[0], lo[1], lo[2]}, {hi[0], hi[1], hi[2]}}; }
};

struct BinNode {
    Bounds box;
    std::uint32_t first = 0;   // leaf: first instance (in refs order); inner: left child
    std::uint32_t second = 0;  // inner: right child
    std::uint32_t count = 0;   // leaf: instances (> 0); inner: 0
};

struct Task {
    std::uint32_t begin, end;
    std::uint32_t node;  // index of the BinNode to fill
    std::uint32_t depth;
    Box box, centres;  // of refs [begin, end) (centres doubled), when `known`
    bool known;
};

void bounds_of(const BigVector<PrimRef>& refs, std::uint32_t begin, std::uint32_t end, Box& box, Box& centres) {
    box = Box();
    centres = Box();
    for (std::uint32_t i = begin; i < end; ++i) {
        box.grow(refs[i].lo, refs[i].hi);
        const V4 c = refs[i].lo + refs[i].hi;
        centres.grow(c, c);
    }
}

// World bounds padded by a few float ulps of their magnitude, so that a hit computed in object
// space (with its own rounding) is never outside the box that leads to it.
Bounds padded_world_bounds(const Instance& inst, const std::vector<TriangleMesh>* meshes) {
    const Bounds b = inst.kind == ShapeKind::Mesh ? mesh_world_bounds((*meshes)[inst.mesh], inst) : world_bounds(inst);
    return b.padded(1e-5f);
}

// The threads a build uses: as asked (0 = all hardware threads), at most 8.
int build_threads(int asked) { return std::min(worker_count(asked, 8), 8); }

// Runs body(begin, end) over [0, n) in chunks, on all build threads when n is large.
template <class Body>
void parallel_chunks(std::size_t n, int threads, Body body) {
    if (threads == 1 || n < kParallelBuildMin) {
        body(std::uint32_t(0), std::uint32_t(n));
        return;
    }
    constexpr std::size_t kChunk = 16384;
    parallel_for((n + kChunk - 1) / kChunk, threads, [&](std::size_t c, int) {
        body(std::uint32_t(c * kChunk), std::uint32_t(std::min(n, (c + 1) * kChunk)));
    });
}

// Builds the subtree of `root` (whose node nodes[root.node] exists) into `nodes`. Tasks of at most
// `defer_below` references are not built but appended to *deferred (when given), for other threads.
template <class Nodes>
void build_subtree(BigVector<PrimRef>& refs, const Task& root, Nodes& nodes, std::uint32_t defer_below,
                   std::vector<Task>* deferred, const BvhBuildCosts& costs, const std::atomic<bool>* cancel) {
    const float traversal_cost = costs.traversal_cost;
    const std::uint32_t max_leaf = costs.max_leaf;
    const std::uint32_t block = costs.block;
    auto blocks = [block](std::uint32_t n) { return float((n + block - 1) / block); };
    std::vector<Task> stack{root};
    // A node's binning reads its references once: looking at `cancel` every few nodes stops a
    // build of millions within a fraction of a second (the tree left is then unusable).
    for (std::uint32_t visited = 0; !stack.empty(); ++visited) {
        if (visited % 64 == 0 && cancel && cancel->load(std::memory_order_relaxed)) return;
        const Task task = stack.back();
        stack.pop_back();
        if (deferred && task.end - task.begin <= defer_below) {
            deferred->push_back(task);
            continue;
        }

        // The binning pass of the parent gives the children's bounds; median splits do not.
        Box box = task.box, centres = task.centres;
        if (!task.known) bounds_of(refs, task.begin, task.end, box, centres);
        const std::uint32_t count = task.end - task.begin;
        auto make_leaf = [&] {
            BinNode& node = nodes[task.node];
            node.box = box.bounds();
            node.first = task.begin;
            node.count = count;
        };
        if (count == 1) { make_leaf(); continue; }

        const V4 ext = centres.hi - centres.lo;
        const int axis = ext[0] > ext[1] ? (ext[0] > ext[2] ? 0 : 2) : (ext[1] > ext[2] ? 1 : 2);
        auto centre = [axis](const PrimRef& r) { return r.lo[axis] + r.hi[axis]; };
        auto median_split = [&] {
            const std::uint32_t mid = task.begin + count / 2;
            std::nth_element(refs.begin() + task.begin, refs.begin() + mid, refs.begin() + task.end,
                             [&](const PrimRef& a, const PrimRef& b) { return centre(a) < centre(b); });
            return mid;
        };
        std::uint32_t mid;
        Box child_box[2], child_centres[2];
        bool known = false;
        if (!(ext[axis] > 0.0f) || task.depth >= kSahDepthLimit) {
            // No plane separates the centres (or the tree is already deep): split at the median.
            if (count <= max_leaf) { make_leaf(); continue; }
            mid = median_split();
        } else {
            struct Bin { Box box, centres; std::uint32_t count = 0; };
            std::array<Bin, kBins> bins{};
            const float lo = centres.lo[axis];
            const float scale = kBins / ext[axis];
            auto bin_of = [&](const PrimRef& r) {
                // Written so that a non-finite position (which flatten refuses) still lands in a bin.
                const float f = (centre(r) - lo) * scale;
                return f < float(kBins - 1) ? (f > 0.0f ? static_cast<int>(f) : 0) : kBins - 1;
            };
            // (In pieces: the top nodes of a build of millions bin millions each.)
            constexpr std::uint32_t kPiece = 1u << 18;
            for (std::uint32_t from = task.begin; from < task.end; from += std::min(kPiece, task.end - from)) {
                if (from != task.begin && cancel && cancel->load(std::memory_order_relaxed)) return;
                for (std::uint32_t i = from, to = from + std::min(kPiece, task.end - from); i < to; ++i) {
                    const PrimRef& r = refs[i];
                    Bin& b = bins[bin_of(r)];
                    b.box.grow(r.lo, r.hi);
                    const V4 c = r.lo + r.hi;
                    b.centres.grow(c, c);
                    ++b.count;
                }
            }
            // Sweep from the right to get the cost of every right side, then from the left.
            std::array<float, kBins> right_cost{};
            Box acc;
            std::uint32_t acc_n = 0;
            for (int i = kBins - 1; i > 0; --i) {
                acc.grow(bins[i].box);
                acc_n += bins[i].count;
                right_cost[i] = acc.area() * blocks(acc_n);
            }
            float best = kInf;
            int best_split = -1;
            acc = Box();
            acc_n = 0;
            for (int i = 0; i < kBins - 1; ++i) {
                acc.grow(bins[i].box);
                acc_n += bins[i].count;
                const float cost = acc.area() * blocks(acc_n) + right_cost[i + 1];
                if (acc_n > 0 && acc_n < count && cost < best) { best = cost; best_split = i + 1; }
            }
            const float leaf_cost = blocks(count);
            const float area = box.area();
            const float split_cost = traversal_cost + (area > 0.0f ? best / area : leaf_cost);
            if (best_split < 0 || (split_cost >= leaf_cost && count <= max_leaf)) {
                if (count <= max_leaf) { make_leaf(); continue; }
                mid = median_split();
            } else {
                auto it = std::partition(refs.begin() + task.begin, refs.begin() + task.end,
                                         [&](const PrimRef& r) { return bin_of(r) < best_split; });
                mid = static_cast<std::uint32_t>(it - refs.begin());
                for (int i = 0; i < kBins; ++i) {
                    child_box[i >= best_split].grow(bins[i].box);
                    child_centres[i >= best_split].grow(bins[i].centres);
                }
                known = true;
            }
        }
        const std::uint32_t left = static_cast<std::uint32_t>(nodes.size());
        nodes.emplace_back();
        nodes.emplace_back();
        BinNode& node = nodes[task.node];
        node.box = box.bounds();
        node.first = left;
        node.second = left + 1;
        node.count = 0;
        stack.push_back({mid, task.end, left + 1, task.depth + 1, child_box[1], child_centres[1], known});
        stack.push_back({task.begin, mid, left, task.depth + 1, child_box[0], child_centres[0], known});
    }
}

// The binary tree over all refs. The top is built by this thread; the subtrees below it are
// built in parallel into separate arrays, then appended in a fixed order (so the result does not
// depend on the thread count or timing).
BigVector<BinNode> build_binary(BigVector<PrimRef>& refs, int threads, const BvhBuildCosts& costs,
                                const std::atomic<bool>* cancel) {
    const std::uint32_t n = static_cast<std::uint32_t>(refs.size());
    BigVector<BinNode> nodes;
    nodes.reserve(2 * std::size_t(n));
    nodes.emplace_back();
    const Task root{0, n, 0, 0, {}, {}, false};
    if (threads == 1 || n < kParallelBuildMin) {
        build_subtree(refs, root, nodes, 0, nullptr, costs, cancel);
        return nodes;
    }
    // Subtrees of at most n/16 refs: enough pieces to balance two to eight threads.
    std::vector<Task> deferred;
    build_subtree(refs, root, nodes, n / 16, &deferred, costs, cancel);
    // Ordinary pages here: each part ends in a partly used page, which on 2 MB pages would be
    // resident whole (16–32 parts: +25 MB of peak for 1M triangles, to save 0.05 s).
    std::vector<std::vector<BinNode>> parts(deferred.size());
    parallel_for(deferred.size(), threads, [&](std::size_t i, int) {
        std::vector<BinNode>& part = parts[i];
        part.reserve(2 * std::size_t(deferred[i].end - deferred[i].begin));
        part.emplace_back();
        Task t = deferred[i];
        t.node = 0;
        build_subtree(refs, t, part, 0, nullptr, costs, cancel);
    });
    // Part node 0 is the deferred task's own node; part node k > 0 goes to base + k - 1.
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const std::vector<BinNode>& part = parts[i];
        const std::uint32_t base = static_cast<std::uint32_t>(nodes.size());
        auto map = [&](std::uint32_t k) { return k == 0 ? deferred[i].node : base + k - 1; };
        for (std::size_t k = 0; k < part.size(); ++k) {
            BinNode node = part[k];
            if (node.count == 0) {
                node.first = map(node.first);
                node.second = map(node.second);
            }
            if (k == 0) nodes[deferred[i].node] = node;
            else nodes.push_back(node);
        }
        std::vector<BinNode>().swap(parts[i]);
    }
    return nodes;
}

// The binary leaves under every node of the tree (children come after their parent in `bin`).
BigVector<std::uint32_t> leaves_under(const BigVector<BinNode>& bin) {
    BigVector<std::uint32_t> n(bin.size(), 1);
    for (std::size_t i = bin.size(); i-- > 0;)
        if (bin[i].count == 0) n[i] = n[bin[i].first] + n[bin[i].second];
    return n;
}

// Depth-first collapse of the binary subtree at `root` into W-wide nodes; returns the index of
// the wide node made for it. `leaves`: leaves_under(bin), for the 8-wide fill rule below (empty
// for 4-wide nodes).
template <class Node>
std::uint32_t collapse(const BigVector<BinNode>& bin, std::uint32_t root, BigVector<Node>& out,
                       const BigVector<std::uint32_t>& leaves) {
    constexpr int W = Node::kWidth;
    std::uint32_t set[W] = {root};
    int size = 1;
    auto open = [&](int i) {
        const BinNode& c = bin[set[i]];
        set[i] = c.first;
        set[size++] = c.second;
    };
    // The largest-area member that is an inner node and passes `ok`, or -1.
    auto largest = [&](auto ok) {
        int pick = -1;
        float pick_area = -1.0f;
        for (int i = 0; i < size; ++i) {
            const BinNode& c = bin[set[i]];
            if (c.count == 0 && ok(set[i]) && c.box.surface_area() > pick_area) { pick = i; pick_area = c.box.surface_area(); }
        }
        return pick;
    };
    if (W > 4 && leaves[root] <= std::uint32_t(W * W)) {
        // Near the bottom of an 8-wide tree, opening by area alone leaves most nodes of the last
        // level half empty (a subtree of 32 leaves becomes 8 nodes of 4; for 10,000 instances,
        // 4,681 nodes where 1,500 would do). Open the members of more than W leaves (so each
        // child fills a node of its own), then absorb whole the small ones that still fit.
        for (int pick; size < W && (pick = largest([&](std::uint32_t b) { return leaves[b] > std::uint32_t(W); })) >= 0;)
            open(pick);
        for (;;) {
            int pick = -1;
            for (int i = 0; i < size; ++i)
                if (bin[set[i]].count == 0 && leaves[set[i]] - 1 <= std::uint32_t(W - size) &&
                    (pick < 0 || leaves[set[i]] < leaves[set[pick]]))
                    pick = i;
            if (pick < 0) break;
            open(pick);
        }
    } else {
        // Open the largest-area inner node of the set until there are W (or only leaves).
        for (int pick; size < W && (pick = largest([](std::uint32_t) { return true; })) >= 0;) open(pick);
    }
    const std::uint32_t index = static_cast<std::uint32_t>(out.size());
    out.emplace_back();
    {
        Node& node = out[index];
        for (int s = 0; s < W; ++s) {
            for (int a = 0; a < 3; ++a) {
                node.box[a][s] = std::numeric_limits<float>::infinity();
                node.box[3 + a][s] = -std::numeric_limits<float>::infinity();
            }
            node.child[s] = 0;
            node.pad[s] = 0;
        }
    }
    for (int s = 0; s < size; ++s) {
        const BinNode& c = bin[set[s]];
        std::uint32_t ref;
        if (c.count > 0) {
            ref = Node::kLeafBit | (c.first << 4) | (c.count - 1);
        } else {
            ref = collapse(bin, set[s], out, leaves);  // may reallocate `out`: index again below
        }
        Node& node = out[index];
        for (int a = 0; a < 3; ++a) {
            node.box[a][s] = c.box.lo[a];
            node.box[3 + a][s] = c.box.hi[a];
        }
        node.child[s] = ref;
    }
    return index;
}

// The binary tree over n boxes; order[i] gets the primitive at leaf place i. Empty (and order
// the identity) for n = 0 or when cancelled.
BigVector<BinNode> build_binary_tree(std::size_t n, const std::function<Bounds(std::uint32_t)>& box_of,
                                     const BvhBuildCosts& costs, int threads_asked, std::vector<std::uint32_t>& order,
                                     const std::atomic<bool>* cancel) {
    const int threads = build_threads(threads_asked);
    order.clear();
    if (n == 0) return {};
    if (n >= Bvh4Node::kMaxInstances) throw std::length_error("too many primitives for the BVH");

    order.resize(n);  // leaf order: the primitive that goes to place i
    auto cancelled = [&] {
        if (!cancel || !cancel->load(std::memory_order_relaxed)) return false;
        for (std::uint32_t i = 0; i < n; ++i) order[i] = i;  // an unfinished tree: nothing of it is kept
        return true;
    };
    if (cancelled()) return {};
    BigVector<PrimRef> refs(n);
    parallel_chunks(n, threads, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t i = begin; i < end; ++i) {
            if (i % 16384 == 0 && cancel && cancel->load(std::memory_order_relaxed)) return;
            const Bounds b = box_of(i);
            float index;
            std::memcpy(&index, &i, 4);
            refs[i] = {V4{b.lo.x, b.lo.y, b.lo.z, index}, V4{b.hi.x, b.hi.y, b.hi.z, 0.0f}};
        }
    });
    if (cancelled()) return {};
    BigVector<BinNode> bin = build_binary(refs, threads, costs, cancel);
    if (cancelled()) return {};
    for (std::uint32_t i = 0; i < n; ++i) order[i] = refs[i].index();
    return bin;
}

// The binary tree collapsed into W-wide nodes.
template <class Node>
BasicBvh<Node> collapse_tree(const BigVector<BinNode>& bin) {
    BasicBvh<Node> bvh;
    if (bin.empty()) return bvh;
    bvh.box = bin[0].box;
    // The binary tree has ~2n/L nodes for leaves of L; a W-wide node replaces W − 1 inner
    // ones, so ~2n/((W − 1)L) wide nodes. Untouched reserved pages cost no memory.
    bvh.nodes.reserve(bin.size() / (Node::kWidth - 1) + 1);
    collapse(bin, 0, bvh.nodes, Node::kWidth > 4 ? leaves_under(bin) : BigVector<std::uint32_t>());
    return bvh;
}

template <class Node>
BasicBvh<Node> build_wide_bvh(std::size_t n, const std::function<Bounds(std::uint32_t)>& box_of,
                              const BvhBuildCosts& costs, int threads, std::vector<std::uint32_t>& order,
                              const std::atomic<bool>* cancel) {
    return collapse_tree<Node>(build_binary_tree(n, box_of, costs, threads, order, cancel));
}

}  // namespace

Bvh build_bvh_over_boxes(std::size_t n, const std::function<Bounds(std::uint32_t)>& box_of, const BvhBuildCosts& costs,
                         int threads, std::vector<std::uint32_t>& order, const std::atomic<bool>* cancel) {
    Bvh bvh;
    static_cast<BasicBvh<Bvh4Node>&>(bvh) = build_wide_bvh<Bvh4Node>(n, box_of, costs, threads, order, cancel);
    return bvh;
}

Bvh8 build_bvh8_over_boxes(std::size_t n, const std::function<Bounds(std::uint32_t)>& box_of,
                           const BvhBuildCosts& costs, int threads, std::vector<std::uint32_t>& order,
                           const std::atomic<bool>* cancel) {
    return build_wide_bvh<Bvh8Node>(n, box_of, costs, threads, order, cancel);
}

Bvh build_bvh(std::vector<Instance>& instances, int threads, const std::vector<TriangleMesh>* meshes,
              std::vector<std::uint32_t>* leaf_order, const std::atomic<bool>* cancel) {
    const float traversal_cost = instances.size() > kLargeScene ? kTraversalCostLarge : kTraversalCostCached;
    std::vector<std::uint32_t> source;
    Bvh bvh;
    auto box_of = [&](std::uint32_t i) { return padded_world_bounds(instances[i], meshes); };
    if (meshes && !meshes->empty()) {  // 8-wide (bvh_node.h)
        bvh.wide = build_wide_bvh<Bvh8Node>(instances.size(), box_of, {traversal_cost, kMaxInstanceLeaf}, threads,
                                            source, cancel);
        bvh.wide.nodes.shrink_to_fit();
        bvh.box = bvh.wide.box;
    } else {
        // 4-wide for the packets; where the CPU has AVX2, an 8-wide copy of the same tree for
        // single rays (bvh_node.h).
        const BigVector<BinNode> bin = build_binary_tree(instances.size(), box_of,
                                                         {traversal_cost, kMaxInstanceLeaf}, threads, source, cancel);
        static_cast<BasicBvh<Bvh4Node>&>(bvh) = collapse_tree<Bvh4Node>(bin);
#ifdef WHITTED_BVH_AVX2
        if (bvh_detail::cpu_has_avx2()) {
            bvh.wide = collapse_tree<Bvh8Node>(bin);
            bvh.wide.nodes.shrink_to_fit();
        }
#endif
    }
    const std::size_t n = instances.size();
    if (cancel && cancel->load(std::memory_order_relaxed)) {  // the instances stay as they were
        if (leaf_order) leaf_order->clear();
        return Bvh{};
    }
    if (leaf_order) *leaf_order = source;
    // Reorder the instances to leaf order in place, following the permutation's cycles.
    for (std::uint32_t i = 0; i < n; ++i) {
        if (source[i] == i) continue;
        const Instance first = instances[i];
        std::uint32_t j = i;
        while (source[j] != i) {
            const std::uint32_t k = source[j];
            instances[j] = instances[k];
            source[j] = j;
            j = k;
        }
        instances[j] = first;
        source[j] = j;
    }
    return bvh;
}

}  // namespace whitted
