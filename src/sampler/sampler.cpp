#include "sampler/sampler.h"

#include <algorithm>
#include <array>

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define WHITTED_SAMPLER_AVX2 1
#endif

namespace whitted {
namespace {

std::uint64_t mix64(std::uint64_t v) {  // splitmix64's finaliser
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ull;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebull;
    v ^= v >> 31;
    return v;
}

std::uint64_t hash(const SampleKey& key, std::uint32_t dim, std::uint32_t seed) {
    return mix64((std::uint64_t(key.x) << 32 | key.y) ^ mix64(std::uint64_t(dim) << 32 | seed));
}

constexpr std::uint32_t reverse_bits(std::uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// The generator matrix of the Sobol sequence's second dimension (primitive polynomial x + 1,
// m_k = 2·m_{k-1} xor m_{k-1}): column k is m_{k+1} in the top bits. The first is the identity
// (bit reversal: the van der Corput sequence).
constexpr std::array<std::uint32_t, 32> kSobolDim1 = [] {
    std::array<std::uint32_t, 32> c{};
    std::uint32_t m = 1;
    for (int k = 0; k < 32; ++k) {
        c[std::size_t(k)] = m << (31 - k);
        m = (m << 1) ^ m;
    }
    return c;
}();

// The second dimension with the bit order of its input and output reversed, v ↦
// reverse(D · reverse(v)), a byte of v at a time: table b holds the image of every value of byte b.
// (D applied bit by bit branches on each of the index's 32 scrambled bits: a fifth of a path
// tracer's time went to mispredicting them.)
constexpr std::array<std::array<std::uint32_t, 256>, 4> kSobolDim1Reversed = [] {
    std::array<std::array<std::uint32_t, 256>, 4> t{};
    for (int b = 0; b < 4; ++b)
        for (int v = 0; v < 256; ++v)
            for (int bit = 0; bit < 8; ++bit)
                if ((v >> bit) & 1) t[std::size_t(b)][std::size_t(v)] ^= reverse_bits(kSobolDim1[std::size_t(31 - (8 * b + bit))]);
    return t;
}();

std::uint32_t sobol_dim1_reversed(std::uint32_t v) {
    return kSobolDim1Reversed[0][v & 0xffu] ^ kSobolDim1Reversed[1][(v >> 8) & 0xffu] ^
           kSobolDim1Reversed[2][(v >> 16) & 0xffu] ^ kSobolDim1Reversed[3][v >> 24];
}

// Nested uniform scrambling approximated by a hash that only carries bits from less to more
// significant positions of the reversed value (Laine and Karras 2011; pbrt-v4's FastOwenScrambler):
// the scramble of v is reverse(owen_hash(reverse(v))).
std::uint32_t owen_hash(std::uint32_t v, std::uint32_t seed) {
    v ^= v * 0x3d20adeau;
    v += seed;
    v *= (seed >> 16) | 1u;
    v ^= v * 0x05526c56u;
    v ^= v * 0x53a22864u;
    return v;
}

float to_unit(std::uint32_t v) { return std::min(float(v) * 0x1p-32f, 0x1.fffffep-1f); }

// Point `index` of the scrambled, shuffled 2-D Sobol sequence seeded by `h`. The index is shuffled
// by an Owen scramble of its own (Burley 2020, "Practical Hash-based Owen Scrambling"), which maps
// every aligned block of 2^k indices onto an aligned block of 2^k points: any power-of-two prefix
// of a pixel's samples is stratified, and the first N samples are the same whatever the total, so
// a render stopped after N samples (a time budget, a pixel that converged) is an N-sample render.
// With i the shuffled index, x is scramble(reverse(i)) and y scramble(D · i); written with the
// reversals that cancel left out (j = reverse(i)).
glm::vec2 sobol_2d(std::uint32_t index, std::uint64_t h) {
    const std::uint64_t h2 = mix64(h);  // the second coordinate's scramble, independent of the first's
    const std::uint32_t j = owen_hash(reverse_bits(index), std::uint32_t(h));
    return {to_unit(reverse_bits(owen_hash(reverse_bits(j), std::uint32_t(h >> 32)))),
            to_unit(reverse_bits(owen_hash(sobol_dim1_reversed(j), std::uint32_t(h2))))};
}

#ifdef WHITTED_SAMPLER_AVX2
// sobol_2d for four seeds at once: lanes 2d and 2d + 1 hold dimension d's x and y. The same
// operations on the same bits, with the second dimension's matrix written without tables: D is
// Pascal's triangle mod 2, and reverse(D · reverse(v)) is reverse(zeta(v)), where zeta xors into
// each bit position the bits of the positions whose index is a subset of its own (one shift per
// index bit).
struct Avx2Sobol {
    [[gnu::target("avx2")]] static __m256i reverse(__m256i v) {
        const __m256i bytes = _mm256_setr_epi8(3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12,
                                               3, 2, 1, 0, 7, 6, 5, 4, 11, 10, 9, 8, 15, 14, 13, 12);
        // A nibble reversed, and reversed and moved up.
        const __m256i low = _mm256_setr_epi8(0, 8, 4, 12, 2, 10, 6, 14, 1, 9, 5, 13, 3, 11, 7, 15,
                                             0, 8, 4, 12, 2, 10, 6, 14, 1, 9, 5, 13, 3, 11, 7, 15);
        const __m256i high = _mm256_slli_epi16(low, 4);
        const __m256i nibble = _mm256_set1_epi8(0x0f);
        v = _mm256_shuffle_epi8(v, bytes);
        const __m256i lo = _mm256_and_si256(v, nibble), hi = _mm256_and_si256(_mm256_srli_epi16(v, 4), nibble);
        return _mm256_or_si256(_mm256_shuffle_epi8(high, lo), _mm256_shuffle_epi8(low, hi));
    }
    [[gnu::target("avx2")]] static __m256i mul(__m256i v, std::uint32_t c) {
        return _mm256_mullo_epi32(v, _mm256_set1_epi32(int(c)));
    }
    [[gnu::target("avx2")]] static __m256i owen_hash(__m256i v, __m256i seed) {
        v = _mm256_xor_si256(v, mul(v, 0x3d20adeau));
        v = _mm256_add_epi32(v, seed);
        v = _mm256_mullo_epi32(v, _mm256_or_si256(_mm256_srli_epi32(seed, 16), _mm256_set1_epi32(1)));
        v = _mm256_xor_si256(v, mul(v, 0x05526c56u));
        return _mm256_xor_si256(v, mul(v, 0x53a22864u));
    }
    [[gnu::target("avx2")]] static __m256i zeta(__m256i v) {
        v = _mm256_xor_si256(v, _mm256_slli_epi32(_mm256_and_si256(v, _mm256_set1_epi32(0x55555555)), 1));
        v = _mm256_xor_si256(v, _mm256_slli_epi32(_mm256_and_si256(v, _mm256_set1_epi32(0x33333333)), 2));
        v = _mm256_xor_si256(v, _mm256_slli_epi32(_mm256_and_si256(v, _mm256_set1_epi32(0x0f0f0f0f)), 4));
        v = _mm256_xor_si256(v, _mm256_slli_epi32(_mm256_and_si256(v, _mm256_set1_epi32(0x00ff00ff)), 8));
        return _mm256_xor_si256(v, _mm256_slli_epi32(v, 16));
    }
    // to_unit: float(v) rounded once, as the two exact halves summed (16 bits each).
    [[gnu::target("avx2")]] static __m256 to_unit(__m256i v) {
        const __m256 hi = _mm256_cvtepi32_ps(_mm256_srli_epi32(v, 16));
        const __m256 lo = _mm256_cvtepi32_ps(_mm256_and_si256(v, _mm256_set1_epi32(0xffff)));
        const __m256 f = _mm256_add_ps(_mm256_mul_ps(hi, _mm256_set1_ps(65536.0f)), lo);
        return _mm256_min_ps(_mm256_mul_ps(f, _mm256_set1_ps(0x1p-32f)), _mm256_set1_ps(0x1.fffffep-1f));
    }
    [[gnu::target("avx2")]] static void run(std::uint32_t index, const std::uint64_t (&h)[4], glm::vec2 (&out)[4]) {
        alignas(32) std::uint32_t shuffle[8], scramble[8];
        for (int d = 0; d < 4; ++d) {
            shuffle[2 * d] = shuffle[2 * d + 1] = std::uint32_t(h[d]);
            scramble[2 * d] = std::uint32_t(h[d] >> 32);
            scramble[2 * d + 1] = std::uint32_t(mix64(h[d]));
        }
        const __m256i j = owen_hash(_mm256_set1_epi32(int(reverse_bits(index))),
                                    _mm256_load_si256(reinterpret_cast<const __m256i*>(shuffle)));
        const __m256i v = reverse(_mm256_blend_epi32(j, zeta(j), 0xaa));  // x: reverse(j); y: D applied
        const __m256i s = owen_hash(v, _mm256_load_si256(reinterpret_cast<const __m256i*>(scramble)));
        alignas(32) float f[8];
        _mm256_store_ps(f, to_unit(reverse(s)));
        for (int d = 0; d < 4; ++d) out[d] = {f[2 * d], f[2 * d + 1]};
    }
};
#endif

}  // namespace

Sampler::Sampler(int aa, int spp, std::uint32_t seed)
    : aa_(std::clamp(aa, 1, kMaxAa)), spp_(std::clamp(spp, 1, kMaxSpp)), seed_(seed) {}

glm::vec2 Sampler::pixel_offset(const SampleKey& key) const {
    const int cells = aa_ * aa_;
    const int cell = int(key.index % std::uint32_t(cells));
    glm::vec2 in_cell(0.5f);
    if (spp_ > 1) in_cell = sobol_2d(key.index / std::uint32_t(cells), hash(key, dimension::kFilm, seed_));
    const float step = 1.0f / float(aa_);
    return {(float(cell % aa_) + in_cell.x) * step, (float(cell / aa_) + in_cell.y) * step};
}

glm::vec2 Sampler::get2d(const SampleKey& key, std::uint32_t dim) const {
    if (centred()) return glm::vec2(0.5f);
    return sobol_2d(key.index, hash(key, dim, seed_));
}

void Sampler::get2d(const SampleKey& key, const std::uint32_t (&dims)[4], glm::vec2 (&out)[4]) const {
#ifdef WHITTED_SAMPLER_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2 && !centred()) {
        const std::uint64_t h[4] = {hash(key, dims[0], seed_), hash(key, dims[1], seed_), hash(key, dims[2], seed_),
                                    hash(key, dims[3], seed_)};
        Avx2Sobol::run(key.index, h, out);
        return;
    }
#endif
    for (int d = 0; d < 4; ++d) out[d] = get2d(key, dims[d]);
}

}  // namespace whitted
