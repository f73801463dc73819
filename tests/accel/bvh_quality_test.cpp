// The BVH's quality, not only its correctness: a tree that answers every query right can still
// test far more boxes and instances per ray than it should, and only the benchmarks (which ctest
// never runs) would notice. Here the tree's cost is measured exactly and bounded on fixed scenes.
//
// The measure: for a random line through the scene's box (uniform over lines, as with the SAH
// itself), the expected number of 4-wide node tests plus instance tests, when every node and leaf
// whose box the line crosses is entered. By Cauchy-Crofton, a random line that meets a convex
// box B meets a convex box A inside it with probability area(A) / area(B), so that expectation is
//   sum over nodes of area(node box) / area(root box)
//   + sum over leaves of count · area(leaf box) / area(root box).
#include <algorithm>
#include <numeric>
#include <vector>

#include <gtest/gtest.h>

#include "accel/bvh.h"
#include "accel/instance_geometry.h"
#include "flatten/flatten.h"
#include "support/scene_builder.h"

namespace whitted {
namespace {

struct TreeCost {
    double node_tests = 0, instance_tests = 0;
    int nodes = 0, leaves = 0;
    double total() const { return node_tests + instance_tests; }
};

Bounds slot_box(const Bvh4Node& n, int s) {
    Bounds b;
    b.lo = {n.box[0][s], n.box[1][s], n.box[2][s]};
    b.hi = {n.box[3][s], n.box[4][s], n.box[5][s]};
    return b;
}

TreeCost cost_of(const Bvh& bvh) {
    TreeCost c;
    const double root = bvh.box.surface_area();
    std::vector<std::pair<std::uint32_t, double>> stack{{0u, root}};  // node, area of its box
    while (!stack.empty()) {
        const auto [index, area] = stack.back();
        stack.pop_back();
        c.node_tests += area / root;
        ++c.nodes;
        const Bvh4Node& n = bvh.nodes.at(index);
        for (int s = 0; s < 4; ++s) {
            const Bounds b = slot_box(n, s);
            if (b.empty()) continue;
            if (Bvh4Node::is_leaf(n.child[s])) {
                c.instance_tests += Bvh4Node::leaf_count(n.child[s]) * double(b.surface_area()) / root;
                ++c.leaves;
            } else {
                stack.push_back({n.child[s], b.surface_area()});
            }
        }
    }
    return c;
}

// The same measure for the tree a plain 4-way object-median split gives (a reference built here,
// independently of the library): each set of more than `leaf` instances is sorted along the
// longest axis of its centres and cut into four equal parts.
double median_tree_cost(const std::vector<Instance>& instances, std::size_t leaf) {
    std::vector<Bounds> boxes;
    for (const Instance& inst : instances) boxes.push_back(world_bounds(inst));
    auto box_of = [&](const std::vector<std::size_t>& set) {
        Bounds b;
        for (std::size_t i : set) {
            b.lo = glm::min(b.lo, boxes[i].lo);
            b.hi = glm::max(b.hi, boxes[i].hi);
        }
        return b;
    };
    std::vector<std::size_t> all(instances.size());
    std::iota(all.begin(), all.end(), 0);
    const double root = box_of(all).surface_area();
    double cost = 0;
    // A node: its own test, then each of its up to four parts as a leaf or a node.
    std::vector<std::vector<std::size_t>> nodes{all};
    while (!nodes.empty()) {
        std::vector<std::size_t> set = std::move(nodes.back());
        nodes.pop_back();
        cost += box_of(set).surface_area() / root;
        Bounds centres;
        for (std::size_t i : set) {
            const glm::vec3 c = 0.5f * (boxes[i].lo + boxes[i].hi);
            centres.lo = glm::min(centres.lo, c);
            centres.hi = glm::max(centres.hi, c);
        }
        const glm::vec3 e = centres.hi - centres.lo;
        const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
        std::sort(set.begin(), set.end(), [&](std::size_t a, std::size_t b) {
            return boxes[a].lo[axis] + boxes[a].hi[axis] < boxes[b].lo[axis] + boxes[b].hi[axis];
        });
        for (int q = 0; q < 4; ++q) {
            std::vector<std::size_t> part(set.begin() + std::ptrdiff_t(set.size() * q / 4),
                                          set.begin() + std::ptrdiff_t(set.size() * (q + 1) / 4));
            if (part.empty()) continue;
            if (part.size() <= leaf) cost += double(part.size()) * box_of(part).surface_area() / root;
            else nodes.push_back(std::move(part));
        }
    }
    return cost;
}

glm::mat4 at(glm::vec3 centre, float size) { return test::translate_scale(centre, glm::vec3(size)); }

// Objects that nearly coincide (centres 0.001 apart): no split can separate them, so any split
// only adds node tests. One leaf is best: the root's test plus one test of each of the eight.
TEST(BvhQuality, NearlyCoincidentObjectsShareOneLeaf) {
    std::vector<Instance> stack;
    for (int i = 0; i < 8; ++i) stack.push_back(make_instance(at({0.001f * float(i), 0, 0}, 1.0f), ShapeKind::Sphere, 0));
    const Bvh bvh = build_bvh(stack);
    const TreeCost c = cost_of(bvh);
    EXPECT_EQ(c.nodes, 1);
    EXPECT_EQ(c.leaves, 1);
    EXPECT_NEAR(c.total(), 1.0 + 8.0, 1e-3);
}

// A small sphere next to a big one, eight times over (a scene of pairs), beside a row of eight
// lone spheres: a mix where equal-count cuts are poor and the surface area heuristic must beat
// the object median.
std::vector<Instance> uneven_scene() {
    std::vector<Instance> s;
    for (int i = 0; i < 8; ++i) {
        s.push_back(make_instance(at({10.0f * float(i), 0, 0}, 4.0f), ShapeKind::Sphere, 0));
        s.push_back(make_instance(at({10.0f * float(i) + 3.0f, 0, 0}, 0.2f), ShapeKind::Cube, 0));
    }
    for (int i = 0; i < 48; ++i)
        s.push_back(make_instance(at({100.0f + 0.5f * float(i), 0, 0}, 0.3f), ShapeKind::Sphere, 0));
    return s;
}

// An 8 × 8 × 8 grid of small spheres: on evenly spread objects, SAH and the object median should
// give trees of about the same cost.
std::vector<Instance> grid_scene() {
    std::vector<Instance> s;
    for (int i = 0; i < 512; ++i)
        s.push_back(make_instance(at({2.0f * float(i % 8), 2.0f * float(i / 8 % 8), 2.0f * float(i / 64)}, 0.5f),
                                  ShapeKind(i % 4), 0));
    return s;
}

TEST(BvhQuality, TheTreeIsAtLeastAsGoodAsTheObjectMedianSplit) {
    for (auto [name, scene] : {std::pair{"grid", grid_scene()}, std::pair{"uneven", uneven_scene()}}) {
        SCOPED_TRACE(name);
        std::vector<Instance> instances = scene;
        const TreeCost c = cost_of(build_bvh(instances));
        // The reference with leaves of up to 4 (and of 8, whichever is cheaper for the scene).
        const double median = std::min(median_tree_cost(scene, 4), median_tree_cost(scene, 8));
        RecordProperty(std::string(name) + "_cost", std::to_string(c.total()));
        RecordProperty(std::string(name) + "_median_cost", std::to_string(median));
        EXPECT_LE(c.total(), 1.05 * median) << "SAH tree: " << c.node_tests << " node and " << c.instance_tests
                                             << " instance tests per ray; object median: " << median;
    }
}

}  // namespace
}  // namespace whitted
