// LDR-FLIP checked three ways, none of them against this code's own output:
// 1. the colour pipeline's intermediate values on known colours: the sRGB matrix against the one
//    derived here from the primaries' chromaticities, YCxCz of white and black, and CIELAB of the primaries as
//    published (easyRGB and Bruce Lindbloom's tables: red 53.241/80.092/67.203, green
//    87.735/−86.183/83.179, blue 32.297/79.188/−107.860);
// 2. closed forms: equal images give 0; uniform images give the colour term alone (the filters
//    keep a constant, the feature detectors see nothing), worked out from the published CIELAB
//    values; the feature filters' normalisation and a step edge's response;
// 3. NVIDIA's reference implementation (NVlabs/flip, python/flip_api.py at commit 313517b, its
//    LDR-FLIP steps run with numpy 1.24, scipy.ndimage.correlate(mode="nearest") standing in
//    for OpenCV's filter2D with BORDER_REPLICATE, which does the same) on the four synthetic pairs
//    below, whose pixels are integer formulas, so both sides have the same bytes. The published
//    test images (images/reference.png and test.png, mean 0.159691) cannot be had in this
//    sandbox: no network beyond the package registries.
#include <algorithm>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "compare/flip.h"
#include "compare/flip_colour.h"

namespace whitted {
namespace {

using namespace flip;

LinearImage filled(int w, int h, glm::vec3 c) {
    return LinearImage{w, h, std::vector<glm::vec3>(std::size_t(w) * std::size_t(h), c), {}};
}

// --- 1. The colour pipeline ---

// FLIP's matrix (its reference implementation's rational constants) is within 2e-4 of the one
// derived from the sRGB primaries and D65, (x, y) = (0.3127, 0.3290); its rows sum to its white.
TEST(FlipColour, MatrixIsTheOneOfTheSrgbPrimariesAndD65) {
    // XYZ of a chromaticity (x, y) at Y = 1; the primaries scaled so that they add up to white.
    auto xyz = [](double x, double y) { return glm::dvec3(x / y, 1.0, (1.0 - x - y) / y); };
    const glm::dmat3 primaries(xyz(0.64, 0.33), xyz(0.30, 0.60), xyz(0.15, 0.06));
    const glm::dvec3 scale = glm::inverse(primaries) * xyz(0.3127, 0.3290);
    for (int c = 0; c < 3; ++c) {
        glm::dvec3 unit(0.0);
        unit[c] = 1.0;
        const glm::dvec3 expected = primaries[c] * scale[c], got = linear_rgb_to_xyz(unit);
        for (int r = 0; r < 3; ++r) EXPECT_NEAR(got[r], expected[r], 2e-4) << c << r;
    }
    const glm::dvec3 back = xyz_to_linear_rgb(linear_rgb_to_xyz({0.2, 0.5, 0.9}));
    EXPECT_NEAR(back.x, 0.2, 1e-12);
    EXPECT_NEAR(back.z, 0.9, 1e-12);
}

TEST(FlipColour, SrgbDecoding) {
    EXPECT_EQ(srgb_to_linear(0.0), 0.0);
    EXPECT_NEAR(srgb_to_linear(1.0), 1.0, 1e-15);
    EXPECT_NEAR(srgb_to_linear(0.04045), 0.04045 / 12.92, 1e-15);  // the linear segment
    EXPECT_NEAR(srgb_to_linear(0.5), 0.2140411, 1e-7);             // ((0.5 + 0.055) / 1.055)^2.4
}

TEST(FlipColour, YcxczOfWhiteAndBlack) {
    const glm::dvec3 white = xyz_to_ycxcz(linear_rgb_to_xyz(glm::dvec3(1.0)));
    EXPECT_NEAR(white.x, 100.0, 1e-12);
    EXPECT_NEAR(white.y, 0.0, 1e-12);
    EXPECT_NEAR(white.z, 0.0, 1e-12);
    EXPECT_EQ(xyz_to_ycxcz(glm::dvec3(0.0)), glm::dvec3(-16.0, 0.0, 0.0));
    const glm::dvec3 v(0.3, 0.2, 0.5), back = ycxcz_to_xyz(xyz_to_ycxcz(v));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(back[c], v[c], 1e-12);
    // White in the D65 matrix's own terms: X and Z of linear (1, 1, 1), the sums of its rows.
    EXPECT_NEAR(white_xyz().x, 0.950428545, 1e-9);
    EXPECT_NEAR(white_xyz().z, 1.088900371, 1e-9);
}

struct PublishedLab {
    glm::dvec3 rgb, lab;
};
const PublishedLab kRed{{1, 0, 0}, {53.241, 80.092, 67.203}};
const PublishedLab kGreen{{0, 1, 0}, {87.735, -86.183, 83.179}};
const PublishedLab kBlue{{0, 0, 1}, {32.297, 79.188, -107.860}};

// Published to three decimals with the IEC matrix; FLIP's differs in the fifth, which moves these
// by up to 0.006.
TEST(FlipColour, CielabOfThePrimariesAsPublished) {
    for (const PublishedLab& p : {kRed, kGreen, kBlue}) {
        const glm::dvec3 lab = xyz_to_lab(linear_rgb_to_xyz(p.rgb));
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(lab[c], p.lab[c], 0.01) << p.rgb.x << p.rgb.y << c;
    }
    const glm::dvec3 white = xyz_to_lab(white_xyz());
    EXPECT_NEAR(white.x, 100.0, 1e-12);
    EXPECT_EQ(xyz_to_lab(glm::dvec3(0.0)), glm::dvec3(0.0));
}

TEST(FlipColour, HuntAdjustmentAndHyab) {
    EXPECT_EQ(hunt_adjust({50.0, 20.0, -10.0}), glm::dvec3(50.0, 10.0, -5.0));
    EXPECT_EQ(hyab({10.0, 3.0, 0.0}, {4.0, 0.0, 4.0}), 6.0 + 5.0);  // |ΔL| + √(3² + 4²)
}

// cmax from the published CIELAB of green and blue.
double published_cmax() { return std::pow(hyab(hunt_adjust(kGreen.lab), hunt_adjust(kBlue.lab)), 0.7); }

TEST(FlipColour, CmaxAndTheMapToZeroOne) {
    EXPECT_NEAR(flip_cmax(), published_cmax(), 1e-3);
    EXPECT_NEAR(flip_cmax(), 41.2761, 1e-4);  // the reference implementation's, printed to float precision
    EXPECT_EQ(flip_colour_error(0.0), 0.0);
    const double knee = std::pow(0.4 * flip_cmax(), 1.0 / 0.7);  // ΔE whose ΔE^0.7 is 0.4·cmax
    EXPECT_NEAR(flip_colour_error(knee), 0.95, 1e-12);
    EXPECT_NEAR(flip_colour_error(knee / 2.0), 0.95 * std::pow(0.5, 0.7), 1e-12);  // linear in ΔE^0.7 below
    EXPECT_NEAR(flip_colour_error(std::pow(flip_cmax(), 1.0 / 0.7)), 1.0, 1e-12);
}

// --- 2. Closed forms ---

TEST(Flip, EqualImagesGiveZero) {
    LinearImage a = filled(20, 12, {0.2f, 0.5f, 0.9f});
    for (std::size_t i = 0; i < a.rgb.size(); ++i) a.rgb[i].x = float(i % 7) / 7.0f;
    const FlipResult r = compute_flip(a, a);
    EXPECT_EQ(r.mean, 0.0);
    EXPECT_EQ(r.max, 0.0);
    for (float e : r.error) EXPECT_EQ(e, 0.0f);
}

// Uniform images: the filtered images are the colours themselves and no feature differs, so every
// pixel's FLIP is the colour term of the two colours' HyAB distance in Hunt-adjusted CIELAB.
double uniform_flip(const glm::dvec3& lab_a, const glm::dvec3& lab_b) {
    const double e = std::pow(hyab(hunt_adjust(lab_a), hunt_adjust(lab_b)), 0.7), cmax = published_cmax();
    return e < 0.4 * cmax ? 0.95 / (0.4 * cmax) * e : 0.95 + (e - 0.4 * cmax) / (0.6 * cmax) * 0.05;
}

TEST(Flip, UniformBlackAgainstWhite) {
    const double expected = uniform_flip({0, 0, 0}, {100, 0, 0});  // 100^0.7 = 25.12 > 0.4·cmax: 0.9674
    EXPECT_NEAR(expected, 0.96738, 1e-5);
    const FlipResult r = compute_flip(filled(16, 16, glm::vec3(0.0f)), filled(16, 16, glm::vec3(1.0f)));
    for (float e : r.error) EXPECT_NEAR(e, expected, 1e-4);
    EXPECT_NEAR(r.mean, expected, 1e-4);
}

TEST(Flip, UniformRedAgainstGreen) {
    const FlipResult r = compute_flip(filled(16, 16, {1, 0, 0}), filled(16, 16, {0, 1, 0}));
    EXPECT_NEAR(r.mean, uniform_flip(kRed.lab, kGreen.lab), 1e-4);
    EXPECT_NEAR(r.mean, 0.986662, 1e-5);  // the reference implementation's
}

// FLIP sees the displayed image: values past 1 are white, and an sRGB grey of 0.5 is a dark colour
// against black only through the colour term (below the knee: linear in ΔE^0.7).
TEST(Flip, ClampedAndReadAsSrgb) {
    EXPECT_EQ(compute_flip(filled(8, 8, glm::vec3(3.0f)), filled(8, 8, glm::vec3(1.0f))).max, 0.0);
    const double lum = srgb_to_linear(0.5);  // Y of grey 0.5
    const double l_star = 116.0 * std::cbrt(lum) - 16.0;
    const FlipResult r = compute_flip(filled(12, 12, glm::vec3(0.5f)), filled(12, 12, glm::vec3(0.0f)));
    EXPECT_NEAR(r.mean, uniform_flip({l_star, 0, 0}, {0, 0, 0}), 1e-4);
}

TEST(Flip, Symmetric) {
    LinearImage a = filled(24, 16, {0.3f, 0.6f, 0.1f}), b = a;
    for (std::size_t i = 0; i < b.rgb.size(); i += 5) b.rgb[i] = {0.9f, 0.1f, 0.4f};
    const FlipResult ab = compute_flip(a, b), ba = compute_flip(b, a);
    EXPECT_EQ(ab.error, ba.error);
}

TEST(FlipFilters, FeatureKernelsAreNormalised) {
    const FeatureKernels k = feature_kernels(flip_default_pixels_per_degree());
    EXPECT_EQ(k.edge.radius, 9);  // ⌈3σ⌉, σ = 0.5 · 0.082° · 67.02 px/° = 2.748 px
    double gauss = 0, edge_pos = 0, edge_neg = 0, point_pos = 0, point_neg = 0;
    for (double w : k.gauss.weights) gauss += w;
    for (double w : k.edge.weights) (w > 0 ? edge_pos : edge_neg) += w;
    for (double w : k.point.weights) (w > 0 ? point_pos : point_neg) += w;
    EXPECT_NEAR(gauss, 1.0, 1e-15);
    EXPECT_NEAR(edge_pos, 1.0, 1e-15);
    EXPECT_NEAR(edge_neg, -1.0, 1e-15);
    EXPECT_NEAR(point_pos, 1.0, 1e-15);
    EXPECT_NEAR(point_neg, -1.0, 1e-15);
    EXPECT_GT(k.edge.weights[0], 0.0);   // −x·g: positive on the left
    EXPECT_LT(k.point.weights[9], 0.0);  // x²/σ² − 1 < 0 at the centre
    // The CSF filters: one radius, 3 standard deviations of the widest Gaussian (b = 0.04).
    for (int c = 0; c < 3; ++c) {
        const auto terms = csf_filter(c, flip_default_pixels_per_degree());
        ASSERT_EQ(terms.size(), c == 2 ? 2u : 1u);
        EXPECT_EQ(terms[0].g.radius, 10);
        double total = 0;
        for (const CsfTerm& t : terms) {
            double s = 0;
            for (double w : t.g.weights) s += w;
            total += t.scale * s * s;
        }
        EXPECT_NEAR(total, 1.0, 1e-12);
    }
}

// A step from 0 to 1 between columns 11 and 12: the edge filter's response is the whole of its
// negative half (−1) on both columns beside the step and 0 beyond its radius; nothing along y.
TEST(FlipFilters, StepEdgeResponse) {
    const FeatureKernels k = feature_kernels(flip_default_pixels_per_degree());
    const int w = 40, h = 6;
    std::vector<float> step(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 12; x < w; ++x) step[std::size_t(y * w + x)] = 1.0f;
    const std::vector<float> along_x = filter_separable(step, w, h, k.edge, k.gauss);
    const std::vector<float> along_y = filter_separable(step, w, h, k.gauss, k.edge);
    for (int y = 0; y < h; ++y) {
        EXPECT_NEAR(along_x[std::size_t(y * w + 11)], -1.0f, 1e-6);
        EXPECT_NEAR(along_x[std::size_t(y * w + 12)], -1.0f, 1e-6);
        EXPECT_NEAR(along_x[std::size_t(y * w + 1)], 0.0f, 1e-6);   // 11 columns from the step
        EXPECT_NEAR(along_x[std::size_t(y * w + 22)], 0.0f, 1e-6);  // 10 columns: past the radius
        for (int x = 0; x < w; ++x) EXPECT_NEAR(along_y[std::size_t(y * w + x)], 0.0f, 1e-6);
    }
}

// --- 3. Against NVIDIA's reference implementation ---

// The pairs, 48 × 32, as 8-bit values from integer formulas (the same in the Python harness).
constexpr int W = 48, H = 32;
using Formula = std::function<glm::ivec3(int, int)>;

LinearImage bytes_image(const Formula& f) {
    LinearImage im = filled(W, H, glm::vec3(0.0f));
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) im.rgb[std::size_t(y * W + x)] = glm::vec3(f(x, y)) / 255.0f;
    return im;
}

glm::ivec3 gradient(int x, int y) { return {x * 255 / (W - 1), y * 255 / (H - 1), 128}; }

struct ReferencePair {
    const char* name;
    Formula a, b;
    double mean, max;
    int max_x, max_y;
    double at_10_10, at_5_20;  // the error at pixels 10,10 and 5,20
};

std::vector<ReferencePair> reference_pairs() {
    auto step_at = [](int e) { return Formula([e](int x, int) { return glm::ivec3(x < e ? 40 : 220); }); };
    auto checker = [](int n) { return Formula([n](int x, int y) { return glm::ivec3((x / n + y / n) % 2 ? 0 : 255); }); };
    const Formula patched = [](int x, int y) {
        glm::ivec3 c = gradient(x, y);
        if (x >= 10 && x < 30 && y >= 8 && y < 20) c.z = 200;
        return c;
    };
    const Formula noisy = [](int x, int y) {
        glm::ivec3 c = gradient(x, y);
        for (int k = 0; k < 3; ++k) c[k] = std::clamp(c[k] + (x * 37 + y * 91 + k * 13) % 23 - 11, 0, 255);
        return c;
    };
    // name, A, B, then the reference implementation's mean, max, where, and two pixels.
    return {
        {"colour", gradient, patched, 0.128399059176445, 0.5737259984016418, 18, 16, 0.4118195176124573, 0.05280717462301254},
        {"edge", step_at(24), step_at(26), 0.08973312377929688, 0.8843244314193726, -1, -1, 0.0, 0.0},
        {"noise", gradient, noisy, 0.049798741936683655, 0.2067626416683197, 47, 29, 0.012212876230478287, 0.026292789727449417},
        {"checker", checker(4), checker(2), 0.46051374077796936, 0.9752576947212219, 46, 0, 0.5140814185142517, 0.2914479076862335},
    };
}

TEST(Flip, MatchesTheReferenceImplementation) {
    for (const ReferencePair& p : reference_pairs()) {
        const FlipResult r = compute_flip(bytes_image(p.a), bytes_image(p.b));
        // The reference computes in float32 (numpy), whitted's filters accumulate in double.
        EXPECT_NEAR(r.mean, p.mean, 2e-5) << p.name;
        EXPECT_NEAR(r.max, p.max, 2e-5) << p.name;
        if (p.max_x >= 0) {  // on the vertical step every row ties
            EXPECT_EQ(r.max_x, p.max_x) << p.name;
            EXPECT_EQ(r.max_y, p.max_y) << p.name;
        }
        EXPECT_NEAR(r.error[std::size_t(10 * W + 10)], p.at_10_10, 2e-5) << p.name;
        EXPECT_NEAR(r.error[std::size_t(20 * W + 5)], p.at_5_20, 2e-5) << p.name;
    }
}

// A viewer further away (more pixels per degree) sees less of fine noise.
TEST(Flip, FartherAwayNoiseMattersLess) {
    const ReferencePair p = reference_pairs()[2];
    FlipOptions far;
    far.pixels_per_degree = 200.0;
    EXPECT_LT(compute_flip(bytes_image(p.a), bytes_image(p.b), far).mean, p.mean - 0.005);
}

}  // namespace
}  // namespace whitted
