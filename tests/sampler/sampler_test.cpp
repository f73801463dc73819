// The sampler: a pure function of (pixel, sample index, dimension), stratified as a (0, 2)-net,
// the centre for one sample, cells for anti-aliasing; and the warps built on it.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>

#include <gtest/gtest.h>

#include "sampler/sampler.h"
#include "sampler/warp.h"

namespace whitted {
namespace {

TEST(Sampler, OneSamplePerPixelIsEveryCentre) {
    const Sampler one(1, 1);
    ASSERT_TRUE(one.centred());
    for (std::uint32_t dim : {dimension::kLens, dimension::light(0, 3), dimension::gloss_reflect(2)}) {
        EXPECT_EQ(one.get2d({5, 7, 0}, dim), glm::vec2(0.5f));
    }
    EXPECT_EQ(one.pixel_offset({5, 7, 0}), glm::vec2(0.5f));
}

TEST(Sampler, AntiAliasingCellsAreTheRegularGridWithOneSampleEach) {
    // aa = 3, spp = 1: sample s at the centre of cell s mod 9, row by row (the old --aa grid).
    const Sampler s(3, 1);
    for (std::uint32_t i = 0; i < 9; ++i) {
        const glm::vec2 o = s.pixel_offset({0, 0, i});
        EXPECT_FLOAT_EQ(o.x, (float(i % 3) + 0.5f) / 3.0f) << i;
        EXPECT_FLOAT_EQ(o.y, (float(i / 3) + 0.5f) / 3.0f) << i;
    }
    // aa = 2, spp = 8: every sample stays in its cell; each cell gets its 8.
    const Sampler t(2, 8);
    int per_cell[4] = {};
    for (std::uint32_t i = 0; i < 32; ++i) {
        const glm::vec2 o = t.pixel_offset({3, 4, i});
        const int cx = int(o.x * 2.0f), cy = int(o.y * 2.0f);
        EXPECT_EQ(cy * 2 + cx, int(i % 4)) << i;
        ++per_cell[cy * 2 + cx];
    }
    for (int c : per_cell) EXPECT_EQ(c, 8);
}

TEST(Sampler, IsAPureFunctionOfPixelIndexAndDimension) {
    const Sampler a(1, 64), b(1, 64);
    for (std::uint32_t i = 0; i < 64; ++i) EXPECT_EQ(a.get2d({9, 2, i}, 5), b.get2d({9, 2, i}, 5));
    // Other pixels, dimensions and seeds give other values.
    EXPECT_NE(a.get2d({9, 2, 0}, 5), a.get2d({9, 3, 0}, 5));
    EXPECT_NE(a.get2d({9, 2, 0}, 5), a.get2d({10, 2, 0}, 5));  // neighbours in a row differ too
    EXPECT_NE(a.pixel_offset({9, 2, 3}), a.pixel_offset({10, 2, 3}));
    EXPECT_NE(a.get2d({9, 2, 0}, 5), a.get2d({9, 2, 0}, 6));
    EXPECT_NE(a.get2d({9, 2, 0}, 5), Sampler(1, 64, 1).get2d({9, 2, 0}, 5));
}

// The sequence as it is defined (Burley 2020: an Owen-scrambled index, the first two Sobol
// dimensions, each Owen-scrambled), written the plain way: each scramble between two bit
// reversals, the second dimension's matrix applied bit by bit. The sampler computes it otherwise
// (reversals that cancel left out, the matrix a byte at a time); its values must be these, bit for
// bit: every image made before depends on them.
namespace reference {
std::uint64_t mix64(std::uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ull;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebull;
    v ^= v >> 31;
    return v;
}
std::uint32_t reverse(std::uint32_t v) {
    std::uint32_t r = 0;
    for (int b = 0; b < 32; ++b) r |= ((v >> b) & 1u) << (31 - b);
    return r;
}
std::uint32_t sobol_dim1(std::uint32_t i) {  // polynomial x + 1: m_k = 2 m_{k-1} xor m_{k-1}
    std::uint32_t v = 0, m = 1;
    for (int k = 0; k < 32; ++k, m = (m << 1) ^ m)
        if ((i >> k) & 1) v ^= m << (31 - k);
    return v;
}
std::uint32_t owen(std::uint32_t v, std::uint32_t seed) {
    v = reverse(v);
    v ^= v * 0x3d20adeau;
    v += seed;
    v *= (seed >> 16) | 1u;
    v ^= v * 0x05526c56u;
    v ^= v * 0x53a22864u;
    return reverse(v);
}
float unit(std::uint32_t v) { return std::min(float(v) * 0x1p-32f, 0x1.fffffep-1f); }
glm::vec2 get2d(const SampleKey& key, std::uint32_t dim, std::uint32_t seed) {
    const std::uint64_t h = mix64((std::uint64_t(key.x) << 32 | key.y) ^ mix64(std::uint64_t(dim) << 32 | seed));
    const std::uint32_t i = owen(key.index, std::uint32_t(h));
    return {unit(owen(reverse(i), std::uint32_t(h >> 32))), unit(owen(sobol_dim1(i), std::uint32_t(mix64(h))))};
}
}  // namespace reference

TEST(Sampler, IsTheScrambledSobolSequenceBitForBit) {
    std::uint64_t state = 12345;
    auto next = [&] { return std::uint32_t((state = reference::mix64(state + 0x9e3779b97f4a7c15ull)) >> 7); };
    for (std::uint32_t seed : {0u, 7u}) {
        const Sampler s(1, 4096, seed);
        for (int n = 0; n < 20000; ++n) {
            // Small indices (the usual), and any 32-bit ones (the matrix's every byte).
            const SampleKey key{next() % 2048, next() % 2048, n % 2 ? next() % 4096 : next()};
            const std::uint32_t dim = next() % 200;
            ASSERT_EQ(s.get2d(key, dim), reference::get2d(key, dim, seed)) << key.x << " " << key.y << " " << key.index;
        }
        for (std::uint32_t i = 0; i < 4096; ++i)
            ASSERT_EQ(s.pixel_offset({3, 5, i}), reference::get2d({3, 5, i}, dimension::kFilm, seed)) << i;
    }
}

// Four dimensions asked at once (a path vertex's; AVX2 where the CPU has it) are the bits of the
// plain definition, for any index and dimension, and the centre for one sample per pixel.
TEST(Sampler, FourDimensionsAtOnceAreTheSequenceBitForBit) {
    std::uint64_t state = 999;
    auto next = [&] { return std::uint32_t((state = reference::mix64(state + 0x9e3779b97f4a7c15ull)) >> 3); };
    for (std::uint32_t seed : {0u, 11u}) {
        const Sampler s(1, 4096, seed);
        for (int n = 0; n < 20000; ++n) {
            const SampleKey key{next() % 4096, next() % 4096, n % 2 ? next() % 4096 : next()};
            const int bounce = int(next() % 64);
            const std::uint32_t dims[4] = {dimension::path(bounce, dimension::kPathChoice), next(),
                                           dimension::path(bounce, dimension::kPathLobe), next() % 300};
            glm::vec2 out[4];
            s.get2d(key, dims, out);
            for (int d = 0; d < 4; ++d)
                ASSERT_EQ(out[d], reference::get2d(key, dims[d], seed)) << key.index << " dim " << dims[d];
        }
    }
    const std::uint32_t dims[4] = {1, 2, 3, 4};
    glm::vec2 out[4];
    Sampler(1, 1).get2d({2, 3, 0}, dims, out);
    for (const glm::vec2& o : out) EXPECT_EQ(o, glm::vec2(0.5f));
}

// The points of a pixel's 2^m samples in any dimension form a (0, m, 2)-net: every elementary
// box of area 2^-m (2^a × 2^(m−a) of them, for every a) holds exactly one point. That is what
// stratification means here, and it holds for every pixel and dimension (the scramble and the
// permutation keep it).
TEST(Sampler, EachDimensionIsAZeroMTwoNet) {
    for (int m : {2, 4, 6, 8}) {
        const std::uint32_t n = 1u << m;
        const Sampler s(1, int(n));
        for (std::uint32_t dim : {dimension::kLens, dimension::light(0, 0), dimension::light(3, 7),
                                  dimension::gloss_refract(1)})
            for (std::uint32_t px : {0u, 17u, 1000u}) {
                std::vector<glm::vec2> pts;
                for (std::uint32_t i = 0; i < n; ++i) {
                    pts.push_back(s.get2d({px, 3, i}, dim));
                    ASSERT_GE(pts.back().x, 0.0f);
                    ASSERT_LT(pts.back().x, 1.0f);
                    ASSERT_GE(pts.back().y, 0.0f);
                    ASSERT_LT(pts.back().y, 1.0f);
                }
                for (int a = 0; a <= m; ++a) {
                    const int nx = 1 << a, ny = 1 << (m - a);
                    std::set<int> boxes;
                    for (const glm::vec2& p : pts) boxes.insert(int(p.y * float(ny)) * nx + int(p.x * float(nx)));
                    ASSERT_EQ(boxes.size(), n) << "m " << m << " a " << a << " dim " << dim << " pixel " << px;
                }
            }
    }
}

// Progressive: every power-of-two prefix of a pixel's samples is a (0, m, 2)-net too, and the first
// N samples of a render with more are those of an N-sample render (a time budget or a converged
// pixel stops after N: the image is an N-sample image, not a badly stratified part of a bigger one).
TEST(Sampler, EveryPowerOfTwoPrefixIsANetAndIndependentOfTheTotal) {
    const Sampler big(1, 1024), small(1, 32);
    for (std::uint32_t dim : {dimension::kLens, dimension::light(1, 2), dimension::path(3, dimension::kPathDirection)})
        for (std::uint32_t px : {0u, 5u, 777u}) {
            for (int m = 1; m <= 10; ++m) {
                const std::uint32_t n = 1u << m;
                for (int a = 0; a <= m; ++a) {
                    const int nx = 1 << a, ny = 1 << (m - a);
                    std::set<int> boxes;
                    for (std::uint32_t i = 0; i < n; ++i) {
                        const glm::vec2 p = big.get2d({px, 9, i}, dim);
                        boxes.insert(int(p.y * float(ny)) * nx + int(p.x * float(nx)));
                    }
                    ASSERT_EQ(boxes.size(), n) << "prefix " << n << " a " << a << " dim " << dim << " pixel " << px;
                }
            }
            for (std::uint32_t i = 0; i < 32; ++i) {
                EXPECT_EQ(big.get2d({px, 9, i}, dim), small.get2d({px, 9, i}, dim)) << "sample " << i;
                EXPECT_EQ(big.pixel_offset({px, 9, i}), small.pixel_offset({px, 9, i})) << "sample " << i;
            }
        }
}

TEST(Sampler, PixelPositionsWithinACellAreStratifiedToo) {
    const Sampler s(1, 16);
    std::set<int> boxes;
    for (std::uint32_t i = 0; i < 16; ++i) {
        const glm::vec2 o = s.pixel_offset({4, 4, i});
        boxes.insert(int(o.y * 4.0f) * 4 + int(o.x * 4.0f));
    }
    EXPECT_EQ(boxes.size(), 16u);
}

TEST(Warp, ConcentricDiscIsUniformAndKeepsTheCentre) {
    EXPECT_EQ(concentric_disc({0.5f, 0.5f}), glm::vec2(0.0f));
    // The corners of the square go to the rim; an area-preserving map sends a fraction q of the
    // square's area (a centred sub-square) to a disc of radius sqrt(q).
    EXPECT_NEAR(glm::length(concentric_disc({0.0f, 0.0f})), 1.0f, 1e-6f);
    EXPECT_NEAR(glm::length(concentric_disc({0.75f, 0.5f})), 0.5f, 1e-6f);
    // Mean of r² over the uniform disc is 1/2; of x and y, 0. Midpoint quadrature of the map.
    const int k = 400;
    double r2 = 0, mx = 0;
    for (int i = 0; i < k; ++i)
        for (int j = 0; j < k; ++j) {
            const glm::vec2 d = concentric_disc({(float(i) + 0.5f) / k, (float(j) + 0.5f) / k});
            ASSERT_LE(glm::length(d), 1.0f + 1e-6f);
            r2 += double(glm::dot(d, d));
            mx += double(d.x);
        }
    EXPECT_NEAR(r2 / (k * k), 0.5, 1e-4);
    EXPECT_NEAR(mx / (k * k), 0.0, 1e-6);
}

// Glossy directions: the cos^e lobe around the ideal direction has E[cos α] = (e+1)/(e+2) and
// E[cos² α] = (e+1)/(e+3); its mean direction is the axis times E[cos α]. Checked with the
// sampler's own stratified points, the tolerance 4 standard errors of the plain Monte Carlo
// mean for that many samples (stratification only makes the error smaller).
TEST(Warp, GlossyLobeHasTheMomentsOfCosPowerE) {
    const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -0.5f, 0.8f));
    const int n = 4096;
    const Sampler s(1, n);
    for (float e : {1.0f, 10.0f, 100.0f, 1000.0f}) {
        const double m1 = (e + 1.0) / (e + 2.0), m2 = (e + 1.0) / (e + 3.0);
        const double sd = std::sqrt(m2 - m1 * m1), tol = 4.0 * sd / std::sqrt(double(n));
        double c1 = 0, c2 = 0;
        glm::dvec3 mean(0.0);
        for (int i = 0; i < n; ++i) {
            const glm::vec3 d = cosine_power_lobe(axis, e, s.get2d({1, 1, std::uint32_t(i)}, 9));
            ASSERT_NEAR(glm::length(d), 1.0f, 1e-5f);
            const double c = glm::dot(d, axis);
            ASSERT_GT(c, -1e-6);
            c1 += c;
            c2 += c * c;
            mean += glm::dvec3(d);
        }
        c1 /= n;
        c2 /= n;
        mean /= double(n);
        EXPECT_NEAR(c1, m1, tol) << "e " << e;
        const double m4 = (e + 1.0) / (e + 5.0);  // E[cos⁴ α], for the spread of cos² α
        EXPECT_NEAR(c2, m2, 4.0 * std::sqrt(m4 - m2 * m2) / std::sqrt(double(n))) << "e " << e;
        // The mean direction: along the axis, the sideways parts cancel (total variance 1 − m1²).
        const glm::dvec3 along = glm::dvec3(axis) * m1;
        EXPECT_NEAR(glm::length(mean - along), 0.0, 4.0 * std::sqrt(1.0 - m1 * m1) / std::sqrt(double(n)))
            << "e " << e;
    }
}

TEST(Warp, UniformConeFillsTheConeEvenly) {
    // Uniform over the cap's solid angle: cos θ uniform on [cos_max, 1], mean (1 + cos_max)/2.
    const glm::vec3 axis(0, -1, 0);
    const float cos_max = std::cos(0.2f);
    const int n = 1024;
    const Sampler s(1, n);
    double c1 = 0;
    for (int i = 0; i < n; ++i) {
        const glm::vec3 d = uniform_cone(axis, cos_max, s.get2d({0, 0, std::uint32_t(i)}, 4));
        const float c = glm::dot(d, axis);
        ASSERT_GE(c, cos_max - 1e-6f);
        c1 += c;
    }
    const double sd = (1.0 - cos_max) / std::sqrt(12.0);
    EXPECT_NEAR(c1 / n, (1.0 + cos_max) / 2.0, 4.0 * sd / std::sqrt(double(n)));
}

}  // namespace
}  // namespace whitted
