#pragma once
// Rendering one image as several independent renders, so that the image carries an estimate of
// its own noise: `reference` stores it in the EXR, `stress` derives its bounds from it.
// Samples are a function of (pixel, sample index, seed) and scrambled Sobol points of one seed
// are not independent across sample ranges, so each batch is a fresh accumulation with its
// own seed (independent randomisations, as randomised quasi-Monte Carlo requires).
#include <cstdint>
#include <functional>
#include <vector>

#include "render/backend/backend.h"
#include "render/scene/scene.h"
#include "render/util/progress.h"

namespace pt::cli {

struct BatchedImage {
    std::vector<float> mean;            // RGBA, the mean of all batches
    std::vector<float> varianceOfMean;  // RGBA, per value: sample variance of the batch means / batches
    uint32_t spp = 0;                   // over all batches
    uint32_t batches = 0;
    uint64_t nonfiniteSamples = 0;  // dropped by the backend, over all batches
    double renderSeconds = 0.0;
    bool interrupted = false;  // stopped early: only the batches finished before count
};

// Renders `batches` (>= 2) batches of `sppPerBatch` samples with seeds scene.render.seed,
// +1, ...; `backend` must have been synced with `scene` (the batches only reset it). Reports
// the fraction done as stage "render". Where `stop` (polled about every quarter second) says
// so, the batch under way is dropped and the image is made of those finished (`batches` says
// how many; with fewer than 2 there is no noise estimate, and the caller should not use it).
BatchedImage renderBatches(Backend& backend, Scene& scene, uint32_t sppPerBatch, uint32_t batches,
                           const ProgressFn& progress = {}, const std::function<bool()>& stop = {});

}  // namespace pt::cli
