#pragma once
// The denoiser's neighbourhood steps on the CPU, a row of pixels at a time: the per-pixel
// steps of atrous_filter.h (spatialVarianceAt, atrousAt) turned inside out, so that each tap
// runs over the whole row, a SIMD vector of pixels an instruction. Each pixel adds its taps in
// atrousAt's order with atrousAt's functions, so both backends filter to the same numbers.
#include <cstdint>
#include <vector>

#include "render/denoise/row_planes.h"

namespace pt::denoise {

// The distances of a-trous taps: (|i|, |j|) = (1, 0) or (0, 1), (2, 0) or (0, 2), (1, 1),
// (2, 1) or (1, 2), (2, 2).
constexpr int kTapDistances = 5;

// Per-row working memory, one a thread.
struct RowSums {
    std::vector<float> r, g, b, weight, variance, centerLuminance, inverseLuminance, outlierLimit;
    std::vector<float> inverseDepth;  // kTapDistances planes: the centre's depth scale for each
    explicit RowSums(uint32_t width)
        : r(width),
          g(width),
          b(width),
          weight(width),
          variance(width),
          centerLuminance(width),
          inverseLuminance(width),
          outlierLimit(width),
          inverseDepth(kTapDistances * size_t(width)) {}
};

// Row y's variance of the mean as its neighbours estimate it (spatialVarianceAt), into
// `variance[x]` (kInvalid where the pixel is left out).
void spatialVarianceRow(const LuminancePlanes& in, const SurfacePlanes& surfaces, const PlaneLayout& layout,
                        uint32_t y, RowSums& sums, float* variance);

// Row y of an a-trous pass with taps `step` apart (atrousAt), into `out`.
void atrousRow(const SamplePlanes& in, const SurfacePlanes& surfaces, const PlaneLayout& layout, uint32_t y,
               uint32_t step, RowSums& sums, SamplePlanes& out);

}  // namespace pt::denoise
