// The magma map: its published ends and middle (matplotlib / BIDS colormap: entry 0 is
// (0.001462, 0.000466, 0.013866), entry 128 (0.716387, 0.214982, 0.475290), entry 255
// (0.987053, 0.991438, 0.749504)), and brighter with every step, which is what lets a reader
// rank errors by brightness.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "compare/colour_map.h"
#include "compare/flip_colour.h"

namespace whitted {
namespace {

TEST(Magma, PublishedEntries) {
    EXPECT_EQ(magma(0.0f), glm::u8vec3(0, 0, 4));
    EXPECT_EQ(magma(128.0f / 255.0f), glm::u8vec3(183, 55, 121));
    EXPECT_EQ(magma(1.0f), glm::u8vec3(252, 253, 191));
    EXPECT_EQ(magma(-1.0f), magma(0.0f));  // clamped
    EXPECT_EQ(magma(7.0f), magma(1.0f));
    EXPECT_EQ(magma(std::numeric_limits<float>::quiet_NaN()), magma(0.0f));
}

TEST(Magma, LuminanceRisesWithEveryEntry) {
    double last = -1.0;
    for (int i = 0; i < 256; ++i) {
        const glm::u8vec3 c = magma(float(i) / 255.0f);
        const glm::dvec3 linear(flip::srgb_to_linear(c.x / 255.0), flip::srgb_to_linear(c.y / 255.0),
                                flip::srgb_to_linear(c.z / 255.0));
        const double y = flip::linear_rgb_to_xyz(linear).y;
        EXPECT_GT(y, last) << i;
        last = y;
    }
}

TEST(Magma, ImageOfValues) {
    const Image im = magma_image({0.0f, 1.0f, 0.5f, 0.25f, 0.0f, 1.0f}, 3, 2);
    ASSERT_EQ(im.width, 3);
    ASSERT_EQ(im.height, 2);
    EXPECT_EQ(im.at(0, 0), magma(0.0f));
    EXPECT_EQ(im.at(1, 0), magma(1.0f));
    EXPECT_EQ(im.at(0, 1), magma(0.25f));
    EXPECT_EQ(im.at(2, 1), glm::u8vec3(252, 253, 191));
}

}  // namespace
}  // namespace whitted
