#include "compare/explain.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace whitted {
namespace {

float channel_max(const glm::vec3& v) { return std::max(v.x, std::max(v.y, v.z)); }

float pixel_error(const LinearImage& a, const LinearImage& b, std::size_t i) {
    return channel_max(glm::abs(a.rgb[i] - b.rgb[i]));
}

bool same_image(const LinearImage& a, const LinearImage& b) { return a.rgb == b.rgb; }

// Solves M·x = b (n × n, row-major, symmetric positive semi-definite) by Gaussian elimination with
// partial pivoting; an unknown whose pivot vanishes (a term the others already make) gets 0.
std::vector<double> solve(std::vector<double> m, std::vector<double> b, std::size_t n) {
    double scale = 0.0;
    for (std::size_t i = 0; i < n; ++i) scale = std::max(scale, m[i * n + i]);
    const double tiny = 1e-12 * scale;
    std::vector<std::size_t> pivot_col(n, n);
    std::vector<bool> used(n, false);
    for (std::size_t col = 0; col < n; ++col) {
        std::size_t best = n;
        for (std::size_t r = 0; r < n; ++r)
            if (!used[r] && (best == n || std::abs(m[r * n + col]) > std::abs(m[best * n + col]))) best = r;
        if (best == n || std::abs(m[best * n + col]) <= tiny) continue;
        used[best] = true;
        pivot_col[col] = best;
        for (std::size_t r = 0; r < n; ++r) {
            if (r == best || m[r * n + col] == 0.0) continue;
            const double f = m[r * n + col] / m[best * n + col];
            for (std::size_t c = 0; c < n; ++c) m[r * n + c] -= f * m[best * n + c];
            b[r] -= f * b[best];
        }
    }
    std::vector<double> x(n, 0.0);
    for (std::size_t col = 0; col < n; ++col)
        if (pivot_col[col] < n) x[col] = b[pivot_col[col]] / m[pivot_col[col] * n + col];
    return x;
}

// The worst regions, and in `masks` each one's differing pixels (the image's size).
std::vector<Region> find_regions(const LinearImage& image, const LinearImage& reference,
                                 const std::vector<std::uint8_t>& mask, int block, int max_regions,
                                 std::vector<std::vector<std::uint8_t>>& masks) {
    const int w = image.width, h = image.height;
    const int bw = (w + block - 1) / block, bh = (h + block - 1) / block;
    std::vector<std::uint8_t> bad(std::size_t(bw) * bh, 0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (mask[std::size_t(y) * w + x]) bad[std::size_t(y / block) * bw + x / block] = 1;
    std::vector<int> label(bad.size(), -1);
    struct Found {
        Region r;
        double total = 0.0;
        std::vector<int> blocks;
    };
    std::vector<Found> found;
    for (std::size_t start = 0; start < bad.size(); ++start) {
        if (!bad[start] || label[start] >= 0) continue;
        Found f;
        std::vector<int> stack{int(start)};
        label[start] = int(found.size());
        while (!stack.empty()) {  // blocks touching at an edge or a corner are one region
            const int b = stack.back();
            stack.pop_back();
            f.blocks.push_back(b);
            const int bx = b % bw, by = b / bw;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = bx + dx, ny = by + dy;
                    if (nx < 0 || ny < 0 || nx >= bw || ny >= bh) continue;
                    const std::size_t nb = std::size_t(ny) * bw + nx;
                    if (bad[nb] && label[nb] < 0) {
                        label[nb] = int(found.size());
                        stack.push_back(int(nb));
                    }
                }
        }
        Region& r = f.r;
        r.x0 = w, r.y0 = h;
        double cx = 0.0, cy = 0.0;
        for (int b : f.blocks)
            for (int y = (b / bw) * block; y < std::min(h, (b / bw + 1) * block); ++y)
                for (int x = (b % bw) * block; x < std::min(w, (b % bw + 1) * block); ++x) {
                    const std::size_t i = std::size_t(y) * w + x;
                    if (!mask[i]) continue;
                    const double e = pixel_error(image, reference, i);
                    ++r.pixels;
                    f.total += e;
                    cx += e * (x + 0.5);
                    cy += e * (y + 0.5);
                    r.x0 = std::min(r.x0, x), r.y0 = std::min(r.y0, y);
                    r.x1 = std::max(r.x1, x + 1), r.y1 = std::max(r.y1, y + 1);
                }
        r.mean_error = f.total / double(r.pixels);
        cx /= f.total, cy /= f.total;
        double nearest = std::numeric_limits<double>::infinity();
        for (int b : f.blocks)
            for (int y = (b / bw) * block; y < std::min(h, (b / bw + 1) * block); ++y)
                for (int x = (b % bw) * block; x < std::min(w, (b % bw + 1) * block); ++x) {
                    const double d = (x + 0.5 - cx) * (x + 0.5 - cx) + (y + 0.5 - cy) * (y + 0.5 - cy);
                    if (mask[std::size_t(y) * w + x] && d < nearest) nearest = d, r.x = x, r.y = y;
                }
        r.image = image.rgb[std::size_t(r.y) * w + r.x];
        r.reference = reference.rgb[std::size_t(r.y) * w + r.x];
        found.push_back(std::move(f));
    }
    std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.total > b.total; });
    std::vector<Region> out;
    masks.clear();
    for (std::size_t i = 0; i < found.size() && int(i) < max_regions; ++i) {
        out.push_back(found[i].r);
        std::vector<std::uint8_t>& m = masks.emplace_back(mask.size(), 0);
        for (int b : found[i].blocks)
            for (int y = (b / bw) * block; y < std::min(h, (b / bw + 1) * block); ++y)
                for (int x = (b % bw) * block; x < std::min(w, (b % bw + 1) * block); ++x)
                    m[std::size_t(y) * w + x] = mask[std::size_t(y) * w + x];
    }
    return out;
}

}  // namespace

