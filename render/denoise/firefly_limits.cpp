#include "render/denoise/firefly_limits.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "render/denoise/atrous_filter.h"

namespace pt::denoise {

namespace {

// A window's count of pixels on a surface, their luminance sum and sum of squares.
struct WindowSums {
    double count = 0.0, luminance = 0.0, squares = 0.0;

    void add(double l) {
        count += 1.0;
        luminance += l;
        squares += l * l;
    }
    void add(const WindowSums& s) {
        count += s.count;
        luminance += s.luminance;
        squares += s.squares;
    }
};

// Whether pixel i is in the firefly windows (inFireflyWindow).
bool takesPart(const DenoiseSample* in, const DenoiseSurface* surfaces, size_t i) {
    return inFireflyWindow(in[i], surfaces[i]);
}

// The taps of row `y` within kFireflyRadius of column x, all but column `skip`, that take part.
WindowSums rowTaps(const DenoiseSample* in, const DenoiseSurface* surfaces, uint32_t width, uint32_t y,
                   uint32_t x, uint32_t skip) {
    WindowSums sums;
    const size_t row = size_t(y) * width;
    const uint32_t from = uint32_t(std::max(int(x) - kFireflyRadius, 0));
    const uint32_t to = std::min(x + uint32_t(kFireflyRadius), width - 1);
    for (uint32_t qx = from; qx <= to; ++qx) {
        const size_t q = row + qx;
        if (qx != skip && takesPart(in, surfaces, q)) sums.add(luminance(in[q].radiance));
    }
    return sums;
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
    constexpr uint32_t kNone = ~0u;  // a column no pixel has
    forEachRow(height, [&](uint32_t y) {
        for (uint32_t x = 0; x < width; ++x) {
            const WindowSums s = rowTaps(in, surfaces, width, y, x, kNone);
            const size_t i = size_t(y) * width + x;
            rowSums.count[i] = s.count;
            rowSums.luminance[i] = s.luminance;
            rowSums.squares[i] = s.squares;
        }
    });
    forEachRow(height, [&](uint32_t y) {
        const uint32_t from = uint32_t(std::max(int(y) - kFireflyRadius, 0));
        const uint32_t to = std::min(y + uint32_t(kFireflyRadius), height - 1);
        for (uint32_t x = 0; x < width; ++x) {
            const size_t i = size_t(y) * width + x;
            if (!takesPart(in, surfaces, i)) {
                limits[i] = kNoLuminanceLimit;
                continue;
            }
            // The centre's own row is summed anew without it: taking a firefly's share out of its
            // row sum by subtraction cancelled its neighbours' away (at 1e7x their luminance,
            // 1e-2 of its limit).
            WindowSums s = rowTaps(in, surfaces, width, y, x, x);
            for (uint32_t qy = from; qy <= to; ++qy) {
                const size_t q = size_t(qy) * width + x;
                if (qy != y) s.add({rowSums.count[q], rowSums.luminance[q], rowSums.squares[q]});
            }
            if (s.count < double(kFireflyMinNeighbours)) {
                limits[i] = kNoLuminanceLimit;
                continue;
            }
            const double mean = s.luminance / s.count;
            const double spread = std::sqrt(std::max(s.squares / s.count - mean * mean, 0.0));
            limits[i] = float(mean + double(kFireflyDeviations) * spread);
        }
    });
}

}  // namespace pt::denoise
