#pragma once
// The single-ray walks test a node's eight boxes in one AVX2 step where the CPU has it, else the
// four-wide tree or two SSE steps (accel/bvh_node.h): walk tests derive from this fixture to run
// both ways (parameter true: AVX2), and must give the same answers.
#include <string>

#include <gtest/gtest.h>

#include "accel/mesh_bvh.h"

namespace whitted::test {

class WalkBothWays : public ::testing::TestWithParam<bool> {
protected:
    void SetUp() override {
        if (set_mesh_walks_use_avx2(GetParam()) != GetParam()) GTEST_SKIP() << "this CPU has no AVX2";
    }
    void TearDown() override { set_mesh_walks_use_avx2(true); }  // the default: AVX2 where the CPU has it
};

inline std::string walk_name(const ::testing::TestParamInfo<bool>& p) { return p.param ? "Avx2" : "Sse"; }

}  // namespace whitted::test
