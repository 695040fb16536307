#include "render/denoise/denoiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <utility>

namespace pt {

namespace {

// Runs perPixel(x, y) over the image, rows in parallel.
template <class PerPixel>
void forEachPixel(uint32_t width, uint32_t height, const PerPixel& perPixel) {
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, height), [&](const tbb::blocked_range<uint32_t>& rows) {
        for (uint32_t y = rows.begin(); y != rows.end(); ++y) {
            for (uint32_t x = 0; x < width; ++x) perPixel(x, y);
        }
    });
}

}  // namespace

void denoiseOnCpu(const DenoiseInput& in, std::vector<float>& rgba) {
    const DenoiseGuides& g = in.guides;
    const size_t pixels = size_t(g.width) * g.height;
    std::vector<DenoiseSample> a(pixels), b(pixels);
    std::vector<denoise::DenoiseSurface> surfaces(pixels);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        a[i] = denoise::demodulatedSample(in.beauty, in.varianceOfMean, g, i);
        surfaces[i] = denoise::surfaceAt(g, x, y);
    });
    if (in.samples < kMinSamplesForOwnVariance) {
        forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
            const uint32_t i = y * g.width + x;
            b[i] = {a[i].radiance,
                    denoise::spatialVarianceAt(a.data(), surfaces.data(), g.width, g.height, x, y)};
        });
        std::swap(a, b);
    }
    const std::vector<DenoiseSample> input = a;  // each pixel's own mean and noise
    for (uint32_t k = 0; k < kDenoiseIterations; ++k) {
        forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
            b[y * g.width + x] =
                denoise::atrousAt(a.data(), surfaces.data(), g.width, g.height, x, y, 1u << k);
        });
        std::swap(a, b);
    }
    rgba.resize(pixels * 4);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        const Vec3 c =
            denoise::remodulated(denoise::boundedByNoise(input[i], a[i].radiance, in.samples), g, i);
        rgba[4 * i + 0] = c.x;
        rgba[4 * i + 1] = c.y;
        rgba[4 * i + 2] = c.z;
        rgba[4 * i + 3] = 1.0f;
    });
}

}  // namespace pt
