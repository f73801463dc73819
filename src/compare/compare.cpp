#include "compare/compare.h"

namespace whitted {

std::string compare_problem(const LinearImage& a, const LinearImage& b) {
    if (a.width == b.width && a.height == b.height) return "";
    return "the images differ in size: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " and " +
           std::to_string(b.width) + "x" + std::to_string(b.height);
}

CompareReport compare_images(const LinearImage& reference, const LinearImage& test, const CompareOptions& options) {
    CompareReport r;
    r.width = reference.width, r.height = reference.height;
    r.errors = compute_errors(reference, test, options.thresholds);
    r.verdict = judge(r.errors, options.thresholds);
    r.ssim = compute_ssim(reference, test, options.ssim);
    r.flip = compute_flip(reference, test, options.flip);
    return r;
}

}  // namespace whitted
