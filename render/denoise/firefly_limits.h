#pragma once
// fireflyLimitAt (atrous_filter.h) over a whole image on the CPU, as box sums. Whether a pixel
// takes part in a window does not depend on the window's centre, so the window's count,
// luminance sum and sum of squares are separable: 7 taps along each row, then 7 of those row
// sums down each column, the centre's own row summed without it, instead of 48 taps a pixel
// (512x512 on 2 cores: 3 ms, where a pixel at a time took 11). The sums are doubles, so that
// the mean of squares less the square of the mean keeps a low-noise surface's spread; the limits
// are fireflyLimitAt's to float rounding.
#include <cstdint>
#include <vector>

#include "render/denoise/denoise_planes.h"

namespace pt::denoise {

// The row sums between the two sweeps, kept for the next call.
struct FireflyRowSums {
    std::vector<double> count, luminance, squares;
};

// `limits[y * width + x]`: fireflyLimitAt(in, surfaces, width, height, x, y), rows in parallel.
void fireflyLimits(const DenoiseSample* in, const DenoiseSurface* surfaces, uint32_t width, uint32_t height,
                   FireflyRowSums& rowSums, float* limits);

}  // namespace pt::denoise
