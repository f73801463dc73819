#pragma once
// The render's source of sample values: a pure function of (pixel, sample index, dimension) to
// [0, 1)², so a pixel's samples are the same for any tiling, thread count, machine or run, and
// any range of sample indices can be rendered on its own (a viewer pass, another MPI rank).
//
// Each dimension is a pair of coordinates of the Sobol (0, 2)-sequence, Owen-scrambled (Laine
// and Karras' hash, as pbrt-v4's FastOwenScrambler) and with the sample index shuffled by an Owen
// scramble of its own (Burley 2020), both seeded by a hash of the pixel and the dimension. Every
// pair of coordinates is stratified over any power-of-two prefix of a pixel's samples, pairs are
// independent of one another, and a sample's values do not depend on how many samples the pixel
// gets: the first N samples of any render are those of an N-sample render (spp > 1).
//
// A pixel's n = aa² · spp samples: sample s lies in sub-pixel cell s mod aa² of an aa × aa grid
// (row by row), at the cell's centre when spp = 1 (the regular anti-aliasing grid) or at a
// stratified point of it otherwise. With n = 1 every dimension is the centre (0.5, 0.5): the pixel
// centre, the lens centre, the light centre (scene-format.md §9.1).
#include <cstdint>

#include <glm/glm.hpp>

namespace whitted {

struct SampleKey {
    std::uint32_t x = 0, y = 0;  // the pixel
    std::uint32_t index = 0;     // which of its samples, in [0, samples_per_pixel)
};

// The fixed dimension layout: which effect reads which dimension (the numbers are labels, hashed
// into the scramble's seed, so they need not be dense).
namespace dimension {
constexpr std::uint32_t kFilm = 0;  // the point in the pixel (read through Sampler::pixel_offset)
constexpr std::uint32_t kLens = 1;  // the point on the lens
constexpr std::uint32_t kTime = 2;  // where in the shutter interval (motion blur): its first coordinate
// At recursion depth `depth`: the point on light `light` (disc or cone), and the glossy direction
// of the reflected and of the refracted ray.
inline std::uint32_t light(int depth, std::uint32_t light) { return 16u + std::uint32_t(depth) * 0x10000u + 2u + light; }
inline std::uint32_t gloss_reflect(int depth) { return 16u + std::uint32_t(depth) * 0x10000u; }
inline std::uint32_t gloss_refract(int depth) { return 16u + std::uint32_t(depth) * 0x10000u + 1u; }
// The path tracer, at bounce `bounce`: which light and Russian roulette; the point on the light;
// which BSDF lobe; the BSDF direction; which triangle of an emissive mesh (§9.3).
inline std::uint32_t path(int bounce, std::uint32_t slot) { return 0x80000000u + std::uint32_t(bounce) * 8u + slot; }
constexpr std::uint32_t kPathChoice = 0, kPathLightPoint = 1, kPathLobe = 2, kPathDirection = 3, kPathLightTriangle = 4;
}  // namespace dimension

class Sampler {
public:
    static constexpr int kMaxAa = 16;       // aa × aa cells: 256 at the most
    static constexpr int kMaxSpp = 1 << 16;

    // aa in [1, kMaxAa], spp in [1, kMaxSpp] (clamped); seed changes every value.
    explicit Sampler(int aa = 1, int spp = 1, std::uint32_t seed = 0);

    int aa() const { return aa_; }
    int spp() const { return spp_; }
    int samples_per_pixel() const { return aa_ * aa_ * spp_; }
    // One sample per pixel: every dimension is the centre.
    bool centred() const { return samples_per_pixel() == 1; }

    // Where in its pixel sample `key` lies: the offset from the pixel's top-left corner, in [0, 1)².
    glm::vec2 pixel_offset(const SampleKey& key) const;
    // The value of dimension `dim` for sample `key`, in [0, 1)².
    glm::vec2 get2d(const SampleKey& key, std::uint32_t dim) const;
    // Four dimensions of one sample: the values get2d gives each, found side by side (eight
    // coordinates in one AVX2 register where the CPU has it), for a path vertex's four.
    void get2d(const SampleKey& key, const std::uint32_t (&dims)[4], glm::vec2 (&out)[4]) const;

private:
    int aa_, spp_;
    std::uint32_t seed_;
};

}  // namespace whitted
