// BigVector (util/big_vector.h): arrays of 2 MB or more start on a 2 MB boundary and are marked
// for transparent huge pages (the kernel's "hg" flag on their mapping); smaller ones use the
// ordinary allocator; the contents behave as any vector's through growth and copies.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <numeric>
#include <sstream>
#include <string>

#include "base/big_vector.h"

namespace whitted {
namespace {

constexpr std::size_t kHuge = std::size_t(2) << 20;

// The VmFlags of the mapping holding `p` in /proc/self/smaps ("" when not found).
std::string vm_flags_of(const void* p) {
    std::ifstream smaps("/proc/self/smaps");
    const auto a = reinterpret_cast<std::uintptr_t>(p);
    bool inside = false;
    for (std::string line; std::getline(smaps, line);) {
        std::uintptr_t lo = 0, hi = 0;
        char dash = 0;
        std::istringstream head(line);
        if (head >> std::hex >> lo >> dash >> hi && dash == '-' && line.find(' ') > line.find('-')) {
            inside = lo <= a && a < hi;
        } else if (inside && line.rfind("VmFlags:", 0) == 0) {
            return line + " ";
        }
    }
    return "";
}

TEST(BigVector, BigArraysAreAlignedAndMarkedForHugePages) {
    BigVector<float> v(3 * kHuge / sizeof(float) + 5);  // three whole 2 MB pages and a bit
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % kHuge, 0u);
    if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
        GTEST_SKIP() << "the kernel has no transparent huge pages";
    const std::string flags = vm_flags_of(v.data());
    ASSERT_FALSE(flags.empty()) << "no /proc/self/smaps entry";
    EXPECT_NE(flags.find(" hg "), std::string::npos) << flags;
}

TEST(BigVector, SmallArraysAreOrdinary) {
    BigVector<float> v(1000);
    EXPECT_EQ(vm_flags_of(v.data()).find(" hg "), std::string::npos);
}

TEST(BigVector, KeepsItsContentsAcrossTheThresholdAndCopies) {
    BigVector<std::uint32_t> v;
    const std::size_t n = kHuge / sizeof(std::uint32_t) * 2 + 17;  // grows from small to big
    for (std::uint32_t i = 0; i < n; ++i) v.push_back(i * 7u);
    BigVector<std::uint32_t> copy = v;
    v.resize(10);
    v.shrink_to_fit();  // back below the threshold
    ASSERT_EQ(copy.size(), n);
    for (std::uint32_t i = 0; i < n; ++i) ASSERT_EQ(copy[i], i * 7u);
    for (std::uint32_t i = 0; i < 10; ++i) EXPECT_EQ(v[i], i * 7u);
}

}  // namespace
}  // namespace whitted
