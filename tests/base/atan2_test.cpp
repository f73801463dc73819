// fast_atan2 against the C library's atan2 (glibc's is correctly rounded in double): within two
// ulps of the angle over quadrants, magnitudes 1e-30 to 1e30 and the axes.
#include <cmath>
#include <cstdint>
#include <limits>

#include <gtest/gtest.h>

#include "base/atan2.h"

namespace whitted {
namespace {

TEST(FastAtan2, IsWithinTwoUlpsOfTheLibrary) {
    std::uint64_t state = 5;
    auto uniform = [&] {  // in [0, 1)
        state = state * 6364136223846793005ull + 1442695040888963407ull;
        return double(state >> 11) * 0x1p-53;
    };
    double worst = 0.0;
    for (int n = 0; n < 2000000; ++n) {
        const double y = (2.0 * uniform() - 1.0) * std::pow(10.0, 60.0 * uniform() - 30.0);
        const double x = (2.0 * uniform() - 1.0) * std::pow(10.0, 60.0 * uniform() - 30.0);
        const double want = std::atan2(y, x), got = fast_atan2(y, x);
        if (want == 0.0) {
            ASSERT_EQ(got, want) << y << " " << x;
            continue;
        }
        const double ulps = std::abs(got - want) / (std::abs(want) * std::numeric_limits<double>::epsilon());
        worst = std::max(worst, ulps);
        ASSERT_LE(ulps, 2.0) << "y " << y << " x " << x;
    }
    EXPECT_GT(worst, 0.0);  // the comparison looked at the bits (not a copy of the library)
    for (double y : {1.0, -1.0, 0.0, -0.0})
        for (double x : {1.0, -1.0, 0.0, -0.0, 1e-300, -1e300})
            EXPECT_EQ(fast_atan2(y, x), std::atan2(y, x)) << y << " " << x;
    EXPECT_EQ(fast_atan2(1.0, std::numeric_limits<double>::infinity()), 0.0);
    EXPECT_DOUBLE_EQ(fast_atan2(std::numeric_limits<double>::infinity(), 1.0), std::atan2(1.0, 0.0));
    EXPECT_TRUE(std::isnan(fast_atan2(std::nan(""), 1.0)));
    EXPECT_TRUE(std::isnan(fast_atan2(1.0, std::nan(""))));
}

}  // namespace
}  // namespace whitted
