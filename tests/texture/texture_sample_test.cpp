// The texel lookup of scene-format.md §8: s = frac(u·U), t = frac(v·V); column s·W, row t·H
// (row 0 = top); bilinear between the four nearest texel centres, wrapping around the edges.
#include <gtest/gtest.h>

#include "texture/texture_sample.h"

namespace whitted {
namespace {

TextureImage make(int w, int h, std::vector<glm::vec3> texels) {
    TextureImage img;
    img.width = w;
    img.height = h;
    for (glm::vec3 t : texels) img.push_back(glm::u8vec3(glm::round(t * 255.0f)));
    return img;
}

void expect_near(glm::vec3 got, glm::vec3 want, const char* what) {
    EXPECT_NEAR(got.x, want.x, 1e-5f) << what;
    EXPECT_NEAR(got.y, want.y, 1e-5f) << what;
    EXPECT_NEAR(got.z, want.z, 1e-5f) << what;
}

const glm::vec3 kBlack(0.0f), kWhite(1.0f), kRed(1, 0, 0), kGreen(0, 1, 0), kBlue(0, 0, 1);

// Two texels side by side: centres at s = 0.25 and 0.75.
TEST(TextureSample, BilinearBetweenTwoTexels) {
    const TextureImage img = make(2, 1, {kBlack, kWhite});
    expect_near(sample_texture(img, {0.25f, 0.5f}, 1, 1), kBlack, "at the centre of texel 0");
    expect_near(sample_texture(img, {0.75f, 0.5f}, 1, 1), kWhite, "at the centre of texel 1");
    // column s·W = 1.0 is the shared edge: x = 1.0 − 0.5 = 0.5 between the centres, half each.
    expect_near(sample_texture(img, {0.5f, 0.5f}, 1, 1), glm::vec3(0.5f), "midway");
    // s = 0.375: column 0.75, x = 0.25 past centre 0 → 25 % of texel 1.
    expect_near(sample_texture(img, {0.375f, 0.5f}, 1, 1), glm::vec3(0.25f), "a quarter of the way");
    expect_near(sample_texture(img, {0.625f, 0.5f}, 1, 1), glm::vec3(0.75f), "three quarters");
}

TEST(TextureSample, BilinearInBothDirections) {
    // 2 × 2: red green / blue white. The image centre is the average of all four.
    const TextureImage img = make(2, 2, {kRed, kGreen, kBlue, kWhite});
    expect_near(sample_texture(img, {0.5f, 0.5f}, 1, 1), (kRed + kGreen + kBlue + kWhite) / 4.0f, "centre");
    // s = 0.5 (between the columns), t = 0.25 (on row 0's centres): red and green only.
    expect_near(sample_texture(img, {0.5f, 0.25f}, 1, 1), (kRed + kGreen) / 2.0f, "top row");
    // s = 0.25 (column 0's centres), t = 0.375: 75 % row 0, 25 % row 1.
    expect_near(sample_texture(img, {0.25f, 0.375f}, 1, 1), 0.75f * kRed + 0.25f * kBlue, "left column");
}

// Row 0 of the image is at v = 0 (the top), column 0 at u = 0.
TEST(TextureSample, RowZeroIsAtVZero) {
    const TextureImage img = make(1, 2, {kRed, kBlue});  // row 0 red, row 1 blue
    expect_near(sample_texture(img, {0.5f, 0.25f}, 1, 1), kRed, "v = 0.25 is row 0");
    expect_near(sample_texture(img, {0.5f, 0.75f}, 1, 1), kBlue, "v = 0.75 is row 1");
}

// Outside the texel centres the lookup wraps: at s = 0 (column 0's left edge) the nearest
// centres are column W−1 (wrapped to −1) and column 0, half each; the same at t = 0.
TEST(TextureSample, WrapsAroundTheEdges) {
    const TextureImage row = make(4, 1, {kRed, kBlack, kBlack, kBlue});
    expect_near(sample_texture(row, {0.0f, 0.5f}, 1, 1), (kRed + kBlue) / 2.0f, "u = 0: last and first column");
    // s = 0.95: column 3.8, x = 3.3 → 70 % column 3 (blue), 30 % column 4 ≡ 0 (red).
    expect_near(sample_texture(row, {0.95f, 0.5f}, 1, 1), 0.7f * kBlue + 0.3f * kRed, "u = 0.95");
    // s = 0.05: column 0.2, x = −0.3 → 30 % column −1 ≡ 3 (blue), 70 % column 0 (red).
    expect_near(sample_texture(row, {0.05f, 0.5f}, 1, 1), 0.3f * kBlue + 0.7f * kRed, "u = 0.05");
    // Continuity across the seam: just below 1 and just above 0 give nearly the same colour.
    const glm::vec3 a = sample_texture(row, {0.9999f, 0.5f}, 1, 1), b = sample_texture(row, {0.0001f, 0.5f}, 1, 1);
    EXPECT_LT(glm::length(a - b), 0.01f);

    const TextureImage column = make(1, 4, {kGreen, kBlack, kBlack, kWhite});
    expect_near(sample_texture(column, {0.5f, 0.0f}, 1, 1), (kGreen + kWhite) / 2.0f, "v = 0: last and first row");
}

// Repeat counts: s = frac(u·U), t = frac(v·V).
TEST(TextureSample, RepeatCounts) {
    const TextureImage img = make(4, 4, [] {
        std::vector<glm::vec3> t;
        for (int i = 0; i < 16; ++i) t.push_back(glm::vec3(float(i) / 15.0f, float(i % 4) / 3.0f, 0.2f));
        return t;
    }());
    for (float u : {0.1f, 0.3f, 0.45f, 0.8f})
        for (float v : {0.05f, 0.4f, 0.7f}) {
            const glm::vec3 repeated = sample_texture(img, {u, v}, 2, 3);
            const float s = u * 2 - std::floor(u * 2), t = v * 3 - std::floor(v * 3);
            expect_near(repeated, sample_texture(img, {s, t}, 1, 1), "2×3 is the single image at frac(2u), frac(3v)");
        }
    // Fractional repeat counts work the same way (0.5: the left half of the image stretched).
    expect_near(sample_texture(img, {0.5f, 0.5f}, 0.5f, 1), sample_texture(img, {0.25f, 0.5f}, 1, 1), "U = 0.5");
}

TEST(TextureSample, OneTexelAndDegenerateInputs) {
    const TextureImage one = make(1, 1, {glm::vec3(0.2f, 0.4f, 0.6f)});
    for (float u : {0.0f, 0.3f, 0.999f}) expect_near(sample_texture(one, {u, u}, 3, 7), glm::vec3(0.2f, 0.4f, 0.6f), "1×1");
    // An empty image (never produced by the loader) reads as white, leaving the material as is.
    expect_near(sample_texture(TextureImage{}, {0.5f, 0.5f}, 1, 1), kWhite, "empty");
    // A NaN coordinate must not index out of bounds.
    const TextureImage img = make(2, 1, {kRed, kBlue});
    const glm::vec3 c = sample_texture(img, {std::nanf(""), 0.5f}, 1, 1);
    EXPECT_TRUE(c == kRed || c == kBlue);
}

}  // namespace
}  // namespace whitted
