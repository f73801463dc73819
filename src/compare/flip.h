#pragma once
// LDR-FLIP: Andersson, Nilsson, Akenine-Möller, Oskarsson, Åström and Fairchild, "FLIP: A
// Difference Evaluator for Alternating Images" (HPG 2020). A per-pixel error in [0, 1] for what a
// viewer flipping between the two images would notice, at a given viewing distance:
//   colour: each image in YCxCz is filtered with the contrast sensitivity of the eye (one
//     Gaussian, or two for blue-yellow), clamped to the RGB cube, taken to Hunt-adjusted CIELAB,
//     and the HyAB distance of the two mapped to ΔEc in [0, 1] (flip_colour.h);
//   features: edges and points (first and second derivatives of a Gaussian whose width is the
//     eye's edge detector, 0.082°) found in each image's luminance; ΔEf = √(max difference / √2);
//   FLIP = ΔEc^(1 − ΔEf).
// The images are what a screen shows: values clamped to [0, 1], read as sRGB (an image viewer
// shows whitted's 8-bit files that way; an .exr is taken as its 8-bit image would be).
#include <vector>

#include "film/image.h"

namespace whitted {

// FLIP's default observer: 0.7 m from a 0.7 m wide 3840-pixel monitor, 67.02 pixels per degree.
double flip_default_pixels_per_degree();

struct FlipOptions {
    double pixels_per_degree = flip_default_pixels_per_degree();
};

struct FlipResult {
    int width = 0, height = 0;
    std::vector<float> error;  // per pixel, row-major, in [0, 1]
    double mean = 0.0;
    double max = 0.0;
    int max_x = 0, max_y = 0;  // the first pixel with the largest error, in row order
};

FlipResult compute_flip(const LinearImage& reference, const LinearImage& test, const FlipOptions& options = {});

namespace flip {

// The filters, as one-dimensional kernels (each filter is separable): index i is offset i − radius.
struct Kernel {
    int radius = 0;
    std::vector<double> weights;  // 2·radius + 1
};

// The contrast sensitivity filters of one opponent channel (0: achromatic Y, 1: red-green Cx,
// 2: blue-yellow Cz): a sum of one or two separable Gaussian terms, each `scale` × g ⊗ g, the
// whole 2-D filter summing to 1.
struct CsfTerm {
    double scale = 0.0;
    Kernel g;
};
std::vector<CsfTerm> csf_filter(int channel, double pixels_per_degree);

// The feature filters' 1-D parts: `gauss` sums to 1; `edge` (first derivative) and `point`
// (second derivative) have positive weights summing to 1 and negative ones to −1. The 2-D edge
// filter along x is edge(x)·gauss(y), the point filter point(x)·gauss(y); along y, transposed.
struct FeatureKernels {
    Kernel gauss, edge, point;
};
FeatureKernels feature_kernels(double pixels_per_degree);

// `plane` (width × height, row-major) correlated with kx along rows and ky along columns, the
// image's border pixels repeated beyond its edges.
std::vector<float> filter_separable(const std::vector<float>& plane, int width, int height, const Kernel& kx,
                                    const Kernel& ky);

}  // namespace flip
}  // namespace whitted
