#pragma once
// Every metric of two images at once: what `whitted compare` prints and what a grading tool
// tabulates.
#include <string>

#include "compare/errors.h"
#include "compare/flip.h"
#include "compare/ssim.h"
#include "film/image.h"

namespace whitted {

struct CompareOptions {
    Thresholds thresholds;
    SsimOptions ssim;
    FlipOptions flip;
};

struct CompareReport {
    int width = 0, height = 0;
    ErrorStats errors;
    Verdict verdict = Verdict::pass;
    SsimStats ssim;
    FlipResult flip;
};

// "" if the images can be compared, else why not ("the images differ in size: 640x480 and 320x240").
std::string compare_problem(const LinearImage& a, const LinearImage& b);

// The metrics of `test` against `reference` (of the same size: compare_problem first). The errors,
// SSIM and FLIP are symmetric; FLIP's paper calls its inputs reference and test.
CompareReport compare_images(const LinearImage& reference, const LinearImage& test, const CompareOptions& options = {});

}  // namespace whitted
