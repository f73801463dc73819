#pragma once
// SSIM over blocks, the check SPEC CPU's povray benchmark makes (every 8×8 block above 0.996).
//
// The formula is Wang, Bovik, Sheikh and Simoncelli, "Image quality assessment: from error
// visibility to structural similarity" (IEEE TIP 2004), eq. (13):
//   SSIM = (2·μa·μb + C1)(2·σab + C2) / ((μa² + μb² + C1)(σa² + σb² + C2)),
//   C1 = (0.01·L)², C2 = (0.03·L)², L = 1 (the range of the values),
// with μ, σ², σab the mean, variance and covariance of the block's values taken with equal weights
// 1/N (eqs. 14–16 with w_i = 1/N). It is computed on each of R, G and B separately, on the values
// clamped to [0, 1] (what an 8-bit image shows), and a block's SSIM is the mean of the three.
// Blocks tile the image from its top-left corner; at the right and bottom edges of an image
// whose sides are not multiples of the block size the blocks are smaller, so every pixel counts.
#include <cstddef>
#include <vector>

#include "film/image.h"

namespace whitted {

struct SsimOptions {
    int block = 8;
    double threshold = 0.996;  // SPEC's: a block passes when its SSIM is above this
};

struct SsimBlock {
    int x = 0, y = 0, width = 0, height = 0;  // the block's pixels [x, x + width) × [y, y + height)
    double ssim = 1.0;
};

struct SsimStats {
    double mean = 1.0;             // over the blocks
    SsimBlock worst;               // the lowest SSIM (the first in row order if several)
    std::size_t blocks = 0;
    std::size_t blocks_failing = 0;  // SSIM ≤ threshold
    int blocks_across = 0, blocks_down = 0;
    std::vector<double> block_ssim;  // row-major, blocks_across × blocks_down
};

SsimStats compute_ssim(const LinearImage& a, const LinearImage& b, const SsimOptions& options = {});

}  // namespace whitted
