#include "pt_render/batched_render.h"

#include <algorithm>
#include <stdexcept>

namespace pt::cli {

namespace {

// Adds passes in chunks of about a quarter of a second so that progress moves and a stop is
// answered; returns whether the batch was finished.
bool renderBatch(Backend& backend, uint32_t spp, uint32_t batch, uint32_t batches, const ProgressFn& progress,
                 const std::function<bool()>& stop) {
    uint32_t chunk = 1;
    while (backend.stats().samplesPerPixel < spp) {
        if (stop && stop()) return false;
        const BackendStats before = backend.stats();
        const uint32_t passes = std::min(chunk, spp - before.samplesPerPixel);
        backend.render(passes);
        const double seconds = std::max(backend.stats().renderSeconds - before.renderSeconds, 1e-6);
        chunk = uint32_t(std::clamp(0.25 / (seconds / passes), 1.0, 65536.0));
        reportProgress(progress, "render",
                       (batch + double(backend.stats().samplesPerPixel) / spp) / double(batches));
    }
    return true;
}

}  // namespace

BatchedImage renderBatches(Backend& backend, Scene& scene, uint32_t sppPerBatch, uint32_t batches,
                           const ProgressFn& progress, const std::function<bool()>& stop) {
    if (batches < 2 || sppPerBatch == 0)
        throw std::invalid_argument("renderBatches: needs 2 or more batches");
    const uint32_t firstSeed = scene.render.seed;
    std::vector<double> sum, sumSquares;
    std::vector<float> batchMean;
    BatchedImage result;
    uint32_t finished = 0;
    for (; finished < batches; ++finished) {
        scene.render.seed = firstSeed + finished;
        backend.sync(scene, SceneChanges::Settings);
        if (!renderBatch(backend, sppPerBatch, finished, batches, progress, stop)) {
            result.interrupted = true;
            break;
        }
        backend.readBeauty(batchMean);
        sum.resize(batchMean.size(), 0.0);
        sumSquares.resize(batchMean.size(), 0.0);
        for (size_t i = 0; i < batchMean.size(); ++i) {
            sum[i] += batchMean[i];
            sumSquares[i] += double(batchMean[i]) * batchMean[i];
        }
        const BackendStats stats = backend.stats();
        result.nonfiniteSamples += stats.nonfiniteSamples;
        result.renderSeconds += stats.renderSeconds;
    }
    scene.render.seed = firstSeed;
    result.spp = sppPerBatch * finished;
    result.batches = finished;
    if (finished < 2) return result;  // no image, or no spread to estimate its noise from
    result.mean.resize(sum.size());
    result.varianceOfMean.resize(sum.size());
    const double n = finished;
    for (size_t i = 0; i < sum.size(); ++i) {
        const double mean = sum[i] / n;
        // Sample variance of the batch means (n - 1 in the denominator), over n for the mean's.
        const double variance = std::max(sumSquares[i] / n - mean * mean, 0.0) * n / (n - 1.0);
        result.mean[i] = float(mean);
        result.varianceOfMean[i] = float(variance / n);
    }
    return result;
}

}  // namespace pt::cli