std::vector<double> fit_terms(const LinearImage& image, const LinearImage& reference,
                              const std::vector<LinearImage>& removals, const std::vector<std::uint8_t>& mask,
                              double& explained, std::vector<double>* shares) {
    std::vector<const LinearImage*> each;
    for (const LinearImage& r : removals) each.push_back(&r);
    return fit_terms(image, reference, each, mask, explained, shares);
}

std::vector<double> fit_terms(const LinearImage& image, const LinearImage& reference,
                              const std::vector<const LinearImage*>& removals, const std::vector<std::uint8_t>& mask,
                              double& explained, std::vector<double>* shares) {
    const std::size_t n = removals.size();
    std::vector<double> m(n * n, 0.0), b(n, 0.0), t(n);
    double total = 0.0;
    for (std::size_t i = 0; i < mask.size(); ++i) {
        if (!mask[i]) continue;
        for (int c = 0; c < 3; ++c) {
            const double d = double(image.rgb[i][c]) - double(reference.rgb[i][c]);
            if (!std::isfinite(d)) continue;  // a NaN or infinite pixel is no colour to fit
            for (std::size_t k = 0; k < n; ++k) t[k] = double(reference.rgb[i][c]) - double(removals[k]->rgb[i][c]);
            for (std::size_t j = 0; j < n; ++j) {
                b[j] += t[j] * d;
                for (std::size_t k = 0; k < n; ++k) m[j * n + k] += t[j] * t[k];
            }
            total += d * d;
        }
    }
    const std::vector<double> a = solve(m, b, n);
    // The residual's energy from the normal equations: |d|² − 2 a·b + aᵀ M a.
    double fitted = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
        fitted += 2.0 * a[j] * b[j];
        for (std::size_t k = 0; k < n; ++k) fitted -= a[j] * m[j * n + k] * a[k];
    }
    explained = total > 0.0 ? std::clamp(fitted / total, 0.0, 1.0) : 1.0;
    std::vector<double> coefficients(n);
    for (std::size_t k = 0; k < n; ++k) coefficients[k] = 1.0 + a[k];
    if (shares) {
        shares->assign(n, 0.0);
        for (std::size_t k = 0; k < n && total > 0.0; ++k) (*shares)[k] = a[k] * a[k] * m[k * n + k] / total;
    }
    return coefficients;
}

