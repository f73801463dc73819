#pragma once
// Per-channel errors and the pass / warn / fail verdict, as OpenImageIO's idiff computes and
// decides them (its -fail, -failpercent, -hardfail, -warn, -warnpercent, -hardwarn).
#include <cstddef>
#include <limits>

#include "film/image.h"

namespace whitted {

// idiff's thresholds and its defaults: any difference over 1e-6 in any pixel fails.
struct Thresholds {
    float fail = 1e-6f;          // a pixel fails if any channel differs by more than this
    float fail_percent = 0.0f;   // FAILURE if more than this percentage of the pixels fail
    float hard_fail = std::numeric_limits<float>::infinity();  // FAILURE if any channel differs by more
    float warn = 1e-6f;
    float warn_percent = 0.0f;
    float hard_warn = std::numeric_limits<float>::infinity();
};

struct ErrorStats {
    std::size_t pixels = 0;
    double mean_error = 0.0;  // mean over every channel of every pixel of |a − b|
    double rms_error = 0.0;   // √(mean of (a − b)²)
    // 20·log10(peak / RMS), peak = 1 or the largest |value| of either image if that is larger
    // (idiff's choice for values past 1); +∞ when the images are equal.
    double psnr = 0.0;
    double peak = 1.0;
    double max_error = 0.0;  // the largest |a − b| of any channel; +∞ for a NaN or ∞ against anything else
    int max_x = 0, max_y = 0, max_channel = 0;  // where: the first such pixel and channel in row order
    float max_a = 0.0f, max_b = 0.0f;            // the two values there
    std::size_t warn_pixels = 0;  // pixels with a channel differing by more than Thresholds::warn
    std::size_t fail_pixels = 0;  // … more than Thresholds::fail
};

// idiff's exit codes.
enum class Verdict { pass = 0, warn = 1, fail = 2 };

// The errors of two images of the same size. Where both have NaN, or the same infinity, in a
// channel there is no error (as idiff); a NaN or infinity against anything else is an infinite
// error, over every threshold, left out of the mean, the RMS and the PSNR.
ErrorStats compute_errors(const LinearImage& a, const LinearImage& b, const Thresholds& t);

// FAILURE if more than fail_percent % of the pixels fail or max_error > hard_fail; otherwise
// WARNING if more than warn_percent % warn or max_error > hard_warn; otherwise PASS.
Verdict judge(const ErrorStats& s, const Thresholds& t);

const char* verdict_name(Verdict v);  // "PASS", "WARNING", "FAILURE" (idiff's words)

}  // namespace whitted
