#include "compare/flip.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "base/parallel_for.h"

#include "compare/flip_colour.h"

namespace whitted {

using std::numbers::pi;

double flip_default_pixels_per_degree() { return 0.7 * 3840.0 / 0.7 * pi / 180.0; }

namespace flip {
namespace {

// The contrast sensitivity functions' parameters (the paper's Table 1: a1, b1, a2, b2); the 2-D
// filter is Σ a·√(π/b)·exp(−π²·r²/b), r in degrees. b2 = 1e-5 where a2 = 0 (one term).
struct CsfParameters {
    double a1, b1, a2, b2;
};
constexpr CsfParameters kCsf[3] = {{1.0, 0.0047, 0.0, 1e-5}, {1.0, 0.0053, 0.0, 1e-5}, {34.1, 0.04, 13.5, 0.025}};

constexpr double kEdgeWidth = 0.082;  // degrees: peak to trough of the eye's edge detector (2 σ)
constexpr double kQf = 0.5;           // the feature exponent

Kernel make_kernel(int radius) { return Kernel{radius, std::vector<double>(std::size_t(2 * radius + 1))}; }

// Weights w(i − radius) scaled so that the positive ones sum to 1 and the negative ones to −1.
void normalise_signed(Kernel& k) {
    double pos = 0.0, neg = 0.0;
    for (double w : k.weights) (w > 0.0 ? pos : neg) += w;
    for (double& w : k.weights) w = w > 0.0 ? w / pos : (w < 0.0 ? w / -neg : 0.0);
}

// The image's planes in YCxCz (three planes), from values clamped to [0, 1] read as sRGB.
std::vector<std::vector<float>> to_ycxcz(const LinearImage& image) {
    const std::size_t n = image.rgb.size();
    std::vector<std::vector<float>> p(3, std::vector<float>(n));
    for (std::size_t i = 0; i < n; ++i) {
        const glm::vec3 v = image.rgb[i];
        const glm::dvec3 linear(srgb_to_linear(clamp01(v.x)), srgb_to_linear(clamp01(v.y)), srgb_to_linear(clamp01(v.z)));
        const glm::dvec3 o = xyz_to_ycxcz(linear_rgb_to_xyz(linear));
        for (int c = 0; c < 3; ++c) p[std::size_t(c)][i] = float(o[c]);
    }
    return p;
}

// The colour pipeline's result for one image: Hunt-adjusted CIELAB of the filtered image.
std::vector<glm::vec3> filtered_hunt_lab(const std::vector<std::vector<float>>& ycxcz, int w, int h, double ppd) {
    std::vector<std::vector<float>> filtered(3);
    for (int c = 0; c < 3; ++c) {
        std::vector<float>& out = filtered[std::size_t(c)];
        out.assign(ycxcz[0].size(), 0.0f);
        for (const CsfTerm& term : csf_filter(c, ppd)) {
            const std::vector<float> part = filter_separable(ycxcz[std::size_t(c)], w, h, term.g, term.g);
            for (std::size_t i = 0; i < out.size(); ++i) out[i] += float(term.scale * part[i]);
        }
    }
    std::vector<glm::vec3> lab(ycxcz[0].size());
    for (std::size_t i = 0; i < lab.size(); ++i) {
        glm::dvec3 rgb = xyz_to_linear_rgb(ycxcz_to_xyz({filtered[0][i], filtered[1][i], filtered[2][i]}));
        rgb = glm::clamp(rgb, 0.0, 1.0);
        lab[i] = glm::vec3(linear_rgb_to_hunt_lab(rgb));
    }
    return lab;
}

// The feature pipeline's result for one image: per pixel, the edge and point magnitudes of its
// normalised luminance (Y/Yn, from the unfiltered YCxCz).
struct Features {
    std::vector<float> edge, point;
};

Features features(const std::vector<float>& y_ycxcz, int w, int h, const FeatureKernels& k) {
    std::vector<float> y(y_ycxcz.size());
    for (std::size_t i = 0; i < y.size(); ++i) y[i] = (y_ycxcz[i] + 16.0f) / 116.0f;
    auto magnitude = [&](const Kernel& d) {
        const std::vector<float> along_x = filter_separable(y, w, h, d, k.gauss);
        const std::vector<float> along_y = filter_separable(y, w, h, k.gauss, d);
        std::vector<float> m(y.size());
        for (std::size_t i = 0; i < m.size(); ++i) m[i] = std::hypot(along_x[i], along_y[i]);
        return m;
    };
    return {magnitude(k.edge), magnitude(k.point)};
}

}  // namespace

std::vector<CsfTerm> csf_filter(int channel, double ppd) {
    // One radius for all three channels, from the widest Gaussian (b = 0.04): 3 standard deviations.
    double widest = 0.0;
    for (const CsfParameters& p : kCsf) widest = std::max({widest, p.b1, p.b2});
    const int radius = int(std::ceil(3.0 * std::sqrt(widest / (2.0 * pi * pi)) * ppd));
    const CsfParameters& p = kCsf[channel];
    std::vector<CsfTerm> terms;
    double total = 0.0;  // of the 2-D filter: Σ scale · (Σ g)²
    for (auto [a, b] : {std::pair{p.a1, p.b1}, std::pair{p.a2, p.b2}}) {
        if (a == 0.0) continue;
        CsfTerm t{a * std::sqrt(pi / b), make_kernel(radius)};
        double sum = 0.0;
        for (int i = -radius; i <= radius; ++i) {
            const double x = i / ppd;  // degrees
            sum += t.g.weights[std::size_t(i + radius)] = std::exp(-pi * pi * x * x / b);
        }
        total += t.scale * sum * sum;
        terms.push_back(std::move(t));
    }
    for (CsfTerm& t : terms) t.scale /= total;
    return terms;
}

FeatureKernels feature_kernels(double ppd) {
    const double sd = 0.5 * kEdgeWidth * ppd;
    const int radius = int(std::ceil(3.0 * sd));
    FeatureKernels k{make_kernel(radius), make_kernel(radius), make_kernel(radius)};
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const std::size_t j = std::size_t(i + radius);
        const double g = std::exp(-double(i) * i / (2.0 * sd * sd));
        sum += k.gauss.weights[j] = g;
        k.edge.weights[j] = -i * g;
        k.point.weights[j] = (double(i) * i / (sd * sd) - 1.0) * g;
    }
    for (double& w : k.gauss.weights) w /= sum;
    // The 2-D filters' positive and negative parts are normalised; the Gaussian factor along the
    // other axis is common to both, so normalising the 1-D part does the same.
    normalise_signed(k.edge);
    normalise_signed(k.point);
    return k;
}

std::vector<float> filter_separable(const std::vector<float>& plane, int w, int h, const Kernel& kx, const Kernel& ky) {
    // Rows on several threads: each output value is computed alone, the same way on any thread.
    std::vector<float> rows(plane.size()), out(plane.size());
    const int workers = worker_count(0, std::size_t(h) / 16);
    parallel_for(std::size_t(h), workers, [&](std::size_t y, int) {
        const float* in = &plane[y * std::size_t(w)];
        float* o = &rows[y * std::size_t(w)];
        for (int x = 0; x < w; ++x) {
            double s = 0.0;
            for (int i = -kx.radius; i <= kx.radius; ++i)
                s += kx.weights[std::size_t(i + kx.radius)] * in[std::clamp(x + i, 0, w - 1)];
            o[x] = float(s);
        }
    });
    std::vector<std::vector<double>> acc(static_cast<std::size_t>(workers), std::vector<double>(static_cast<std::size_t>(w)));
    parallel_for(std::size_t(h), workers, [&](std::size_t y, int worker) {
        std::vector<double>& sum = acc[std::size_t(worker)];
        std::fill(sum.begin(), sum.end(), 0.0);
        for (int i = -ky.radius; i <= ky.radius; ++i) {
            const double wt = ky.weights[std::size_t(i + ky.radius)];
            const float* in = &rows[std::size_t(std::clamp(int(y) + i, 0, h - 1)) * std::size_t(w)];
            for (int x = 0; x < w; ++x) sum[std::size_t(x)] += wt * in[x];
        }
        float* o = &out[y * std::size_t(w)];
        for (int x = 0; x < w; ++x) o[x] = float(sum[std::size_t(x)]);
    });
    return out;
}

}  // namespace flip