Explanation explain_image(const Scene& scene, const RenderJob& job, const LinearImage& image,
                          const ExplainOptions& options) {
    Explanation e;
    RenderJob reference_job = job;
    reference_job.cancel = options.cancel;
    const LinearImage reference = render_variant(scene, reference_job, nullptr, options.quantize);
    e.compare = compare_images(reference, image, options.compare);
    e.psnr = e.compare.errors.psnr;
    const float tolerance = std::max(options.differ, options.compare.thresholds.warn);
    std::vector<std::uint8_t> mask(image.rgb.size(), 0);
    for (std::size_t i = 0; i < mask.size(); ++i) {
        const float err = pixel_error(image, reference, i);
        mask[i] = err > tolerance || std::isnan(err);
        e.differing += mask[i];
    }
    if (!e.differs()) return e;
    auto cancelled = [&] { return options.cancel && options.cancel->load(); };

    std::vector<LinearImage> removals;
    std::vector<Variant> removal_variants;
    for (const Variant& v : explain_variants(scene, job)) {
        if (cancelled()) {
            e.cancelled = true;
            return e;
        }
        LinearImage rendered = render_variant(scene, reference_job, &v, options.quantize);
        VariantMatch match{v, compute_errors(image, rendered, options.compare.thresholds).psnr,
                           !same_image(rendered, reference)};
        e.variants.push_back(match);
        if (!v.removal || !match.changes_scene) continue;
        bool seen = false;  // a term with no image over the differing pixels cannot be fitted
        for (std::size_t i = 0; i < mask.size() && !seen; ++i) seen = mask[i] && rendered.rgb[i] != reference.rgb[i];
        if (!seen) continue;
        removals.push_back(std::move(rendered));
        removal_variants.push_back(v);
    }
    std::stable_sort(e.variants.begin(), e.variants.end(),
                     [](const VariantMatch& a, const VariantMatch& b) { return a.psnr > b.psnr; });
    for (const VariantMatch& m : e.variants)
        if (m.changes_scene && m.psnr >= e.psnr + options.better_db) e.matches.push_back(m);

    // The terms fitted over `where`'s pixels, largest share first (those with no image there left out).
    auto fit = [&](const std::vector<std::uint8_t>& where, double& explained) {
        std::vector<const LinearImage*> here;
        std::vector<Variant> here_variants;
        for (std::size_t k = 0; k < removals.size(); ++k) {
            bool seen = false;
            for (std::size_t i = 0; i < where.size() && !seen; ++i)
                seen = where[i] && removals[k].rgb[i] != reference.rgb[i];
            if (!seen) continue;
            here.push_back(&removals[k]);
            here_variants.push_back(removal_variants[k]);
        }
        std::vector<TermFit> terms;
        explained = 0.0;
        if (here.empty()) return terms;
        std::vector<double> shares;
        const std::vector<double> c = fit_terms(image, reference, here, where, explained, &shares);
        for (std::size_t k = 0; k < c.size(); ++k) terms.push_back(TermFit{here_variants[k], c[k], shares[k]});
        std::stable_sort(terms.begin(), terms.end(), [](const TermFit& a, const TermFit& b) { return a.share > b.share; });
        return terms;
    };
    e.terms = fit(mask, e.explained);

    std::vector<std::vector<std::uint8_t>> region_masks;
    e.regions = find_regions(image, reference, mask, options.block, options.max_regions, region_masks);
    for (std::size_t i = 0; i < e.regions.size(); ++i) e.regions[i].terms = fit(region_masks[i], e.regions[i].explained);
    for (Region& r : e.regions) {
        r.inspection = inspect_pixel(scene, job, r.x, r.y, options.cancel);
        if (r.inspection.cancelled) e.cancelled = true;
    }
    return e;
}

}  // namespace whitted
