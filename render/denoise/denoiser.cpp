#include "render/denoise/denoiser.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "render/denoise/firefly_limits.h"
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

// The planes a denoise works in, kept for the next call of the same size: at 512x512 they
// are 30 MB, which a call that allocated them anew spent about a sixth of its time faulting in.
// The planes' margins are written once, at allocation; every call overwrites the pixels.
struct CpuDenoiser::Workspace {
    denoise::PlaneLayout layout;
    // `input` keeps each pixel's own mean and noise for boundedByNoise; the passes alternate
    // between a and b (as GpuDenoiser::run).
    std::vector<DenoiseSample> input;
    std::vector<denoise::DenoiseSurface> surfaces;
    std::vector<denoise::SurfaceStops> stops;
    denoise::SurfacePlanes surfacePlanes;
    denoise::SamplePlanes a, b;
    // Below kMinSamplesForOwnVariance only: each pixel's firefly limit, the luminances its
    // neighbours' variance is estimated from, and that variance (made at the first call that
    // needs them).
    std::unique_ptr<denoise::LuminancePlanes> luminance;
    denoise::FireflyRowSums fireflyRowSums;
    std::vector<float> fireflyLimit, spread;

    explicit Workspace(const denoise::PlaneLayout& l)
        : layout(l),
          input(size_t(l.width) * l.height),
          surfaces(input.size()),
          stops(input.size()),
          surfacePlanes(l),
          a(l),
          b(l) {}
};

CpuDenoiser::CpuDenoiser() = default;
CpuDenoiser::~CpuDenoiser() = default;

void CpuDenoiser::run(const DenoiseInput& in, std::vector<float>& rgba) {
    const DenoiseGuides& g = in.guides;
    const size_t pixels = size_t(g.width) * g.height;
    if (!workspace_ || workspace_->layout.width != g.width || workspace_->layout.height != g.height) {
        workspace_.reset();  // the old planes go before the new ones come
        workspace_ = std::make_unique<Workspace>(denoise::PlaneLayout{g.width, g.height});
    }
    Workspace& w = *workspace_;
    const denoise::PlaneLayout& layout = w.layout;
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        const denoise::PixelGuides pixel = denoise::guidesAt(g, i);
        w.input[i] = denoise::demodulatedSample(denoise::loadRgb(in.beauty, i), in.varianceOfMean[4 * i],
                                                in.samples, pixel);
        w.surfaces[i] = denoise::surfaceOf(pixel, w.stops[i].normalPower);
    });
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        w.stops[i].depthSlope = denoise::depthSlopeAt(w.surfaces.data(), g.width, g.height, x, y);
        w.surfacePlanes.store(layout.at(x, y), w.surfaces[i], w.stops[i]);
    });
    if (in.samples < kMinSamplesForOwnVariance) {
        // Too few samples for each pixel's own variance to stand alone: fireflies are held to
        // their neighbours, which then estimate it with it.
        if (!w.luminance) {
            w.luminance = std::make_unique<denoise::LuminancePlanes>(layout);
            w.fireflyLimit.resize(pixels);
            w.spread.resize(pixels);
        }
        denoise::fireflyLimits(w.input.data(), w.surfaces.data(), g.width, g.height, w.fireflyRowSums,
                               w.fireflyLimit.data());
        forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
            const uint32_t i = y * g.width + x;
            w.input[i] = denoise::withoutFirefly(w.input[i], w.fireflyLimit[i]);
            w.luminance->store(layout.at(x, y), w.input[i]);
        });
        forEachRow(g.width, g.height, [&](uint32_t y, denoise::RowSums& sums) {
            float* spread = &w.spread[size_t(y) * g.width];
            denoise::spatialVarianceRow(*w.luminance, w.surfacePlanes, layout, y, sums, spread);
            DenoiseSample* row = &w.input[size_t(y) * g.width];
            for (uint32_t x = 0; x < g.width; ++x)
                row[x].variance = denoise::firstSamplesVariance(
                    row[x].variance, denoise::fewSamplesVariance(spread[x], in.samples), in.samples);
        });
    }
    const denoise::SampleOutput first(w.a);
    forEachPixel(g.width, g.height,
                 [&](uint32_t x, uint32_t y) { first.store(layout.at(x, y), w.input[y * g.width + x]); });
    const denoise::SamplePlanes* from = &w.a;
    for (uint32_t k = 0; k < kDenoiseIterations; ++k) {
        denoise::SamplePlanes* to = from == &w.a ? &w.b : &w.a;
        forEachRow(g.width, g.height, [&](uint32_t y, denoise::RowSums& sums) {
            denoise::atrousRow(*from, w.surfacePlanes, layout, y, 1u << k, sums, *to);
        });
        from = to;
    }
    rgba.resize(pixels * 4);
    forEachPixel(g.width, g.height, [&](uint32_t x, uint32_t y) {
        const uint32_t i = y * g.width + x;
        const Vec3 filtered = denoise::filteredRadiance(w.input[i], from->packed(layout.at(x, y)));
        const Vec3 c = denoise::remodulated(denoise::boundedByNoise(w.input[i], filtered, in.samples),
                                            denoise::loadRgb(g.albedo, i), denoise::loadRgb(g.emission, i));
        rgba[4 * i + 0] = c.x;
        rgba[4 * i + 1] = c.y;
        rgba[4 * i + 2] = c.z;
        rgba[4 * i + 3] = 1.0f;
    });
}

void denoiseOnCpu(const DenoiseInput& in, std::vector<float>& rgba) { CpuDenoiser().run(in, rgba); }

}  // namespace pt
