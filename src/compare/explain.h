#pragma once
// `whitted explain`: why an image differs from whitted's reference for its scene. Three answers:
//   which convention: the image against renders of the lab's classic mistakes (explain_variants.h);
//     those it matches far better than the reference are named;
//   which term: the difference, over the pixels that differ, fitted by least squares as a sum of
//     the terms' images (reference minus the render without the term): "0.02 × the reference's
//     specular term" says the highlights are missing; over the whole image and over each region
//     (one mistake may be in the mirror and another in the shadows);
//   where: the worst regions (connected 8×8 blocks holding differing pixels), each with the pixel
//     inspector's account of its centre pixel in the reference.
#include <atomic>
#include <string>
#include <vector>

#include "accel/scene.h"
#include "compare/compare.h"
#include "compare/explain_variants.h"
#include "inspect/pixel_inspector.h"
#include "render/render_job.h"

namespace whitted {

struct ExplainOptions {
    CompareOptions compare;  // the verdict's thresholds (as `whitted compare`), SSIM, FLIP
    // A variant is named when the image is at least this much closer to it than to the reference
    // (PSNR, dB).
    double better_db = 6.0;
    // A pixel differs (for the fit and the regions) when a channel differs by more than this; also
    // never less than the compare thresholds' `warn`.
    float differ = 1.5f / 255.0f;
    int block = 8;        // regions are connected blocks of block × block pixels
    int max_regions = 3;
    bool quantize = true;  // compare 8-bit values (the image is an 8-bit file)
    const std::atomic<bool>* cancel = nullptr;
};

struct VariantMatch {
    Variant variant;
    double psnr = 0.0;  // of the image against this variant's render (+∞: identical)
    bool changes_scene = true;  // the variant's render differs from the reference at all
};

struct TermFit {
    Variant variant;            // the removal whose difference is the term's image
    double coefficient = 1.0;   // the image has coefficient × the reference's term
    // The share of the difference's energy this term's change alone makes ((c − 1)²·|T|² / |D|²):
    // a term whose image is faint where the pixels differ can take any coefficient for little.
    double share = 0.0;
};

struct Region {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // pixels [x0, x1) × [y0, y1)
    std::size_t pixels = 0;               // differing pixels in it
    double mean_error = 0.0;              // their mean of the largest channel difference
    int x = 0, y = 0;                     // its centre pixel: the differing pixel nearest its error-weighted centre
    glm::vec3 image{0.0f}, reference{0.0f};  // there
    PixelReport inspection;               // the reference's pixel (x, y)
    std::vector<TermFit> terms;           // the fit over this region's differing pixels, largest share first
    double explained = 0.0;               // its R²
};

struct Explanation {
    CompareReport compare;  // the image against the reference
    std::size_t differing = 0;  // pixels differing by more than ExplainOptions::differ
    double psnr = 0.0;          // the image against the reference (= compare.errors.psnr)
    std::vector<VariantMatch> variants;  // all rendered, closest first
    std::vector<VariantMatch> matches;   // those far closer than the reference, closest first
    std::vector<TermFit> terms;          // every term fitted (those with an image over the differing pixels)
    double explained = 0.0;  // share of the difference's energy the fit explains (R², 0 to 1)
    std::vector<Region> regions;  // worst first
    bool cancelled = false;
    bool differs() const { return compare.verdict != Verdict::pass; }
};

// Explains `image` (the job's size) against the job's render of `scene`. With no difference
// (PASS) only the comparison is made.
Explanation explain_image(const Scene& scene, const RenderJob& job, const LinearImage& image,
                          const ExplainOptions& options = {});

// The fit alone, for tests: coefficients c_k minimising Σ (image − reference − Σ (c_k − 1)·T_k)²
// over the pixels where `mask` is set (T_k = reference − removals[k]); `explained` gets R², and
// `shares`, if given, each term's share as TermFit::share.
std::vector<double> fit_terms(const LinearImage& image, const LinearImage& reference,
                              const std::vector<LinearImage>& removals, const std::vector<std::uint8_t>& mask,
                              double& explained, std::vector<double>* shares = nullptr);
std::vector<double> fit_terms(const LinearImage& image, const LinearImage& reference,
                              const std::vector<const LinearImage*>& removals, const std::vector<std::uint8_t>& mask,
                              double& explained, std::vector<double>* shares = nullptr);

}  // namespace whitted
