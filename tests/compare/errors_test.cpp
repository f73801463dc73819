// idiff's errors and verdict on small images worked out by hand.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "compare/errors.h"

namespace whitted {
namespace {

LinearImage filled(int w, int h, glm::vec3 c) {
    return LinearImage{w, h, std::vector<glm::vec3>(std::size_t(w) * std::size_t(h), c), {}};
}

// 2×2 grey 0.5; B has R = 0.75 in pixel (1, 0): one value of twelve differs, by 0.25.
struct OnePixelOff : ::testing::Test {
    LinearImage a = filled(2, 2, glm::vec3(0.5f)), b = a;
    void SetUp() override { b.rgb[1].x = 0.75f; }
};

TEST_F(OnePixelOff, MeanRmsAndPsnrOfAKnownMse) {
    const ErrorStats s = compute_errors(a, b, {});
    EXPECT_EQ(s.pixels, 4u);
    EXPECT_DOUBLE_EQ(s.mean_error, 0.25 / 12.0);
    // MSE = 0.25² / 12 = 1/192, so PSNR = 10·log10(192) with peak 1.
    EXPECT_DOUBLE_EQ(s.rms_error, std::sqrt(1.0 / 192.0));
    EXPECT_NEAR(s.psnr, 22.83301, 1e-5);
    EXPECT_EQ(s.peak, 1.0);
    EXPECT_EQ(s.max_error, 0.25);
    EXPECT_EQ(s.max_x, 1);
    EXPECT_EQ(s.max_y, 0);
    EXPECT_EQ(s.max_channel, 0);
    EXPECT_EQ(s.max_a, 0.5f);
    EXPECT_EQ(s.max_b, 0.75f);
    EXPECT_EQ(s.fail_pixels, 1u);
    EXPECT_EQ(s.warn_pixels, 1u);
}

TEST_F(OnePixelOff, IdiffDefaultsFailOnAnyDifference) {
    Thresholds t;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::fail);
    EXPECT_EQ(judge(compute_errors(a, a, t), t), Verdict::pass);
}

// One pixel of four is 25%: "more than P %" fails only below 25.
TEST_F(OnePixelOff, FailPercentIsStrictlyMoreThan) {
    Thresholds t;
    t.fail_percent = 25.0f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::warn);  // not failing, but warn's 0% is exceeded
    t.warn_percent = 25.0f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::pass);
    t.fail_percent = 24.9f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::fail);
    t.fail_percent = 25.0f;
    t.warn_percent = 24.9f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::warn);
}

// A difference equal to the threshold is not over it.
TEST_F(OnePixelOff, ThresholdIsStrictlyMoreThan) {
    Thresholds t;
    t.fail = 0.25f;
    ErrorStats s = compute_errors(a, b, t);
    EXPECT_EQ(s.fail_pixels, 0u);
    EXPECT_EQ(judge(s, t), Verdict::warn);  // the warn threshold is still 1e-6
    t.warn = 0.25f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::pass);
    t.fail = 0.2499f;
    EXPECT_EQ(compute_errors(a, b, t).fail_pixels, 1u);
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::fail);
}

TEST_F(OnePixelOff, HardLimitsCatchOnePixel) {
    Thresholds t;
    t.fail_percent = t.warn_percent = 100.0f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::pass);
    t.hard_warn = 0.25f;  // not over
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::pass);
    t.hard_warn = 0.2f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::warn);
    t.hard_fail = 0.2f;
    EXPECT_EQ(judge(compute_errors(a, b, t), t), Verdict::fail);
}

// A pixel counts once however many of its channels are over.
TEST(Errors, ShareOfPixelsOverTheTolerance) {
    LinearImage a = filled(2, 2, glm::vec3(0.0f)), b = a;
    b.rgb[0] = {0.125f, 0.0f, 0.0f};
    b.rgb[1] = {0.0f, 0.375f, 0.375f};  // two channels over, one pixel
    b.rgb[3] = {0.0f, 0.0f, 0.5f};
    Thresholds t;
    t.fail = 0.25f;
    t.warn = 0.1f;
    const ErrorStats s = compute_errors(a, b, t);
    EXPECT_EQ(s.fail_pixels, 2u);
    EXPECT_EQ(s.warn_pixels, 3u);
    EXPECT_DOUBLE_EQ(s.mean_error, (0.125 + 0.375 + 0.375 + 0.5) / 12.0);
    EXPECT_EQ(s.max_error, 0.5);
    EXPECT_EQ(s.max_x, 1);
    EXPECT_EQ(s.max_y, 1);
    EXPECT_EQ(s.max_channel, 2);
    t.fail_percent = 50.0f;  // 2 of 4 is not more than 50%
    t.warn_percent = 75.0f;
    EXPECT_EQ(judge(s, t), Verdict::pass);
}

// 8-bit values 0 and 51 differ by 51/255 = 0.2 everywhere: PSNR = 20·log10(1/0.2).
TEST(Errors, PsnrOfBytes) {
    const ErrorStats s = compute_errors(filled(3, 3, glm::vec3(0.0f)), filled(3, 3, glm::vec3(51.0f / 255.0f)), {});
    EXPECT_NEAR(s.psnr, 20.0 * std::log10(5.0), 1e-5);
    EXPECT_NEAR(s.mean_error, 0.2, 1e-7);
}

// Values past 1 (an .exr) make the peak the largest value, as idiff does.
TEST(Errors, PeakOfLinearImagesIsTheirLargestValue) {
    const ErrorStats s = compute_errors(filled(1, 1, {2.0f, 0.0f, 0.0f}), filled(1, 1, {1.0f, 0.0f, 0.0f}), {});
    EXPECT_EQ(s.peak, 2.0);
    EXPECT_NEAR(s.rms_error, std::sqrt(1.0 / 3.0), 1e-12);
    EXPECT_NEAR(s.psnr, 20.0 * std::log10(2.0 * std::sqrt(3.0)), 1e-9);
}

TEST(Errors, EqualImagesHaveInfinitePsnr) {
    const LinearImage a = filled(4, 3, {0.1f, 0.2f, 0.3f});
    const ErrorStats s = compute_errors(a, a, {});
    EXPECT_TRUE(std::isinf(s.psnr) && s.psnr > 0);
    EXPECT_EQ(s.max_error, 0.0);
    EXPECT_EQ(s.fail_pixels, 0u);
}

TEST(Errors, NanMatchesNanButNothingElse) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    LinearImage a = filled(2, 1, glm::vec3(0.5f)), b = a;
    a.rgb[0].x = b.rgb[0].x = nan;  // no error
    a.rgb[0].y = b.rgb[0].y = inf;  // no error
    EXPECT_EQ(compute_errors(a, b, {}).max_error, 0.0);
    b.rgb[1].z = nan;  // against 0.5: an infinite error, over every threshold
    Thresholds t;
    t.fail = t.warn = 1000.0f;
    const ErrorStats s = compute_errors(a, b, t);
    EXPECT_TRUE(std::isinf(s.max_error));
    EXPECT_EQ(s.max_x, 1);
    EXPECT_EQ(s.max_channel, 2);
    EXPECT_EQ(s.fail_pixels, 1u);
    EXPECT_EQ(s.mean_error, 0.0);  // the finite values all agree
    b.rgb[0].y = -inf;             // the other infinity
    EXPECT_EQ(compute_errors(a, b, t).fail_pixels, 2u);
}

}  // namespace
}  // namespace whitted
