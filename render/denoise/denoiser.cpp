#include "render/denoise/denoiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/denoise/row_filter.h"

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

// Runs perRow(y, sums) over the image's rows in parallel, with working memory for a row.
template <class PerRow>
void forEachRow(uint32_t width, uint32_t height, const PerRow& perRow) {
    tbb::parallel_for(tbb::blocked_range<uint32_t>(0, height), [&](const tbb::blocked_range<uint32_t>& rows) {
        denoise::RowSums sums(width);
        for (uint32_t y = rows.begin(); y != rows.end(); ++y) perRow(y, sums);
    });
}

}  // namespace

void denoiseOnCpu(const DenoiseInput& in, std::vector<float>& rgba) {
    const DenoiseGuides& g = in.guides;
    const size_t pixels = size_t(g.width) * g.height;
    const denoise::PlaneLayout layout{g.width, g.height};
    // `input` keeps each pixel's own mean and noise for boundedByNoise; the passes alternate
    // between a and b (as GpuDenoiser::run).
    const bool ownVariance = in.samples >= kMinSamplesForOwnVariance;
    std::vector<DenoiseSample> input(pixels);
    std::vector<denoise::DenoiseSurface> surfaces(pixels);
    std::vector<denoise::SurfaceStops> stops(pixels);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        const denoise::PixelGuides pixel = denoise::guidesAt(g, i);
        input[i] = denoise::demodulatedSample(denoise::loadRgb(in.beauty, i), in.varianceOfMean[4 * i],
                                              in.samples, pixel);
        surfaces[i] = denoise::surfaceOf(pixel, stops[i].normalPower);
    });
    denoise::SurfacePlanes surfacePlanes(layout);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        stops[i].depthSlope = denoise::depthSlopeAt(surfaces.data(), g.width, g.height, x, y);
        surfacePlanes.store(layout.at(x, y), surfaces[i], stops[i]);
    });
    if (!ownVariance) {
        // Too few samples for each pixel's own variance: its neighbours estimate it.
        denoise::LuminancePlanes luminance(layout);
        forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
            luminance.store(layout.at(x, y), input[y * g.width + x]);
        });
        std::vector<float> variance(pixels);
        forEachRow(g.width, g.height, [&](uint32_t y, denoise::RowSums& sums) {
            denoise::spatialVarianceRow(luminance, surfacePlanes, layout, y, sums,
                                        &variance[size_t(y) * g.width]);
        });
        for (size_t i = 0; i < pixels; ++i) input[i].variance = variance[i];
    }
    denoise::SamplePlanes a(layout), b(layout);
    const denoise::SampleOutput first(a);
    forEachPixel(g.width, g.height,
                 [&](uint32_t x, uint32_t y) { first.store(layout.at(x, y), input[y * g.width + x]); });
    const denoise::SamplePlanes* from = &a;
    for (uint32_t k = 0; k < kDenoiseIterations; ++k) {
        denoise::SamplePlanes* to = from == &a ? &b : &a;
        forEachRow(g.width, g.height, [&](uint32_t y, denoise::RowSums& sums) {
            denoise::atrousRow(*from, surfacePlanes, layout, y, 1u << k, sums, *to);
        });
        from = to;
    }
    rgba.resize(pixels * 4);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        const Vec3 filtered = denoise::filteredRadiance(input[i], from->packed(layout.at(x, y)));
        const Vec3 c = denoise::remodulated(denoise::boundedByNoise(input[i], filtered, in.samples),
                                            denoise::loadRgb(g.albedo, i), denoise::loadRgb(g.emission, i));
        rgba[4 * i + 0] = c.x;
        rgba[4 * i + 1] = c.y;
        rgba[4 * i + 2] = c.z;
        rgba[4 * i + 3] = 1.0f;
    });
}

}  // namespace pt
