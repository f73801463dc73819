// SSIM over 8×8 blocks on blocks worked out by hand: with C1 = 0.01², C2 = 0.03²,
//   SSIM = (2·μa·μb + C1)(2·σab + C2) / ((μa² + μb² + C1)(σa² + σb² + C2)).
#include <cmath>

#include <gtest/gtest.h>

#include "compare/ssim.h"

namespace whitted {
namespace {

constexpr double C1 = 1e-4, C2 = 9e-4;

LinearImage filled(int w, int h, glm::vec3 c) {
    return LinearImage{w, h, std::vector<glm::vec3>(std::size_t(w) * std::size_t(h), c), {}};
}

// A checkerboard of single pixels, `lo` and `hi`, `lo` at (0, 0).
LinearImage checker(int w, int h, float lo, float hi) {
    LinearImage im = filled(w, h, glm::vec3(lo));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if ((x + y) % 2) im.rgb[std::size_t(y * w + x)] = glm::vec3(hi);
    return im;
}

TEST(Ssim, EqualImagesScoreExactlyOne) {
    LinearImage a = checker(16, 16, 0.1f, 0.9f);
    a.rgb[37] = {0.3f, 0.7f, 0.2f};
    const SsimStats s = compute_ssim(a, a);
    EXPECT_EQ(s.blocks, 4u);
    EXPECT_EQ(s.blocks_failing, 0u);
    for (double v : s.block_ssim) EXPECT_EQ(v, 1.0);
    EXPECT_EQ(s.mean, 1.0);
}

// Flat blocks: σ = 0, so SSIM is the luminance term alone, (2·μa·μb + C1) / (μa² + μb² + C1).
TEST(Ssim, ConstantShiftOfAFlatBlock) {
    const SsimStats s = compute_ssim(filled(8, 8, glm::vec3(0.5f)), filled(8, 8, glm::vec3(0.625f)));
    ASSERT_EQ(s.blocks, 1u);
    EXPECT_NEAR(s.block_ssim[0], (0.625 + C1) / (0.25 + 0.390625 + C1), 1e-12);  // 0.975613…
    EXPECT_NEAR(s.block_ssim[0], 0.9756135, 1e-7);
    EXPECT_EQ(s.blocks_failing, 1u);
}

// The same shift of a textured block: σa = σb = σab, so the structure term is 1 and only the
// luminance term is left, the same number as for the flat block.
TEST(Ssim, ConstantShiftOfATexturedBlock) {
    const LinearImage a = checker(8, 8, 0.25f, 0.75f), b = checker(8, 8, 0.375f, 0.875f);
    EXPECT_NEAR(compute_ssim(a, b).block_ssim[0], (0.625 + C1) / (0.25 + 0.390625 + C1), 1e-12);
}

// 0/1 against 1/0: equal means, σ² = 0.25 each, σab = −0.25: (−0.5 + C2) / (0.5 + C2) = −0.996406…
TEST(Ssim, InvertedCheckerboard) {
    const double v = compute_ssim(checker(8, 8, 0.0f, 1.0f), checker(8, 8, 1.0f, 0.0f)).block_ssim[0];
    EXPECT_NEAR(v, (-0.5 + C2) / (0.5 + C2), 1e-12);
    EXPECT_NEAR(v, -0.9964065, 1e-7);
}

// 0/1 against flat 0.5: equal means, σb = σab = 0: C2 / (0.25 + C2) = 0.003587…
TEST(Ssim, CheckerboardAgainstItsMean) {
    const double v = compute_ssim(checker(8, 8, 0.0f, 1.0f), filled(8, 8, glm::vec3(0.5f))).block_ssim[0];
    EXPECT_NEAR(v, C2 / (0.25 + C2), 1e-12);
}

// A block's SSIM is the mean of its channels': R equal (1), G and B shifted.
TEST(Ssim, MeanOverTheChannels) {
    const double shifted = (0.625 + C1) / (0.25 + 0.390625 + C1);
    const double v = compute_ssim(filled(8, 8, glm::vec3(0.5f)), filled(8, 8, {0.5f, 0.625f, 0.625f})).block_ssim[0];
    EXPECT_NEAR(v, (1.0 + 2.0 * shifted) / 3.0, 1e-12);
}

// Values are clamped to [0, 1] first: 2 and 1 are the same white.
TEST(Ssim, ValuesAreClamped) {
    EXPECT_EQ(compute_ssim(filled(8, 8, glm::vec3(2.0f)), filled(8, 8, glm::vec3(1.0f))).block_ssim[0], 1.0);
}

TEST(Ssim, WorstBlockAndTheShareAtOrBelowTheThreshold) {
    const LinearImage a = checker(24, 16, 0.2f, 0.8f);
    LinearImage b = a;
    b.rgb[std::size_t(3 * 24 + 10)] = glm::vec3(0.5f);   // a small change in the block at 8,0
    b.rgb[std::size_t(12 * 24 + 20)] = glm::vec3(1.0f);  // a larger one in the block at 16,8
    const SsimStats s = compute_ssim(a, b);
    EXPECT_EQ(s.blocks_across, 3);
    EXPECT_EQ(s.blocks_down, 2);
    EXPECT_EQ(s.blocks, 6u);
    EXPECT_EQ(s.blocks_failing, 2u);
    EXPECT_EQ(s.worst.x, 16);
    EXPECT_EQ(s.worst.y, 8);
    EXPECT_EQ(s.worst.width, 8);
    EXPECT_LT(s.worst.ssim, s.block_ssim[1]);
    EXPECT_LT(s.block_ssim[1], 0.996);
    EXPECT_EQ(s.block_ssim[0], 1.0);
    SsimOptions lenient;
    lenient.threshold = s.block_ssim[1];  // "at or below": that block still counts
    EXPECT_EQ(compute_ssim(a, b, lenient).blocks_failing, 2u);
}

// Sides that are not multiples of 8: the last blocks are smaller, and still count.
TEST(Ssim, EdgeBlocksAreSmaller) {
    const LinearImage a = filled(10, 9, glm::vec3(0.5f));
    LinearImage b = a;
    b.rgb[std::size_t(8 * 10 + 9)] = glm::vec3(0.625f);  // pixel 9,8: alone in the 2×1 corner block
    const SsimStats s = compute_ssim(a, b);
    EXPECT_EQ(s.blocks, 4u);
    EXPECT_EQ(s.worst.x, 8);
    EXPECT_EQ(s.worst.y, 8);
    EXPECT_EQ(s.worst.width, 2);
    EXPECT_EQ(s.worst.height, 1);
    // Its two pixels: a = (0.5, 0.5), b = (0.5, 0.625): μb = 0.5625, σb² = 0.00390625, σab = 0.
    const double lum = (2 * 0.5 * 0.5625 + C1) / (0.25 + 0.5625 * 0.5625 + C1);
    EXPECT_NEAR(s.worst.ssim, lum * C2 / (0.00390625 + C2), 1e-12);
}

}  // namespace
}  // namespace whitted
