#include "render/denoise/denoiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

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
    // `input` keeps each pixel's own mean and noise for boundedByNoise; the passes alternate
    // between a and b (as GpuDenoiser::run).
    const bool ownVariance = in.samples >= kMinSamplesForOwnVariance;
    // `demodulated`: the input before its neighbours estimate the variance, at few samples only.
    std::vector<DenoiseSample> input(pixels), demodulated(ownVariance ? 0 : pixels);
    std::vector<denoise::PackedSample> a(pixels), b(pixels);
    std::vector<denoise::DenoiseSurface> surfaces(pixels);
    std::vector<denoise::SurfaceStops> stops(pixels);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        const denoise::PixelGuides pixel = denoise::guidesAt(g, i);
        (ownVariance ? input : demodulated)[i] = denoise::demodulatedSample(
            denoise::loadRgb(in.beauty, i), in.varianceOfMean[4 * i], in.samples, pixel);
        surfaces[i] = denoise::surfaceOf(pixel, stops[i].normalPower);
    });
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        stops[i].depthSlope = denoise::depthSlopeAt(surfaces.data(), g.width, g.height, x, y);
        if (!ownVariance) {
            input[i] = {demodulated[i].radiance,
                        denoise::spatialVarianceAt(demodulated.data(), surfaces.data(), stops.data(), g.width,
                                                   g.height, x, y)};
        }
        a[i] = denoise::packSample(input[i]);
    });
    const std::vector<denoise::PackedSample>* from = &a;
    for (uint32_t k = 0; k < kDenoiseIterations; ++k) {
        std::vector<denoise::PackedSample>* to = from == &a ? &b : &a;
        forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
            (*to)[y * g.width + x] = denoise::atrousAt(from->data(), surfaces.data(), stops.data(), g.width,
                                                       g.height, x, y, 1u << k);
        });
        from = to;
    }
    rgba.resize(pixels * 4);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        const Vec3 filtered = denoise::filteredRadiance(input[i], (*from)[i]);
        const Vec3 c = denoise::remodulated(denoise::boundedByNoise(input[i], filtered, in.samples),
                                            denoise::loadRgb(g.albedo, i), denoise::loadRgb(g.emission, i));
        rgba[4 * i + 0] = c.x;
        rgba[4 * i + 1] = c.y;
        rgba[4 * i + 2] = c.z;
        rgba[4 * i + 3] = 1.0f;
    });
}

}  // namespace pt