FlipResult compute_flip(const LinearImage& reference, const LinearImage& test, const FlipOptions& options) {
    using namespace flip;
    const int w = reference.width, h = reference.height;
    const double ppd = options.pixels_per_degree;
    FlipResult r;
    r.width = w, r.height = h;
    const FeatureKernels kernels = feature_kernels(ppd);

    // One image at a time, keeping only what the final step needs of each.
    std::vector<glm::vec3> lab[2];
    Features feat[2];
    const LinearImage* images[2] = {&reference, &test};
    for (int k = 0; k < 2; ++k) {
        const std::vector<std::vector<float>> ycxcz = to_ycxcz(*images[k]);
        lab[k] = filtered_hunt_lab(ycxcz, w, h, ppd);
        feat[k] = features(ycxcz[0], w, h, kernels);
    }

    r.error.resize(reference.rgb.size());
    double sum = 0.0;
    for (std::size_t i = 0; i < r.error.size(); ++i) {
        const double colour = flip_colour_error(hyab(glm::dvec3(lab[0][i]), glm::dvec3(lab[1][i])));
        const double feature_difference = std::max(std::abs(feat[0].edge[i] - feat[1].edge[i]),
                                                   std::abs(feat[0].point[i] - feat[1].point[i]));
        const double feature = std::pow(feature_difference / std::sqrt(2.0), kQf);
        const float e = float(std::pow(colour, 1.0 - feature));
        r.error[i] = e;
        sum += e;
        if (e > r.max) r.max = e, r.max_x = int(i % std::size_t(w)), r.max_y = int(i / std::size_t(w));
    }
    r.mean = r.error.empty() ? 0.0 : sum / double(r.error.size());
    return r;
}

}  // namespace whitted
