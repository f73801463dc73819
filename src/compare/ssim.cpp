#include "compare/ssim.h"

#include <algorithm>

namespace whitted {
namespace {

constexpr double kC1 = 0.01 * 0.01, kC2 = 0.03 * 0.03;  // (K·L)², L = 1

// The mean over R, G, B of the SSIM of the pixels [x0, x0 + w) × [y0, y0 + h).
double block_ssim(const LinearImage& a, const LinearImage& b, int x0, int y0, int w, int h) {
    const double n = double(w) * double(h);
    double total = 0.0;
    for (int c = 0; c < 3; ++c) {
        auto value = [&](const LinearImage& im, int x, int y) {
            return double(clamp01(im.rgb[std::size_t(y) * std::size_t(im.width) + std::size_t(x)][c]));
        };
        double ma = 0.0, mb = 0.0;
        for (int y = y0; y < y0 + h; ++y)
            for (int x = x0; x < x0 + w; ++x) ma += value(a, x, y), mb += value(b, x, y);
        ma /= n, mb /= n;
        double va = 0.0, vb = 0.0, cov = 0.0;
        for (int y = y0; y < y0 + h; ++y)
            for (int x = x0; x < x0 + w; ++x) {
                const double da = value(a, x, y) - ma, db = value(b, x, y) - mb;
                va += da * da, vb += db * db, cov += da * db;
            }
        va /= n, vb /= n, cov /= n;
        total += (2.0 * ma * mb + kC1) * (2.0 * cov + kC2) / ((ma * ma + mb * mb + kC1) * (va + vb + kC2));
    }
    return total / 3.0;
}

}  // namespace

SsimStats compute_ssim(const LinearImage& a, const LinearImage& b, const SsimOptions& options) {
    SsimStats s;
    const int k = std::max(1, options.block);
    s.blocks_across = (a.width + k - 1) / k;
    s.blocks_down = (a.height + k - 1) / k;
    s.blocks = std::size_t(s.blocks_across) * std::size_t(s.blocks_down);
    s.block_ssim.resize(s.blocks);
    double sum = 0.0;
    bool first = true;
    for (int by = 0; by < s.blocks_down; ++by)
        for (int bx = 0; bx < s.blocks_across; ++bx) {
            const int x = bx * k, y = by * k, w = std::min(k, a.width - x), h = std::min(k, a.height - y);
            const double v = block_ssim(a, b, x, y, w, h);
            s.block_ssim[std::size_t(by) * std::size_t(s.blocks_across) + std::size_t(bx)] = v;
            sum += v;
            if (v <= options.threshold) ++s.blocks_failing;
            if (first || v < s.worst.ssim) s.worst = {x, y, w, h, v};
            first = false;
        }
    s.mean = s.blocks ? sum / double(s.blocks) : 1.0;
    return s;
}

}  // namespace whitted
