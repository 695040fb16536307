#include "render/denoise/firefly_limits.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "render/denoise/atrous_filter.h"

namespace pt::denoise {

namespace {

// Whether pixel i takes part in its neighbours' windows, as fireflyLimitAt has it: a sample
// that is not left out, on a surface.
bool takesPart(const DenoiseSample* in, const DenoiseSurface* surfaces, size_t i) {
    return in[i].valid() && surfaces[i].depth > 0.0f;
}

template <class PerRow>
void forEachRow(uint32_t height, const PerRow& perRow) {
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, height), [&](const tbb::blocked_range<uint32_t>& rows) {
        for (uint32_t y = rows.begin(); y != rows.end(); ++y) perRow(y);
    });
}

}  // namespace

void fireflyLimits(const DenoiseSample* in, const DenoiseSurface* surfaces, uint32_t width, uint32_t height,
                   FireflyRowSums& rowSums, float* limits) {
    const size_t pixels = size_t(width) * height;
    rowSums.count.resize(pixels);
    rowSums.luminance.resize(pixels);
    rowSums.squares.resize(pixels);
    const int r = kFireflyRadius;
    forEachRow(height, [&](uint32_t y) {
        const size_t row = size_t(y) * width;
        for (uint32_t x = 0; x < width; ++x) {
            double count = 0.0, sum = 0.0, squares = 0.0;
            const uint32_t from = uint32_t(std::max(int(x) - r, 0)),
                           to = std::min(x + uint32_t(r), width - 1);
            for (uint32_t qx = from; qx <= to; ++qx) {
                if (!takesPart(in, surfaces, row + qx)) continue;
                const double l = luminance(in[row + qx].radiance);
                count += 1.0;
                sum += l;
                squares += l * l;
            }
            rowSums.count[row + x] = count;
            rowSums.luminance[row + x] = sum;
            rowSums.squares[row + x] = squares;
        }
    });
    forEachRow(height, [&](uint32_t y) {
        const uint32_t from = uint32_t(std::max(int(y) - r, 0)), to = std::min(y + uint32_t(r), height - 1);
        for (uint32_t x = 0; x < width; ++x) {
            const size_t i = size_t(y) * width + x;
            if (!takesPart(in, surfaces, i)) {
                limits[i] = kNoLuminanceLimit;
                continue;
            }
            double count = 0.0, sum = 0.0, squares = 0.0;
            for (uint32_t qy = from; qy <= to; ++qy) {
                const size_t q = size_t(qy) * width + x;
                count += rowSums.count[q];
                sum += rowSums.luminance[q];
                squares += rowSums.squares[q];
            }
            const double own = luminance(in[i].radiance);  // the centre takes part: out of its window
            count -= 1.0;
            sum -= own;
            squares -= own * own;
            if (count < double(kFireflyMinNeighbours)) {
                limits[i] = kNoLuminanceLimit;
                continue;
            }
            const double mean = sum / count;
            limits[i] = float(mean + double(kFireflyDeviations) *
                                         std::sqrt(std::max(squares / count - mean * mean, 0.0)));
        }
    });
}

}  // namespace pt::denoise
