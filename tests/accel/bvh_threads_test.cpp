// The BVH build takes the thread count it is given (`--threads 1` means one thread for the build
// too) and gives the very same tree for any count, so images cannot depend on it.
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "accel/bvh.h"

namespace whitted {
namespace {

// Enough instances for the parallel build path (it starts at 50,000), each a translated unit
// shape with its own scale.
std::vector<Instance> grid(int side) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(0.2f, 1.0f);
    std::vector<Instance> instances;
    for (int i = 0; i < side * side; ++i) {
        const glm::vec3 s(u(rng), u(rng), u(rng)), t(float(i % side), 0.0f, float(i / side));
        Instance inst{};
        // world→object of translate(t)·scale(s): x_obj = (x − t) / s.
        inst.world_to_object[0] = {1 / s.x, 0, 0, -t.x / s.x};
        inst.world_to_object[1] = {0, 1 / s.y, 0, -t.y / s.y};
        inst.world_to_object[2] = {0, 0, 1 / s.z, -t.z / s.z};
        inst.kind = ShapeKind(i % 4);
        instances.push_back(inst);
    }
    return instances;
}

// Field by field (padding bytes are not part of the tree).
bool same_nodes(const Bvh& a, const Bvh& b) {
    if (a.nodes.size() != b.nodes.size()) return false;
    for (std::size_t i = 0; i < a.nodes.size(); ++i)
        if (std::memcmp(a.nodes[i].box, b.nodes[i].box, sizeof a.nodes[i].box) != 0 ||
            std::memcmp(a.nodes[i].child, b.nodes[i].child, sizeof a.nodes[i].child) != 0)
            return false;
    return true;
}

bool same_order(const std::vector<Instance>& a, const std::vector<Instance>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (std::memcmp(a[i].world_to_object, b[i].world_to_object, sizeof a[i].world_to_object) != 0 ||
            a[i].kind != b[i].kind || a[i].material != b[i].material)
            return false;
    return true;
}

TEST(BvhThreads, TheTreeIsTheSameForAnyThreadCount) {
    const std::vector<Instance> input = grid(260);  // 67,600 instances
    std::vector<Instance> one = input, two = input, all = input, many = input;
    const Bvh b1 = build_bvh(one, 1);
    const Bvh b2 = build_bvh(two, 2);
    const Bvh b0 = build_bvh(all, 0);
    const Bvh b8 = build_bvh(many, 8);
    ASSERT_FALSE(b1.nodes.empty());
    EXPECT_TRUE(same_nodes(b1, b2));
    EXPECT_TRUE(same_nodes(b1, b0));
    EXPECT_TRUE(same_nodes(b1, b8));
    EXPECT_TRUE(same_order(one, two));
    EXPECT_TRUE(same_order(one, all));
    EXPECT_TRUE(same_order(one, many));
}

}  // namespace
}  // namespace whitted
