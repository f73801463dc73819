#include "compare/errors.h"

#include <algorithm>
#include <cmath>

namespace whitted {

ErrorStats compute_errors(const LinearImage& a, const LinearImage& b, const Thresholds& t) {
    ErrorStats s;
    s.pixels = a.rgb.size();
    double sum = 0.0, sum_sq = 0.0, peak = 1.0;
    std::size_t finite_values = 0;
    for (std::size_t i = 0; i < s.pixels; ++i) {
        bool warned = false, failed = false;
        for (int c = 0; c < 3; ++c) {
            const float av = a.rgb[i][c], bv = b.rgb[i][c];
            double f;
            if (!std::isfinite(av) || !std::isfinite(bv)) {
                if ((std::isnan(av) && std::isnan(bv)) || av == bv) continue;  // NaN against NaN, ∞ against the same ∞
                f = std::numeric_limits<double>::infinity();
            } else {
                f = std::abs(av - bv);  // float arithmetic, as idiff
                sum += f;
                sum_sq += f * f;
                ++finite_values;
                peak = std::max({peak, double(std::abs(av)), double(std::abs(bv))});
            }
            if (f > s.max_error) {
                s.max_error = f;
                s.max_x = int(i % std::size_t(a.width));
                s.max_y = int(i / std::size_t(a.width));
                s.max_channel = c;
                s.max_a = av, s.max_b = bv;
            }
            if (!warned && f > t.warn) warned = true, ++s.warn_pixels;
            if (!failed && f > t.fail) failed = true, ++s.fail_pixels;
        }
    }
    const double n = double(std::max<std::size_t>(finite_values, 1));
    s.mean_error = sum / n;
    s.rms_error = std::sqrt(sum_sq / n);
    s.peak = peak;
    s.psnr = s.rms_error > 0.0 ? 20.0 * std::log10(peak / s.rms_error) : std::numeric_limits<double>::infinity();
    return s;
}

Verdict judge(const ErrorStats& s, const Thresholds& t) {
    const double pixels = double(std::max<std::size_t>(s.pixels, 1));
    if (double(s.fail_pixels) > t.fail_percent / 100.0 * pixels || s.max_error > t.hard_fail) return Verdict::fail;
    if (double(s.warn_pixels) > t.warn_percent / 100.0 * pixels || s.max_error > t.hard_warn) return Verdict::warn;
    return Verdict::pass;
}

const char* verdict_name(Verdict v) {
    switch (v) {
        case Verdict::pass: return "PASS";
        case Verdict::warn: return "WARNING";
        case Verdict::fail: return "FAILURE";
    }
    return "?";
}

}  // namespace whitted
